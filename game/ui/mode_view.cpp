#include "game/ui/mode_view.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "game/render/renderer.hpp"

namespace sweetspot {

void fit_renderer(Renderer& renderer, int w, int h, double scale) {
  const double s = std::clamp(scale, 0.25, 1.0);
  const int rw = std::max(16, static_cast<int>(std::lround(w * s)));
  const int rh = std::max(16, static_cast<int>(std::lround(h * s)));
  if (rw != renderer.width() || rh != renderer.height()) renderer.resize(rw, rh);
}

void draw_banner(const char* text, int width, float y) { draw_banner(text, 0.5f * static_cast<float>(width), y, 1.0f); }

float banner_text_width(std::string_view text, float scale) {
  const float size = ImGui::GetFontSize() * scale;
  return ImGui::GetFont()->CalcTextSizeA(size, 1e9f, 0.0f, text.data(), text.data() + text.size()).x;
}

float draw_banner(const char* text, float centre_x, float y, float scale) {
  // Under every window: the pause menu covers it, as it covers the picture.
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  ImFont* font = ImGui::GetFont();
  const float size = ImGui::GetFontSize() * scale;
  const float text_w = banner_text_width(text, scale);
  const ImVec2 pos(centre_x - 0.5f * text_w, y);
  const float bottom = pos.y + kBannerHeight * scale;
  dl->AddRectFilled(ImVec2(pos.x - 10 * scale, pos.y - 6 * scale), ImVec2(pos.x + text_w + 10 * scale, bottom),
                    IM_COL32(0, 0, 0, 170), 4.0f * scale);
  dl->AddText(font, size, pos, IM_COL32(255, 230, 120, 255), text);
  return bottom;
}

}  // namespace sweetspot
