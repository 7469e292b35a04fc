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

float draw_banner(const char* text, float centre_x, float y, float scale, const char* second) {
  // Under every window: the pause menu covers it, as it covers the picture.
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  ImFont* font = ImGui::GetFont();
  const float size = ImGui::GetFontSize() * scale;
  const bool two = second != nullptr && second[0] != '\0';
  const float first_w = banner_text_width(text, scale), second_w = two ? banner_text_width(second, scale) : 0.0f;
  const float text_w = std::max(first_w, second_w);
  const float line = kBannerHeight * scale;
  const float bottom = y + (two ? 2.0f : 1.0f) * line;
  dl->AddRectFilled(ImVec2(centre_x - 0.5f * text_w - 10 * scale, y - 6 * scale), ImVec2(centre_x + 0.5f * text_w + 10 * scale, bottom),
                    IM_COL32(0, 0, 0, 170), 4.0f * scale);
  dl->AddText(font, size, ImVec2(centre_x - 0.5f * first_w, y), IM_COL32(255, 230, 120, 255), text);
  if (two) dl->AddText(font, size, ImVec2(centre_x - 0.5f * second_w, y + line), IM_COL32(255, 230, 120, 255), second);
  return bottom;
}

}  // namespace sweetspot
