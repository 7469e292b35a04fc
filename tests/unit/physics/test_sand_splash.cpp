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

TEST_CASE("the sand takes the strike only once its cushion is thicker than the ball flattens", "[sand]") {
  const double radius = 0.021335, mass = 0.04593, k = 2.36e7;  // the tour ball of balls.toml
  // By hand: 12.7 mm x 25.4 mm of channel banked up 12.7 + 21.3 mm of face: 9.5 mm of sand.
  CHECK(sand_cushion(kSplashEntry, radius) == Approx(0.0127 * 0.0254 / (0.0127 + radius)).epsilon(1e-12));
  CHECK(sand_cushion(0.0, radius) == 0.0);
  // A splash's 8 m/s of normal approach flattens the ball ~1.9 mm, a drive's 45 m/s ~7.5 mm.
  CHECK(hertz_flattening(mass, k, 8.0) == Approx(1.89e-3).epsilon(0.01));
  CHECK(hertz_flattening(mass, k, 45.0) == Approx(7.52e-3).epsilon(0.01));
  const double flat = hertz_flattening(mass, k, 8.0);
  CHECK(cushion_share(sand_cushion(0.0, radius), flat) == 0.0);
  CHECK(cushion_share(sand_cushion(kSplashEntry, radius), flat) == 1.0);
  // In between the share grows with the sand and nothing jumps.
  double last = 0.0;
  for (double x = 2.5e-4; x <= 0.006; x += 2.5e-4) {
    const double s = cushion_share(sand_cushion(x, radius), flat);
    CHECK((s > last || s == 1.0));
    CHECK(s - last < 0.07);
    last = s;
  }
  CHECK(last == 1.0);
}

TEST_CASE("a restitution mixed with the sand's keeps both curves' points and each at its ends", "[sand]") {
  CorCurve face;
  face.count = 3;
  face.speed = {10.0, 40.0, 60.0};
  face.cor = {0.85, 0.80, 0.76};
  const CorCurve sand = CorCurve::constant(0.1);
  const CorCurve half = mix_restitution(face, sand, 0.5);
  for (double v : {0.0, 10.0, 25.0, 40.0, 55.0, 80.0}) {
    INFO(v << " m/s");
    CHECK(mix_restitution(face, sand, 0.0).at(v) == face.at(v));
    CHECK(mix_restitution(face, sand, 1.0).at(v) == sand.at(v));
    CHECK(half.at(v) == Approx(0.5 * face.at(v) + 0.5 * sand.at(v)).epsilon(1e-12));
  }
}
