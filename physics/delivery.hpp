// Delivery: a swing (and a pitch) -> the contact state -> the impulse solve -> launch
// conditions in the conventions of DESIGN §2. Everything that shapes the launch (gear
// effect, bulge and roll, the bat's effective mass along the barrel) comes from geometry
// and inertia fed to the same impulse solver; there is no hand-added spin term.
#pragma once

#include <limits>

#include "physics/equipment.hpp"
#include "physics/impact.hpp"
#include "physics/launch.hpp"

namespace sweetspot {

/// A golf swing at impact, launch-monitor conventions (DESIGN §2). Defaults: a tour driver.
struct GolfSwing {
  double club_speed = 50.5;    ///< m/s of the face centre; tour driver 113 mph = 50.5 m/s
  double attack_angle = 0;     ///< rad, + up; tour driver -1.3°, 7-iron -4.3°
  double club_path = 0;        ///< rad, + right (in-to-out for a right-hander)
  double dynamic_loft = std::numeric_limits<double>::quiet_NaN();  ///< rad; NaN -> club.dynamic_loft
  double face_angle = 0;       ///< rad, + open (face pointing right of target)
  double impact_toe = 0;       ///< m from the face centre, + toward the toe; ±20 mm is a big miss
  double impact_up = 0;        ///< m from the face centre, + up the face
  double closure_rate = 0;     ///< rad/s about the shaft axis, + closing; tour ~ 30–40 rad/s
};

/// A bat swing at impact. Defaults: a line drive with a wood bat.
struct BatSwing {
  double bat_speed = 31.3;     ///< m/s at the sweet spot (70 mph, Statcast average)
  double attack_angle = 0.15;  ///< rad, + up: tilt of the swing plane (velocity of the sweet spot)
  double direction = 0;        ///< rad, + toward right field: horizontal direction of the swing
  double impact_from_tip = 0.1524;  ///< m along the barrel from the tip (6 in = sweet spot)
  double undercut = 0;         ///< m, + ball centre above the bat axis (backspin, loft); ±20 mm typical
};

/// The pitch arriving at the plate.
struct Pitch {
  double speed = 40.2;         ///< m/s (90 mph)
  double approach_angle = 0.1; ///< rad, + descending (fastball ~6°)
  double spin = 240;           ///< rad/s (~2300 rpm)
  double spin_axis = 0;        ///< rad, 0 = pure backspin for the pitcher's ball (DESIGN §2 axis sign)
};

/// The impactor (club head or bat) at the instant of impact, before the impulse: its mesh
/// frame (HEAD or BAT frame, physics/equipment.hpp) mapped to world, and the velocity of
/// the mesh-frame origin and the angular velocity (world, SI).
struct ImpactorPose {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
};

struct Delivery {
  LaunchState launch;               ///< ball state at separation
  ImpactResult impact;              ///< the solve (impulses, contact kind, energy)
  ImpactInput impact_input;         ///< what was solved (for diagnostics and tests)
  ImpactorPose impactor_at_impact;  ///< for rendering
  double impactor_speed = 0;        ///< m/s, club head / bat at the contact point before impact
  double smash_factor = 0;          ///< ball speed / impactor_speed
};

/// Golf: ball at rest on the tee at the world origin (centre at y = radius). Throws
/// InputError naming the field and range on invalid input. `material` is the club face's
/// material after any scenario override.
Delivery deliver_golf(const BallSpec& ball, const ClubSpec& club, const GolfSwing& swing,
                      const ImpactMaterial& material);

/// Baseball: contact 0.9 m above home plate at the origin, pitch travelling toward -x.
/// Throws InputError on invalid input. `material` is the bat's ball–bat material; its e
/// curve is scaled by bat.cor_factor_at(impact_from_tip).
Delivery deliver_baseball(const BallSpec& ball, const BatSpec& bat, const BatSwing& swing,
                          const Pitch& pitch, const ImpactMaterial& material);

/// Height of the baseball's centre at contact, m.
inline constexpr double kBaseballContactHeight = 0.9;

}  // namespace sweetspot
