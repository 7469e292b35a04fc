#include "game/ui/trajectory_plot.hpp"

#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "game/render/camera.hpp"

namespace sweetspot {

PlotMap fit_plot(const ShotTrajectory& shot, PlotView view, double px0, double py0, double width,
                 double height) {
  // Start from the launch point and a minimum extent so a short or empty shot still maps.
  double xmin = 0.0, xmax = 10.0, ymin = view == PlotView::Side ? 0.0 : -5.0, ymax = 5.0;
  for (const auto& s : shot.samples) {
    xmin = std::min(xmin, s.position.x());
    xmax = std::max(xmax, s.position.x());
    ymin = std::min(ymin, plot_y(s.position, view));
    ymax = std::max(ymax, plot_y(s.position, view));
  }
  const double margin = 6.0;  // px
  const double w = std::max(1.0, width - 2 * margin), h = std::max(1.0, height - 2 * margin);
  PlotMap m;
  m.scale = std::min(w / (xmax - xmin), h / (ymax - ymin));
  m.x0 = xmin;
  // Centre the data vertically in the box.
  const double used_h = (ymax - ymin) * m.scale;
  m.y0 = ymin;
  m.px0 = px0 + margin;
  m.py0 = py0 - margin - 0.5 * (h - used_h);
  return m;
}

namespace {

ImU32 phase_colour(Phase p) {
  switch (p) {
    case Phase::Flight: return IM_COL32(255, 220, 60, 255);
    case Phase::Bounce: return IM_COL32(255, 120, 40, 255);
    case Phase::Roll: return IM_COL32(90, 200, 255, 255);
    case Phase::Rest: return IM_COL32(230, 230, 230, 255);
  }
  return IM_COL32_WHITE;
}

void draw_one(const ShotTrajectory& shot, PlotView view, double t, const char* label, float height) {
  const ImVec2 size(ImGui::GetContentRegionAvail().x, height);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(20, 28, 36, 255));
  const PlotMap m = fit_plot(shot, view, origin.x, origin.y + size.y, size.x, size.y);
  // Reference line: the ground (side) or the target line (top).
  const float ly = static_cast<float>(m.to_px_y(0.0));
  dl->AddLine(ImVec2(origin.x, ly), ImVec2(origin.x + size.x, ly), IM_COL32(90, 110, 90, 255));
  for (std::size_t i = 1; i < shot.samples.size(); ++i) {
    const auto& a = shot.samples[i - 1];
    const auto& b = shot.samples[i];
    dl->AddLine(ImVec2(static_cast<float>(m.to_px_x(a.position.x())), static_cast<float>(m.to_px_y(plot_y(a.position, view)))),
                ImVec2(static_cast<float>(m.to_px_x(b.position.x())), static_cast<float>(m.to_px_y(plot_y(b.position, view)))),
                phase_colour(b.phase), 2.0f);
  }
  if (!shot.samples.empty()) {
    const TrajectorySample s = sample_at(shot, t);
    dl->AddCircleFilled(ImVec2(static_cast<float>(m.to_px_x(s.position.x())),
                               static_cast<float>(m.to_px_y(plot_y(s.position, view)))),
                        4.0f, IM_COL32_WHITE);
  }
  dl->AddText(ImVec2(origin.x + 4, origin.y + 2), IM_COL32(200, 200, 200, 255), label);
  ImGui::Dummy(size);
}

}  // namespace

void draw_trajectory_plots(const ShotTrajectory& shot, double t) {
  // Both plots in what is left of the column (a 1280x800 window's launch monitor leaves less
  // than two full ones), each between a readable 40 px and 110.
  const float each = std::clamp(0.5f * (ImGui::GetContentRegionAvail().y - ImGui::GetStyle().ItemSpacing.y), 40.0f, 110.0f);
  draw_one(shot, PlotView::Side, t, "side", each);
  draw_one(shot, PlotView::Top, t, "top", each);
}

}  // namespace sweetspot
