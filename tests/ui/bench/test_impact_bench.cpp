// The impact micro-benchmark measures real, valid impacts.
#include <catch2/catch.hpp>

#include <algorithm>

#include "game/bench/impact_bench.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

TEST_CASE("the benchmark's impacts are valid and varied", "[bench][impact]") {
  const auto impacts = realistic_impacts(test::assets().equipment());
  REQUIRE(impacts.size() > 300);
  double lo = 1e300, hi = 0.0;
  for (const auto& in : impacts) {
    REQUIRE(validate_impact(in).empty());
    const auto r = solve_impact(in);
    CHECK_FALSE(r.energy_limited);
    const double spin = r.ball_after.angular_velocity.norm();
    lo = std::min(lo, spin);
    hi = std::max(hi, spin);
  }
  // The set spans the bag (a driver's ~2500 rpm to a wedge's ~10000) and both sports, so
  // the timing in `bench` is of varied solves, not one repeated case.
  CHECK(hi > 3.0 * lo);
}
