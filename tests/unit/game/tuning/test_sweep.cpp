// Sweeps of e x mu: ordering, thread independence, limits.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "game/content/scenario.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"
#include "game/tuning/sweep.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

TEST_CASE("sweep output is ordered and independent of the thread count", "[sweep]") {
  const Assets& A = test::assets();
  const Scenario s = load_scenario(A, "golf/7-iron", {"world.name=none"});
  SweepOptions o;
  o.e = parse_grid_axis("0.7:0.9:3", "--e", ImpactMaterial::kE);
  o.mu = parse_grid_axis("0.1:0.5:4", "--mu", ImpactMaterial::kMu);
  o.threads = 1;
  const auto one = run_sweep(s, o);
  o.threads = 3;
  const auto three = run_sweep(s, o);
  REQUIRE(one.size() == 12);
  CHECK(sweep_csv(one) == sweep_csv(three));
  CHECK(one[0].e == 0.7);
  CHECK(one[0].mu == 0.1);
  CHECK(one[3].mu == Approx(0.5).epsilon(1e-15));
  CHECK(one[4].e == Approx(0.8).epsilon(1e-15));
  CHECK(one[11].e == Approx(0.9).epsilon(1e-15));
  // Ball speed rises with e at fixed µ.
  CHECK(one[8].shot.launch.ball_speed > one[0].shot.launch.ball_speed);
  CHECK_THROWS_WITH(parse_grid_axis("0.5:1.5:3", "--e", ImpactMaterial::kE), Contains("--e 0.5:1.5:3") && Contains("<= 1"));
  CHECK_THROWS_WITH(parse_grid_axis("0:1:0", "--e", ImpactMaterial::kE), Contains("N = 0"));
  CHECK_THROWS_WITH(parse_grid_axis("0:1", "--e", ImpactMaterial::kE), Contains("A:B:N"));
  CHECK_THROWS_WITH(parse_grid_axis("0:nan:3", "--mu", ImpactMaterial::kMu), Contains("NaN"));
  o.e = parse_grid_axis("0:1:1000", "--e", ImpactMaterial::kE);
  o.mu = parse_grid_axis("0:1:101", "--mu", ImpactMaterial::kMu);
  CHECK_THROWS_WITH(run_sweep(s, o), Contains("101000") && Contains("100000"));
}

TEST_CASE("sweep threads share one golf_hole world and still agree bit for bit", "[sweep][world]") {
  const Assets& A = test::assets();
  // The world is built once per process and queried by every worker at once (its default
  // sweep method only reads). Full flights to rest on the course, 1 thread against 4.
  const Scenario s = load_scenario(A, "golf/driver", {});
  SweepOptions o;
  o.e = parse_grid_axis("0.70:0.86:5", "--e", ImpactMaterial::kE);
  o.mu = parse_grid_axis("0.2:0.6:5", "--mu", ImpactMaterial::kMu);
  o.threads = 1;
  const auto one = run_sweep(s, o);
  o.threads = 4;
  const auto four = run_sweep(s, o);
  REQUIRE(one.size() == 25);
  CHECK(sweep_csv(one) == sweep_csv(four));
  for (const auto& p : one) CHECK(p.shot.end == ShotEnd::Rest);
}
