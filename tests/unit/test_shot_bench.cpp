// The shot benchmark measures real work and its accuracy figures mean what they say.
#include <catch2/catch.hpp>

#include "game/bench/shot_bench.hpp"

using namespace sweetspot::bench;

TEST_CASE("shot bench: ours converges to the reference, the 240 Hz baseline does not", "[bench][shots]") {
  const CarryErrors e = golf_carry_errors();
  CHECK(e.reference_m > 240.0);
  CHECK(e.ours_error_m < 1e-4);
  CHECK(e.baseline_error_m > e.ours_error_m);
  CHECK(e.baseline_error_m < 5.0);  // same aero model: the baseline is close, just not converged
}

TEST_CASE("shot bench: timings are positive and shots end somewhere sensible", "[bench][shots]") {
  const ShotBenchResult g = bench_golf_shots(0.01);
  CHECK(g.shots >= 16);
  CHECK(g.us_per_shot > 0.0);
  CHECK(g.mean_total_m > 240.0);
  const ShotBenchResult b = bench_baseline_golf_shots(0.01);
  CHECK(b.shots >= 16);
  CHECK(b.mean_total_m > 200.0);
}
