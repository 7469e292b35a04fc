// Delivery: a swing (and a pitch) -> the contact state -> the impulse solve -> launch
// conditions in the conventions of DESIGN §2. Everything that shapes the launch (gear
// effect, bulge and roll, the bat's effective mass along the barrel) comes from geometry
// and inertia fed to the same impulse solver; there is no hand-added spin term.
#pragma once

#include <cmath>
#include <limits>

#include "physics/compliant_impact.hpp"
#include "physics/equipment.hpp"
#include "physics/impact.hpp"
#include "physics/launch.hpp"
#include "physics/range.hpp"
#include "physics/sand_splash.hpp"

namespace sweetspot {

/// A golf swing at impact, launch-monitor conventions (DESIGN §2). Defaults: a tour driver.
/// Each field's allowed range sits beside it; validate_golf_swing() checks them all.
struct GolfSwing {
  double club_speed = 50.5;    ///< m/s of the face centre; tour driver 113 mph = 50.5 m/s, a 3 m putt ~1.5 m/s
  /// From a tap-in putt to beyond the long-drive record (~68 m/s, 152 mph). The floor: a
  /// putter head at 0.1 m/s starts the ball at ~0.15 m/s, which rolls ~2 cm on a stimp-10
  /// green; slower is no stroke (and 1e-300 m/s makes the smash factor infinite).
  static constexpr Range kClubSpeed{0.1, 90.0};
  double attack_angle = 0;     ///< rad, + up; tour driver -1.3°, 7-iron -4.3°, putter ~+2°
  static constexpr Range kAttackAngle{deg_to_rad(-30.0), deg_to_rad(30.0)};
  double club_path = 0;        ///< rad, + right (in-to-out for a right-hander)
  static constexpr Range kClubPath{deg_to_rad(-30.0), deg_to_rad(30.0)};
  double dynamic_loft = std::numeric_limits<double>::quiet_NaN();  ///< rad; NaN -> club.dynamic_loft
  /// A de-lofted putter (0°) to a lob wedge laid wide open.
  static constexpr Range kDynamicLoft{0.0, deg_to_rad(80.0)};
  /// rad, the loft where the face meets the ball: what TrackMan reports as "dynamic loft"
  /// (the face's vertical angle at the centre-point of contact), which on a rolled driver
  /// face exceeds the face-centre loft by the roll's tilt at the strike (strike_tilt()).
  /// NaN -> from dynamic_loft; setting both is an error. Same range as kDynamicLoft.
  double strike_loft = std::numeric_limits<double>::quiet_NaN();
  double face_angle = 0;       ///< rad, + open (face pointing right of target), at the face centre
  static constexpr Range kFaceAngle{deg_to_rad(-30.0), deg_to_rad(30.0)};
  /// rad, + open, the face's direction where it meets the ball: what TrackMan reports as
  /// "face angle" (the direction the face points at the centre-point of contact), which on a
  /// bulged driver face is open of the face centre's by the bulge's turn at a toe strike
  /// (strike_turn()). NaN -> from face_angle; setting it with a face_angle other than 0 is
  /// an error. Same range as kFaceAngle.
  double strike_face_angle = std::numeric_limits<double>::quiet_NaN();
  double impact_toe = 0;       ///< m from the face centre, + toward the toe; ±20 mm is a big miss
  static constexpr Range kImpactToe{-0.05, 0.05};  ///< half a driver face (~110 mm wide)
  /// m from the face centre, + up the face; NaN -> club.strike_height (the tour player's
  /// usual strike: the driver's is high on the face, every other club's at the centre).
  double impact_up = std::numeric_limits<double>::quiet_NaN();
  static constexpr Range kImpactUp{-0.03, 0.03};   ///< half a driver face (~60 mm tall)
  double closure_rate = 0;     ///< rad/s about the shaft axis, + closing; tour ~ 30–40 rad/s
  static constexpr Range kClosureRate{-110.0, 110.0};  ///< ±6300 deg/s, ~3x a tour player's
  /// m before the ball where the club enters the sand: a splash from a bunker
  /// (physics/sand_splash.hpp); 0, the ball struck first. Range kSandEntry.
  double sand_entry = 0.0;
};

/// A bat swing at impact. Defaults: a line drive with a wood bat.
struct BatSwing {
  double bat_speed = 31.3;     ///< m/s at the sweet spot (70 mph, Statcast average)
  /// Statcast's fastest swings ~90 mph (40 m/s); the floor is a bunt's bat barely moving
  /// (0.5 m/s: slower is no swing, and denormal speeds make the smash factor infinite).
  static constexpr Range kBatSpeed{0.5, 60.0};
  double attack_angle = 0.15;  ///< rad, + up: tilt of the swing plane (velocity of the sweet spot)
  static constexpr Range kAttackAngle{deg_to_rad(-45.0), deg_to_rad(60.0)};
  double direction = 0;        ///< rad, + toward right field: horizontal direction of the swing
  static constexpr Range kDirection{deg_to_rad(-90.0), deg_to_rad(90.0)};
  /// rad, the bat's axis from the hands to the head against level at contact, − head below
  /// the hands (Blast Motion's "vertical bat angle"). A swing in a tilted plane meets the ball
  /// with the head below the hands (~30° down in the league's 32° plane); the ball then leaves
  /// along a normal tilted toward the opposite field when the bat is under its centre and
  /// toward the pull side when over it. 0 = a level bat.
  double vertical_bat_angle = 0.0;
  static constexpr Range kVerticalBatAngle{deg_to_rad(-80.0), deg_to_rad(30.0)};
  /// m along the barrel from the tip (6 in = sweet spot). Below 0 the ball's centre is past
  /// the end of the bat and its edge meets the end cap's rim (down to 95 % of the ball's radius
  /// past it): the ball caught off the end.
  double impact_from_tip = 0.1524;
  /// Outer bound (the longest bats, 42 in; 5 cm past the end, more than any ball's radius); the
  /// bat and ball limit it to the barrel beyond 5 cm past the pivot and 95 % of the ball's radius
  /// past the tip.
  static constexpr Range kImpactFromTip{-0.05, 1.0668};
  double undercut = 0;         ///< m, + ball centre above the bat axis (backspin, loft); ±20 mm typical
  /// Outer bound; the bat and ball radii limit it to 95 % of their sum at the contact.
  static constexpr Range kUndercut{-0.1, 0.1};
};

/// The pitch arriving at the plate.
struct Pitch {
  double speed = 40.2;         ///< m/s (90 mph); 0 = a ball on a batting tee
  /// Up to 110 mph: the fastest pitch on record is 105.8 mph (Chapman, 2010).
  static constexpr Range kSpeed{0.0, 49.1744};
  double approach_angle = 0.1; ///< rad, + descending (fastball ~6°)
  static constexpr Range kApproachAngle{deg_to_rad(-20.0), deg_to_rad(45.0)};
  double spin = 240;           ///< rad/s (~2300 rpm)
  /// Up to 4000 rpm: the highest MLB spin rates are ~3500 rpm (Statcast curveballs).
  static constexpr Range kSpin{0.0, 418.87902047863906};
  double spin_axis = 0;        ///< rad, 0 = pure backspin for the pitcher's ball (DESIGN §2 axis sign)
  static constexpr Range kSpinAxis{-kPi, kPi};
};

/// Each throws InputError naming the field (as a scenario key) and its allowed range.
void validate_golf_swing(const GolfSwing& swing, const ClubSpec& club);
/// m, how far above the face centre the swing strikes the ball: swing.impact_up, else the
/// club's typical strike height (ClubSpec::strike_height).
inline double strike_up(const GolfSwing& swing, const ClubSpec& club) {
  return std::isnan(swing.impact_up) ? club.strike_height : swing.impact_up;
}
/// rad, how much the face's roll (sole-to-crown curvature) tilts the face normal up at a
/// strike `up` metres above the centre: atan(up / roll_radius). 2.2° at 11.5 mm on a 305 mm
/// roll; ~0 on an iron's flat face.
double strike_tilt(const ClubSpec& club, double up);
/// rad, the face-centre loft the swing delivers: dynamic_loft, else strike_loft less the
/// tilt at the swing's strike, else the club's default.
double face_centre_loft(const GolfSwing& swing, const ClubSpec& club);
/// rad, how far the face's bulge (heel-to-toe curvature) turns the horizontal direction of
/// the face normal, + open, at a strike `toe` metres toward the toe and `up` metres up on a
/// face whose centre has loft `centre_loft`: the azimuth of the normal (1, up/R_roll,
/// toe/R_bulge) after the loft, atan2(toe/R_bulge, cos L - sin L · up/R_roll). 2.4° at a
/// half-inch toe strike on a 305 mm bulge; ~0 on an iron's flat face.
double strike_turn(const ClubSpec& club, double centre_loft, double toe, double up);
/// rad, the face-centre face angle the swing delivers: strike_face_angle less the turn at
/// the swing's strike, else face_angle.
double face_centre_face_angle(const GolfSwing& swing, const ClubSpec& club);
/// Unit vector of the face centre's motion: up by the attack angle, right by the path.
Vec3 head_direction(const GolfSwing& swing);
/// Why a swing that sets both swing.dynamic_loft and swing.strike_loft is refused.
inline constexpr const char* kLoftGivenTwice =
    "give the loft at the face centre (swing.dynamic_loft) or where the face meets the ball (swing.strike_loft), not both";
/// Why a swing that sets both swing.face_angle and swing.strike_face_angle is refused.
inline constexpr const char* kFaceAngleGivenTwice =
    "give the face angle at the face centre (swing.face_angle) or where the face meets the ball (swing.strike_face_angle), not both";
void validate_bat_swing(const BatSwing& swing, const BatSpec& bat, const BallSpec& ball);
void validate_pitch(const Pitch& pitch);

/// Past the end of a bat a ball's edge still catches the end cap's rim while its centre is
/// within this share of its radius beyond the tip (BatSwing::impact_from_tip); the share keeps
/// the tilted normal off the axis.
inline constexpr double kEndCapReach = 0.95;
/// Where along `bat` (m from the tip) a ball can meet it: from its edge on the end cap's rim,
/// kEndCapReach of its radius past the tip, in to 5 cm outside the swing's pivot.
Range bat_contact_range(const BatSpec& bat, const BallSpec& ball);
/// From the bat's axis to the ball's centre at contact `from_tip` m from the tip: the barrel's
/// radius and the ball's; past the tip, the ball's edge on the end cap's rim.
double bat_ball_reach(const BatSpec& bat, const BallSpec& ball, double from_tip);

/// The bat's axis (knob to tip) across the sweet spot's path `path` (unit), turned about the
/// path from `level` (unit, across the path and level) until the axis stands at
/// `vertical_bat_angle` from level (− head down): the turn is asin(sin v / cos α) for a path
/// climbing at α, which exists while |v| ≤ 90° − |α| (a tilted plane keeps
/// sin²α + sin²v = sin²tilt ≤ 1).
Vec3 bat_axis_across(const Vec3& path, const Vec3& level, double vertical_bat_angle);

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
  LaunchState launch;               ///< ball state at separation (position: its centre before impact)
  /// The solve (impulses, contact kind, energy; e_t_used is the tangential restitution the
  /// contact produced: −u_t'·û_t / |u_t| at the first contact point).
  ImpactResult impact;
  ImpactInput impact_input;         ///< the instantaneous model's input at first touch (diagnostics, tests)
  bool compliant = false;           ///< solved with duration (physics/compliant_impact.hpp)
  double contact_time = 0.0;        ///< s the ball was on the face (compliant), 0 for the rigid impulse
  /// The two bodies as they first touch and as they separate (world frame, CG poses). The
  /// instantaneous impulse leaves the poses where they were; the impact with duration moves
  /// and turns them. Momentum and angular momentum balances use these (tests).
  RigidBody impactor_before, ball_before, impactor_separated, ball_separated;
  ImpactorPose impactor_at_impact;  ///< for rendering
  double impactor_speed = 0;        ///< m/s, club head / bat at the contact point before impact
  double smash_factor = 0;          ///< ball speed / impactor_speed
};

/// Whether a strike of this ball with this material is solved with duration (the compliant
/// contact: the ball has a contact layer and the model asks for it) rather than as an
/// instantaneous impulse; the textbook's friction law is instantaneous by definition.
bool uses_duration(const BallSpec& ball, const ImpactMaterial& m);

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

/// The same with the ball's velocity and spin as it arrives (a pitch flown to the plate), m/s
/// and rad/s; its speed and spin within Pitch's ranges.
Delivery deliver_baseball(const BallSpec& ball, const BatSpec& bat, const BatSwing& swing, const Vec3& pitch_velocity,
                          const Vec3& pitch_spin, const ImpactMaterial& material);

/// Height of the baseball's centre at contact, m.
inline constexpr double kBaseballContactHeight = 0.9;

}  // namespace sweetspot
