// The splash's plough (physics/sand_splash.hpp): the head shares its momentum with the sand it
// sweeps up, a closed form checked here by momentum and against a hand calculation.
#include <catch2/catch.hpp>

#include "physics/sand_splash.hpp"

using namespace sweetspot;

TEST_CASE("a club ploughing sand keeps its momentum shared with the sand it sweeps", "[sand]") {
  const double m = 0.296, v0 = 20.0, width = 0.076;  // the sand wedge of clubs.toml, a 45 mph splash
  SECTION("the ball first: no sand, no loss") { CHECK(club_speed_after_sand(v0, m, width, 0.0) == v0); }
  SECTION("the taught inch: by hand, 1600 kg/m3 x 76 mm x 12.7 mm x 25.4 mm = 39.2 g of sand") {
    const double v = club_speed_after_sand(v0, m, width, kSplashEntry);
    CHECK(v == Approx(v0 * 0.296 / (0.296 + 0.0392)).epsilon(1e-3));
    // Momentum: what the head lost, the sand carries away at the head's speed.
    const double sand = kBunkerSandDensity * width * kSplashDepth * kSplashEntry;
    CHECK(m * (v0 - v) == Approx(sand * v).epsilon(1e-12));
    // Energy: the sand's plastic share is spent, never made.
    CHECK(0.5 * m * v * v + 0.5 * sand * v * v < 0.5 * m * v0 * v0);
  }
  SECTION("the more sand, the slower, and never backward") {
    double last = v0;
    for (double x = 0.005; x <= kSandEntry.max + 1e-12; x += 0.005) {
      const double v = club_speed_after_sand(v0, m, width, x);
      CHECK(v < last);
      CHECK(v > 0.0);
      last = v;
    }
  }
  SECTION("a heavier head loses less") {
    CHECK(club_speed_after_sand(v0, 0.35, width, 0.05) > club_speed_after_sand(v0, 0.25, width, 0.05));
  }
}
