#include "game/modes/lab/grip.hpp"

#include <cmath>

#include "physics/impact.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
namespace {

bool same_launch(const LaunchMetrics& a, const LaunchMetrics& b, const GripTolerance& tol) {
  return std::fabs(a.ball_speed - b.ball_speed) <= tol.ball_speed &&
         std::fabs(a.vertical_angle - b.vertical_angle) <= tol.angle &&
         std::fabs(a.horizontal_angle - b.horizontal_angle) <= tol.angle &&
         std::fabs(a.spin.total - b.spin.total) <= tol.spin + tol.spin_fraction * std::fabs(b.spin.total) &&
         std::fabs(a.spin.axis_rad - b.spin.axis_rad) <= tol.angle;
}

}  // namespace

double mu_grip(const ResolvedShot& shot, const GripTolerance& tol) {
  if (shot.material.friction == FrictionModel::None) return 0.0;
  ResolvedShot s = shot;
  const auto launch_at = [&](double mu) {
    s.material.mu = mu;
    return launch_shot(s, "grip").launch;
  };
  // Bisection needs "matches" to hold for every µ above the threshold: friction only caps
  // the tangential force, so a larger µ caps it less, and once the cap is never reached
  // the launch no longer depends on µ.
  double hi = ImpactMaterial::kMu.max;
  const LaunchMetrics stuck = launch_at(hi);
  double lo = 0.0;
  if (same_launch(launch_at(lo), stuck, tol)) return 0.0;
  while (hi - lo > 1e-4) {
    const double mid = 0.5 * (lo + hi);
    (same_launch(launch_at(mid), stuck, tol) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace sweetspot
