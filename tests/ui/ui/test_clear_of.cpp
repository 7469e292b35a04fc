// Marks drawn over the 3D image keep clear of its labels (game/ui/clear_of.hpp): a flagstick
// through a shot's carry label leaves a gap there, and nowhere else.
#include <catch2/catch.hpp>

#include "game/ui/clear_of.hpp"

using namespace sweetspot;

TEST_CASE("a pole crossing a label leaves a gap exactly over the label", "[ui][unit]") {
  // A vertical pole from y 400 (its foot) up to y 300, and a label box over y 340..360.
  const Eigen::Vector2f foot(100.0f, 400.0f), top(100.0f, 300.0f);
  const std::vector<Eigen::Vector4f> label{{80.0f, 340.0f, 160.0f, 360.0f}};
  const auto parts = parts_clear_of(foot, top, label);
  REQUIRE(parts.size() == 2);
  CHECK(parts[0].first == 0.0f);
  CHECK(parts[0].second == Approx(0.4f));  // up to y 360
  CHECK(parts[1].first == Approx(0.6f));   // from y 340
  CHECK(parts[1].second == 1.0f);
  // Beside the label, or with no labels, the pole is whole.
  CHECK(parts_clear_of({200.0f, 400.0f}, {200.0f, 300.0f}, label) == std::vector<std::pair<float, float>>{{0.0f, 1.0f}});
  CHECK(parts_clear_of(foot, top, {}) == std::vector<std::pair<float, float>>{{0.0f, 1.0f}});
  // A label over the whole pole hides it; two overlapping labels make one gap.
  CHECK(parts_clear_of(foot, top, {{0.0f, 0.0f, 500.0f, 500.0f}}).empty());
  const auto two = parts_clear_of(foot, top, {{80.0f, 340.0f, 160.0f, 360.0f}, {90.0f, 350.0f, 110.0f, 380.0f}});
  REQUIRE(two.size() == 2);
  CHECK(two[0].second == Approx(0.2f));
  CHECK(two[1].first == Approx(0.6f));
  // A slanted line through a box's corner region is cut where it enters and leaves.
  const auto slant = parts_clear_of({0.0f, 0.0f}, {100.0f, 100.0f}, {{40.0f, 20.0f, 60.0f, 80.0f}});
  REQUIRE(slant.size() == 2);
  CHECK(slant[0].second == Approx(0.4f));
  CHECK(slant[1].first == Approx(0.6f));
}

TEST_CASE("a flag's cloth and a label overlap only where their rectangles do", "[ui][unit]") {
  const std::vector<Eigen::Vector4f> label{{80.0f, 340.0f, 160.0f, 360.0f}};
  CHECK(overlaps_any({150.0f, 350.0f}, {170.0f, 370.0f}, label));
  CHECK_FALSE(overlaps_any({160.0f, 350.0f}, {170.0f, 370.0f}, label));  // touching edges do not cover
  CHECK_FALSE(overlaps_any({0.0f, 0.0f}, {10.0f, 10.0f}, {}));
}
