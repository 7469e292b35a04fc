// The grip threshold µ_grip: above it the launch no longer changes with µ, below it it does;
// for the rigid impulse model it is the sticking solution's J_t/J_n (closed form).
#include <catch2/catch.hpp>

#include <cmath>

#include "game/content/scenario.hpp"
#include "game/modes/lab/grip.hpp"
#include "support/test_assets.hpp"
#include "game/rules/run_shot.hpp"

using namespace sweetspot;

namespace {
LaunchMetrics launch_at(ResolvedShot s, double mu) {
  s.material.mu = mu;
  return launch_shot(s, "t").launch;
}
}  // namespace

TEST_CASE("rigid model: mu_grip is the sticking impulse ratio J_t/J_n", "[grip][impact]") {
  for (const char* name : {"golf/driver", "golf/7-iron", "golf/pw", "baseball/line-drive"}) {
    INFO(name);
    const Scenario s = load_scenario(test::assets(), name, {"world.name=none", "impact.model=rigid"});
    ResolvedShot stuck = s.resolved;
    stuck.material.mu = ImpactMaterial::kMu.max;
    const ShotResult r = launch_shot(stuck, "stuck");
    REQUIRE(r.impact.contact == ContactKind::Grip);
    const double ratio = r.impact.tangential_impulse / r.impact.normal_impulse;
    const double g = mu_grip(s.resolved);
    // The launch matches within the tolerance a little below the exact ratio.
    CHECK(g <= ratio + 1e-4);
    CHECK(g > 0.8 * ratio);
    CHECK(launch_at(s.resolved, ratio).spin.total == Approx(r.launch.spin.total).epsilon(1e-9));
  }
}

TEST_CASE("compliant model: above mu_grip the launch stops changing, below it it changes", "[grip][compliant]") {
  const GripTolerance tol;
  for (const char* name : {"golf/driver", "golf/pw", "baseball/line-drive"}) {
    INFO(name);
    const Scenario s = load_scenario(test::assets(), name, {"world.name=none"});
    const double g = mu_grip(s.resolved, tol);
    REQUIRE(g > 0.0);
    const LaunchMetrics stuck = launch_at(s.resolved, ImpactMaterial::kMu.max);
    const LaunchMetrics above = launch_at(s.resolved, std::min(g + 0.01, ImpactMaterial::kMu.max));
    // Half the threshold: just under it the contact's micro-slip moves the spin by about the
    // tolerance itself (~0.5 rad/s on the line drive), so the probe goes well below.
    const LaunchMetrics below = launch_at(s.resolved, 0.5 * g);
    CHECK(std::fabs(above.spin.total - stuck.spin.total) <= tol.spin + tol.spin_fraction * stuck.spin.total);
    CHECK(std::fabs(above.ball_speed - stuck.ball_speed) <= tol.ball_speed);
    const bool below_differs = std::fabs(below.spin.total - stuck.spin.total) > tol.spin + tol.spin_fraction * stuck.spin.total ||
                               std::fabs(below.ball_speed - stuck.ball_speed) > tol.ball_speed ||
                               std::fabs(below.vertical_angle - stuck.vertical_angle) > tol.angle;
    CHECK(below_differs);
  }
}

TEST_CASE("frictionless contact: mu_grip is 0, friction changes nothing", "[grip]") {
  const Scenario s = load_scenario(test::assets(), "golf/7-iron", {"world.name=none", "impact.friction=none"});
  CHECK(mu_grip(s.resolved) == 0.0);
}
