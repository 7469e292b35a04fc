// The shot benchmark measures real work and its accuracy figures mean what they say.
#include <catch2/catch.hpp>

#include <cstddef>

#include "game/bench/shot_bench.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot::bench;

TEST_CASE("shot bench: ours converges to the reference, the 240 Hz baseline does not", "[bench][shots]") {
  const CarryErrors e = golf_carry_errors(sweetspot::test::assets());
  REQUIRE(e.shots.size() == 3);
  const double tour_carry_yd[] = {275.0, 172.0, 136.0};  // TrackMan PGA driver, 7-iron, PW
  for (std::size_t i = 0; i < e.shots.size(); ++i) {
    const CarryError& c = e.shots[i];
    INFO(c.name);
    CHECK(c.reference_m / 0.9144 == Approx(tour_carry_yd[i]).epsilon(0.1));
    CHECK(c.ours_error_m < 0.004);  // the default tolerances' contract (physics/flight.hpp)
    CHECK(c.baseline_error_m > c.ours_error_m);
    CHECK(c.baseline_error_m < 5.0);  // same aero model: the baseline is close, just not converged
    CHECK(c.ours_error_m <= e.ours_error_m);
    CHECK(c.baseline_error_m <= e.baseline_error_m);
  }
}

TEST_CASE("shot bench: the timed shots are the tour set and end where tour shots end", "[bench][shots]") {
  // What is timed must be the real work: the mean total of the driver/7-iron/PW rotation
  // is what full shots give (a broken loop that skipped the roll would not reach it).
  const ShotBenchResult g = bench_golf_shots(sweetspot::test::assets(), 0.01);
  CHECK(g.shots >= 16);
  CHECK(g.mean_total_m > 150.0);
  const ShotBenchResult b = bench_baseline_golf_shots(sweetspot::test::assets(), 0.01);
  CHECK(b.shots >= 16);
  CHECK(b.mean_total_m > 120.0);
}
