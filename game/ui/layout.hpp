// Where the lab window's panels and its 3D view go, for any window size: the
// view is never under a panel, so the shot is always visible. Pure arithmetic, no ImGui,
// so it is unit-tested.
//   wide (>= kWideMin px): a left column (Shot, Tuning) and a right column (Launch monitor,
//     Trajectory, Replay), the view between them;
//   narrow: one sidebar on the right with every panel as a collapsible section, the view
//     to its left;
//   hidden (the H key): no panels, a one-line HUD over the view, the view the whole window.
#pragma once

namespace sweetspot {

/// A rectangle in window pixels, origin top-left, y down.
struct Rect {
  float x = 0, y = 0, w = 0, h = 0;
  bool contains(float px, float py) const { return px >= x && px < x + w && py >= y && py < y + h; }
  bool overlaps(const Rect& o) const { return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h; }
};

enum class LayoutKind { Wide, Sidebar, Hidden };

struct PanelLayout {
  LayoutKind kind = LayoutKind::Wide;
  Rect left;   ///< Wide: Shot and Tuning; empty otherwise
  Rect right;  ///< Wide: Launch monitor, Trajectory, Replay; Sidebar: every panel; empty when hidden
  Rect view;   ///< the 3D view: the window minus the panels, at least kMinView px each way
};

/// Windows at least this wide get two columns (px): 340 + 400 px of panels leave a view of
/// about 540 px at 1280.
inline constexpr float kWideMin = 1100.0f;
inline constexpr float kLeftColumn = 340.0f;   ///< px: the sliders' label and value columns fit
inline constexpr float kRightColumn = 400.0f;  ///< px: the launch-monitor table's four columns fit
inline constexpr float kSidebar = 380.0f;      ///< px
inline constexpr float kMargin = 6.0f;         ///< px between panels and the window edge
inline constexpr float kMinView = 160.0f;      ///< px: below this the sidebar would eat the view; it narrows

PanelLayout lay_out_panels(float width, float height, bool hidden);

}  // namespace sweetspot
