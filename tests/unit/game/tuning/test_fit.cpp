// fit: e and mu from measured launch numbers.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "game/content/scenario.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"
#include "game/tuning/fit.hpp"
#include "game/rules/run_shot.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

TEST_CASE("fit recovers e and mu that produced a launch", "[fit]") {
  const Assets& A = test::assets();
  Scenario s = load_scenario(A, "golf/7-iron", {"world.name=none"});
  ResolvedShot truth = s.resolved;
  truth.material.e = CorCurve::constant(0.78);
  truth.material.mu = 0.15;
  const ShotResult r = launch_shot(truth, "truth");
  FitTarget t;
  t.ball_speed = r.launch.ball_speed;
  t.launch_angle = r.launch.vertical_angle;
  t.spin = r.launch.spin.total;
  const FitResult f = fit_e_mu(s, t);
  CHECK(f.reached);
  CHECK(f.e == Approx(0.78).margin(0.002));
  CHECK(std::fabs(f.ball_speed_residual) < 0.01);
  CHECK(std::fabs(f.spin_residual) < rpm_to_radps(5));
  if (r.impact.contact == ContactKind::Slip) CHECK(f.mu == Approx(0.15).margin(0.005));
  // Unreachable: faster than any e can give.
  FitTarget fast;
  fast.ball_speed = mph_to_mps(200);
  const FitResult g = fit_e_mu(s, fast);
  CHECK_FALSE(g.reached);
  CHECK(g.e == Approx(1.0).margin(1e-9));
  const FitTarget parsed = parse_fit_target("ball_speed=120mph,launch_angle=16.3deg,spin=7097rpm");
  CHECK(*parsed.ball_speed == Approx(mph_to_mps(120)).epsilon(1e-15));
  CHECK_THROWS_WITH(parse_fit_target("ball_speed=120"), Contains("--target ball_speed=120") && Contains("missing unit"));
  CHECK_THROWS_WITH(parse_fit_target("carry=200yd"), Contains("unknown target 'carry'"));
  CHECK_THROWS_WITH(parse_fit_target("spin=30000rpm"), Contains("20000 rpm"));
  CHECK_THROWS_WITH(parse_fit_target("spin=3000rpm,spin=4000rpm"), Contains("spin is given twice"));
}

