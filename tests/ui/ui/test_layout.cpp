// The lab window's layout (game/ui/layout.hpp): at any window size the 3D view is
// a real share of the window and no panel lies on it.
#include <catch2/catch.hpp>

#include "game/ui/layout.hpp"

using namespace sweetspot;

namespace {

bool inside_window(const Rect& r, float w, float h) { return r.x >= 0 && r.y >= 0 && r.x + r.w <= w + 1e-3f && r.y + r.h <= h + 1e-3f; }

}  // namespace

TEST_CASE("the 3D view is never under a panel, at any window size", "[ui][unit]") {
  for (const auto& [w, h] : {std::pair{1280.0f, 800.0f}, {1920.0f, 1080.0f}, {1100.0f, 700.0f}, {1099.0f, 700.0f},
                             {800.0f, 600.0f}, {640.0f, 480.0f}, {400.0f, 300.0f}}) {
    INFO(w << "x" << h);
    for (bool hidden : {false, true}) {
      const PanelLayout l = lay_out_panels(w, h, hidden);
      CHECK(inside_window(l.view, w, h));
      CHECK(l.view.w >= std::min(kMinView, w));
      CHECK(l.view.h == h);
      if (hidden) {
        CHECK(l.kind == LayoutKind::Hidden);
        CHECK(l.view.w == w);  // H gives the whole window to the shot
        continue;
      }
      CHECK(inside_window(l.right, w, h));
      CHECK_FALSE(l.view.overlaps(l.right));
      if (l.kind == LayoutKind::Wide) {
        CHECK(inside_window(l.left, w, h));
        CHECK_FALSE(l.view.overlaps(l.left));
        CHECK_FALSE(l.left.overlaps(l.right));
      }
    }
  }
  // 1280x800 (the design size): two columns, a view of at least 500 px between them.
  const PanelLayout wide = lay_out_panels(1280, 800, false);
  CHECK(wide.kind == LayoutKind::Wide);
  CHECK(wide.view.w >= 500);
  CHECK(wide.left.w == kLeftColumn);
  CHECK(wide.right.w == kRightColumn);
  // 800x600: one sidebar on the right and half the window for the shot, not the 3D view
  // lost under cut-off panels.
  const PanelLayout narrow = lay_out_panels(800, 600, false);
  CHECK(narrow.kind == LayoutKind::Sidebar);
  CHECK(narrow.view.x == 0);
  CHECK(narrow.view.w >= 400);
  CHECK(narrow.right.x > narrow.view.x + narrow.view.w);
  // Tiny windows: the sidebar narrows so the view keeps kMinView.
  const PanelLayout tiny = lay_out_panels(400, 300, false);
  CHECK(tiny.view.w >= kMinView);
  CHECK(tiny.right.w < kSidebar);
}
