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

void draw_banner(const char* text, int width, float y) {
  // Under every window: the pause menu covers it, as it covers the picture.
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float text_w = ImGui::CalcTextSize(text).x;
  const ImVec2 pos(0.5f * (static_cast<float>(width) - text_w), y);
  dl->AddRectFilled(ImVec2(pos.x - 10, pos.y - 6), ImVec2(pos.x + text_w + 10, pos.y + kBannerHeight), IM_COL32(0, 0, 0, 170), 4.0f);
  dl->AddText(pos, IM_COL32(255, 230, 120, 255), text);
}

}  // namespace sweetspot
