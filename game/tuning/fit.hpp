// `sweetspot fit`: the restitution e and friction µ that make a scenario reproduce
// measured launch numbers (ball speed, launch angle, spin). Bounded least squares over
// e ∈ [0, 1], µ ∈ [0, µ_max]: a coarse grid for a robust start (the launch is not smooth
// where the contact switches between grip and slip), then projected Levenberg–Marquardt.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "game/content/scenario.hpp"

namespace sweetspot {

/// Measured launch numbers, SI; any subset (at least one).
struct FitTarget {
  std::optional<double> ball_speed;    ///< m/s
  std::optional<double> launch_angle;  ///< rad, vertical
  std::optional<double> spin;          ///< rad/s, total
};

/// Parses "ball_speed=167mph,launch_angle=10.9deg,spin=2686rpm" (units required). Throws
/// InputError naming --target, the key and its allowed range.
FitTarget parse_fit_target(std::string_view text);

/// A target counts as reached when every residual is within these (launch-monitor
/// precision): 1 mph, 0.5°, 100 rpm.
inline constexpr double kFitSpeedTolerance = 0.44704;                      ///< m/s
inline constexpr double kFitAngleTolerance = 0.5 * 3.14159265358979323846 / 180.0;  ///< rad
inline constexpr double kFitSpinTolerance = 100.0 * 2.0 * 3.14159265358979323846 / 60.0;  ///< rad/s

struct FitResult {
  double e = 0.0;
  double mu = 0.0;
  double mu_max = 0.0;              ///< the upper bound searched
  LaunchMetrics launch;             ///< what (e, µ) produces
  ContactKind contact = ContactKind::Grip;
  /// With a gripping contact every µ above tangential/normal impulse gives the same
  /// launch; this is that lower bound (0 when the contact slips).
  double mu_grip_threshold = 0.0;
  double ball_speed_residual = 0.0; ///< got - target, SI (0 when not targeted)
  double launch_angle_residual = 0.0;
  double spin_residual = 0.0;
  bool reached = false;             ///< every targeted residual within tolerance
  int evaluations = 0;              ///< deliveries solved
};

/// Fits e and µ (constant e replaces the equipment's speed curve). Throws InputError for a
/// launch-only scenario (nothing to fit) or an empty target.
FitResult fit_e_mu(const Scenario& base, const FitTarget& target);

}  // namespace sweetspot
