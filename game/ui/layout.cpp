#include "game/ui/layout.hpp"

#include <algorithm>

namespace sweetspot {

PanelLayout lay_out_panels(float width, float height, bool hidden) {
  PanelLayout l;
  width = std::max(width, 1.0f);
  height = std::max(height, 1.0f);
  if (hidden) {
    l.kind = LayoutKind::Hidden;
    l.view = {0, 0, width, height};
    return l;
  }
  const float column_h = std::max(1.0f, height - 2 * kMargin);
  if (width >= kWideMin) {
    l.kind = LayoutKind::Wide;
    l.left = {kMargin, kMargin, kLeftColumn, column_h};
    l.right = {width - kMargin - kRightColumn, kMargin, kRightColumn, column_h};
    const float x0 = l.left.x + l.left.w + kMargin, x1 = l.right.x - kMargin;
    l.view = {x0, 0, x1 - x0, height};
    return l;
  }
  l.kind = LayoutKind::Sidebar;
  // The sidebar gives way on very narrow windows so the view keeps kMinView px.
  const float bar = std::max(1.0f, std::min(kSidebar, width - kMinView - 2 * kMargin));
  l.right = {width - kMargin - bar, kMargin, bar, column_h};
  l.view = {0, 0, std::max(1.0f, l.right.x - kMargin), height};
  return l;
}

}  // namespace sweetspot
