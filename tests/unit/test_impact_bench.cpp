// The impact micro-benchmark measures real, valid impacts.
#include <catch2/catch.hpp>

#include "game/bench/impact_bench.hpp"

using namespace sweetspot;

TEST_CASE("the benchmark's impacts are valid and varied", "[bench][impact]") {
  const auto impacts = realistic_impacts();
  REQUIRE(impacts.size() > 300);
  int grips = 0, slips = 0;
  for (const auto& in : impacts) {
    REQUIRE(validate_impact(in).empty());
    const auto r = solve_impact(in);
    CHECK_FALSE(r.energy_limited);
    (r.contact == ContactKind::Grip ? grips : slips)++;
  }
  CHECK(grips > 0);
  CHECK(slips >= 0);
  CHECK(measure_impact_solves_per_s(0.01) > 1e4);
}
