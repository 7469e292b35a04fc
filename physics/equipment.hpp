// Equipment parameter sets (DESIGN §3): the balls, the golf bag and the bats, as plain
// immutable data. Values live in assets/equipment/*.toml with their sources; the loader is
// game/equipment/equipment_file.hpp. Everything SI.
//
// HEAD FRAME (also the club mesh frame): origin at the face centre, +x out of the face
// (toward the ball when square), +y up along the face, +z toward the toe, at the club's
// static-loft = 0 orientation; delivery applies the dynamic loft by rotation.
// BAT FRAME (also the bat mesh frame): origin at the knob end, +x along the axis to the tip.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "physics/impact.hpp"
#include "physics/math.hpp"
#include "physics/range.hpp"

namespace sweetspot {

/// A ball's contact layer for the impact with duration (physics/compliant_impact.hpp).
struct BallCompliance {
  /// N/m^1.5, Hertz coefficient of F = k δ^{3/2}. Set from a measured contact time (a golf
  /// ball is on a driver's face ~0.45 ms at 45 m/s; a baseball on a bat ~0.7 ms). 0 = rigid:
  /// deliveries then use the instantaneous impulse of physics/impact.hpp.
  double stiffness = 0.0;
  static constexpr Range kStiffness{0.0, 1e12};
  static constexpr double kMinStiffness = 1e5;  ///< N/m^1.5, for a stiffness other than 0 (validate_ball)
  /// Poisson's ratio of the ball's rubber; the Mindlin ratio of tangential to normal contact
  /// stiffness is 2(1−ν)/(2−ν) (0.67 for ν = 0.5). Rubber cores ~0.48.
  double poisson = 0.48;
  static constexpr Range kPoisson{0.0, 0.5};
  /// Tangential over normal contact stiffness of the patch, k_t / (dF_n/dδ), when measured
  /// for the ball itself; 0 = Mindlin's 2(1−ν)/(2−ν) from `poisson`. A wound baseball's
  /// cover and yarn shear far more easily than a solid rubber's Mindlin ratio allows: Kensrud,
  /// Nathan & Smith (Am. J. Phys. 85 (2017) 503) fit k_n/k_t = 4.75 (0.21).
  double shear_stiffness_ratio = 0.0;
  static constexpr Range kShearStiffnessRatio{0.0, 1.0};
  /// The ratio the contact uses: the measured one, or Mindlin's from ν.
  double shear_ratio() const {
    return shear_stiffness_ratio > 0.0 ? shear_stiffness_ratio : 2.0 * (1.0 - poisson) / (2.0 - poisson);
  }
  /// The rubber's hysteresis in shear relative to compression: the tangential spring is
  /// damped by this × the Mindlin ratio × the normal law's Hunt–Crossley damping. 0 = an
  /// elastic shear spring (the ball's tangential rebound rings undamped); tour ball 2.0,
  /// fitted to TrackMan's PGA irons and woods (balls.toml).
  double tangential_damping = 1.0;
  static constexpr Range kTangentialDamping{0.0, 10.0};
};

struct BallSpec {
  std::string name;     ///< "tour" (golf), "mlb" (baseball)
  double mass = 0.04593;    ///< kg; golf 45.93 g (USGA max), baseball 0.145
  static constexpr Range kMass{0.01, 0.5};  ///< a ping-pong ball (2.7 g) is out; a softball (0.19 kg) is in
  double radius = 0.021335; ///< m; golf 42.67 mm diameter, baseball 36.9 mm radius
  static constexpr Range kRadius{0.01, 0.1};
  double inertia = 8.363e-6;///< kg·m² about any diameter; 0.4 m R² for both balls (DESIGN §3)
  BallCompliance compliance;  ///< the contact layer the compliant impact presses (physics/compliant_impact.hpp)
};

struct ClubSpec {
  std::string name;      ///< "driver","3-wood","5-wood","hybrid","3-iron".."9-iron","pw","sw","lw"
  double loft = 0.171;   ///< rad, static loft; putter 3°, driver 9.8°, 7-iron 34°
  static constexpr Range kLoft{0.0, deg_to_rad(70.0)};
  double lie = 1.03;     ///< rad, static lie; driver ~59°, 7-iron ~62.5°, putter ~70°
  static constexpr Range kLie{deg_to_rad(40.0), deg_to_rad(80.0)};
  double dynamic_loft = 0.22;  ///< rad, typical delivered loft of a tour player (scenario default); range GolfSwing::kDynamicLoft
  /// m above the face centre where a tour player usually strikes the ball (scenario default
  /// of the impact's up offset): ~+10 mm on a driver teed high, 0 for the other clubs.
  double strike_height = 0.0;  ///< range GolfSwing::kImpactUp
  double head_mass = 0.204;    ///< kg; driver 204 g, 7-iron ~267 g, putter ~350 g
  /// kg of shaft tip that moves with the head during the ~0.45 ms contact (a bending wave
  /// travels ~0.1 m of shaft in that time): McNally, McPhee & Henrikson (ISEA 2020) needed
  /// ~3 g on a measured driver to match measured ball speeds. Added to the head's mass.
  double shaft_tip_mass = 0.0;
  static constexpr Range kShaftTipMass{0.0, 0.05};
  static constexpr Range kHeadMass{0.05, 1.0};
  /// The scenario's club.head_mass override is this range too.
  Vec3 cg{-0.0423, 0.0, 0.0};  ///< m, CG in the head frame (x < 0: behind the face)
  Mat3 inertia = Mat3::Identity() * 4e-4;  ///< kg·m² about the CG in head axes; driver ~2.8e-4..5.7e-4
  double bulge_radius = 0.305; ///< m, heel-toe face curvature; irons ~10 m (flat)
  double roll_radius = 0.305;  ///< m, sole-crown face curvature; irons ~10 m (flat)
  static constexpr Range kFaceRadius{0.1, 1000.0};  ///< bulge and roll
  ImpactMaterial face;         ///< ball–face e curve, e_t, µ, friction model
  /// The face's size (half-width heel-toe, half-height sole-crown, m) and its COR map: the
  /// ball–face COR falls toward the edges of the face (the face flexes, and the head's mass
  /// backs it, less there), e × (1 − cor_edge_drop·r⁴), r² = (toe/w)² + (up/h)². A driver face is
  /// ~110 × 56 mm; irons ~76 × 46 mm.
  double face_half_width = 0.055;
  double face_half_height = 0.028;
  static constexpr Range kFaceHalfSize{0.005, 0.1};
  double cor_edge_drop = 0.0;
  static constexpr Range kCorEdgeDrop{0.0, 0.5};
  /// The COR map's factor at an impact `toe`, `up` (m) from the face centre, in (0, 1].
  double face_cor_factor(double toe, double up) const;
  double length = 1.14;        ///< m, shaft length (display and rendering only); putter ~0.86
  static constexpr Range kLength{0.5, 1.3};
};

struct BatSpec {
  std::string name;           ///< "maple" (wood), "bbcor" (alloy)
  double length = 0.84;       ///< m; a 33 in bat
  static constexpr Range kLength{0.5, 1.2};
  double mass = 0.989;        ///< kg
  static constexpr Range kMass{0.3, 2.0};  ///< also the scenario's bat.mass override
  double cg_from_knob = 0.575;///< m; Cross & Nathan's wood bat: 0.265 m from the barrel end
  double inertia_cg = 0.046;  ///< kg·m² about the CG, transverse axis
  static constexpr Range kInertiaCg{1e-3, 1.0};
  double inertia_axial = 2.0e-4;  ///< kg·m² about the long axis (small; ~ ½ m r² of the barrel)
  /// (distance from knob m, radius m), distances strictly increasing, first at 0, last at
  /// `length`. The barrel is 1.3 in (33 mm) in radius at most (MLB rule 3.02).
  std::vector<std::pair<double, double>> barrel_profile;
  double sweet_spot_from_tip = 0.1524;  ///< m; Statcast: 6 in
  double pivot_from_knob = 0.15;        ///< m; the swing's rotation centre, near the hands
  ImpactMaterial material;     ///< ball–bat e curve, e_t, µ
  /// Ball–bat restitution multiplier along the barrel, (distance from tip m, factor ≤ 1),
  /// distances increasing. Models the barrel vibrations a rigid bat lacks (Nathan 2000;
  /// Cross 1999): COR peaks near the node ~5–7 in from the tip and falls toward both ends.
  /// Empty = 1 everywhere.
  std::vector<std::pair<double, double>> cor_profile;

  /// m from the swing's pivot out to the tip: a point `from_pivot` out lies this less it from the tip.
  double pivot_to_tip() const { return length - pivot_from_knob; }
  /// m from the swing's pivot out to the sweet spot: the arm the bat turns the sweet spot on.
  double sweet_arm() const { return pivot_to_tip() - sweet_spot_from_tip; }
  /// Barrel radius (m) at `from_knob` (m), linear between profile points, 0 outside.
  double radius_at(double from_knob) const;
  /// Restitution factor at `from_tip` (m), linear between cor_profile points, held at ends.
  double cor_factor_at(double from_tip) const;
};

/// Each throws InputError naming the field and its allowed range ("club 'driver': loft
/// must be in [0, 70] deg, got ...").
void validate_ball(const BallSpec& b);
void validate_club(const ClubSpec& c);
void validate_bat(const BatSpec& b);
/// Throws InputError on an invalid ball–impactor material (`what` prefixes the message).
void validate_material(const ImpactMaterial& m, const std::string& what);

}  // namespace sweetspot
