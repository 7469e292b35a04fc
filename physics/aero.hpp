// Aerodynamic models: drag and Magnus lift coefficients as functions of the spin parameter
// S = R·|ω|/|v_r|, and the spin decay rate. Models are named data with their source, so a
// scenario or the UI picks one by name; one model covers every club (no per-club tuning).
//
// Forces (DESIGN §4), with v_r = v - wind: drag -½ρA·Cd·|v_r|·v_r, lift
// ½ρA·Cl·|v_r|²·(ω × v_r)/(|ω|·|v_r|). The lift points along ω × v_r and scales with the
// share of the spin across the flow (sin of the angle between ω and v_r): rifle (gyro) spin
// makes none. The coefficients read the whole spin, S = R|ω|/|v_r|: the lift of a ball
// saturates with how fast its whole surface turns, not with its transverse spin alone. For
// a golf ball or a batted ball, whose spin lies across the flow, the two readings agree; for
// a pitch with a large gyro share they part where Cl(S) bends over: at Savant's measured
// active spin, sliders, cutters and curveballs move Savant's inches with this law and 1.3-1.9
// times as far with Cl read at the transverse spin alone (docs/validation.md, pitch
// movement). The Nathan drag term uses the total spin rate as well.
#pragma once

#include <string>
#include <string_view>

#include "physics/math.hpp"

namespace sweetspot {

enum class LiftLaw {
  Quadratic,   ///< Cl = l0 + l1 S + l2 S²
  Power,       ///< Cl = l1 S^l2
  Saturating,  ///< Cl = l1 S / (l0 + l2 S)
};

struct AeroCoefficients {
  double cd = 0.0;  ///< drag coefficient, golf ~0.2–0.3, baseball ~0.35
  double cl = 0.0;  ///< lift coefficient, golf driver ~0.2
};

/// The air density (kg/m³) at which the models' spin decay is stated: Environment{}'s air
/// (21 °C, 50 % relative humidity, 101 325 Pa; air_density() gives this double): the air of
/// Nathan's trajectory calculator's defaults (70 °F, sea level, 50 %) and of a sea-level
/// laboratory, where Smits & Smith measured the golf ball's decay. The decay is the air's
/// friction torque on the spinning ball, which is ∝ ρ (aero_models.toml: decay_length =
/// 2I/(ρ A R² c)), so both decay terms scale by ρ / this: a ball at Denver (ρ 17 % lower)
/// keeps its spin longer.
inline constexpr double kSpinDecayReferenceDensity = 1.1944245034101437;

/// The Reynolds number (ρ|v|D/µ) every aero model is stated and checked up to
/// (validate_aero_model): the launch range's 150 m/s golf ball into the strongest wind aloft
/// (hurricane force at 10 m is ~46 m/s at 100 m in the log law), ~5.5e5. A flight that starts
/// beyond it (a large, fast ball) is refused, not integrated.
inline constexpr double kMaxReynolds = 6e5;

/// A named drag/lift/spin-decay model. Immutable data; evaluate with coefficients(). The
/// shipped models and their sources are in assets/aero_models.toml.
struct AeroModel {
  std::string name;    ///< "ferguson2022", "smits_smith1994", "nathan"
  std::string sport;   ///< "golf" or "baseball"
  std::string source;  ///< citation, shown by the UI
  // Drag: Cd = d0 + d1 S + d2 S² + d_krpm · (total spin / 1000 rpm)
  double d0 = 0.0, d1 = 0.0, d2 = 0.0, d_krpm = 0.0;
  LiftLaw lift = LiftLaw::Quadratic;
  double l0 = 0.0, l1 = 0.0, l2 = 0.0;
  /// Upper end of the fitted S range; S is held there beyond it so a quadratic fit does
  /// not turn over (slow, high-spin balls late in a wedge's descent reach S ~ 0.5+).
  double s_max = 1e9;
  /// Below this S the lift falls linearly to 0 at S = 0: a ball that does not spin has no
  /// Magnus lift by symmetry, whatever a fit's intercept says (0 = the law as written).
  double lift_onset = 0.0;
  /// Drag crisis: below the critical Reynolds number the boundary layer stays laminar and
  /// Cd rises by crisis_rise, Cd += rise / (1 + exp((Re − re)/width)). 0 = none.
  double crisis_re = 0.0, crisis_rise = 0.0, crisis_width = 1.0;
  /// Past the crisis a dimpled ball's drag climbs again with Reynolds number (the
  /// supercritical rise of rough spheres, Achenbach 1974): Cd += drag_re_slope ·
  /// (Re − crisis_re)/1e5 · (1 − 1/(1 + exp((Re − crisis_re)/width))), the crisis's
  /// turbulent fraction (smooth: ~0 below the crisis, the straight line above it). 0 = none;
  /// tour_fit 0.058 per 1e5. Needs a crisis (crisis_rise > 0): it is measured from it.
  double drag_re_slope = 0.0;
  /// Spin decay dω/dt = -ω (decay_per_metre·|v_r| + 1/decay_tau)·ρ/kSpinDecayReferenceDensity.
  /// Golf: proportional to speed, ~4 %/s (ferguson2022, 5.36e-4 1/m) to 6.7 %/s (tour_fit's
  /// Smits & Smith, 8.95e-4 1/m) at a driver's 74.7 m/s. Nathan: tau ≈ 30 s. Both stated at
  /// the reference density.
  double decay_per_metre = 0.0;  ///< 1/m
  double decay_tau = 0.0;        ///< s; 0 = no speed-independent term

  /// Coefficients at spin parameter `s` (≥ 0), total spin rate `spin` (rad/s) and Reynolds
  /// number `re` (ρ|v|D/µ; a driver launches at ~2e5). Continuous in all three.
  AeroCoefficients coefficients(double s, double spin, double re = 2e5) const;
  /// Spin decay rate (1/s) at air speed `speed` (m/s) in air of `density` (kg/m³).
  double spin_decay_rate(double speed, double density = kSpinDecayReferenceDensity) const;
};

const char* to_string(LiftLaw l);
/// "quadratic", "power", "saturating"; false when unknown.
bool lift_law_from_string(std::string_view name, LiftLaw* out);
/// Empty when `m` is usable (finite coefficients; 0 < Cd ≤ 2 and |Cl| ≤ 2 over S in
/// [0, s_max], Re in [0, 6e5] and spin up to 20 000 rpm; no lift pole; a slope past the
/// crisis only with a crisis, of width ≥ 100);
/// otherwise a message naming the model and the problem. Models are data
/// (assets/aero_models.toml, loaded by game/content).
std::string validate_aero_model(const AeroModel& m);

/// Aerodynamic force (N) on a ball of `radius` (m) in air of `density` (kg/m³) moving at
/// `v_rel` (m/s, relative to the air) with spin `omega` (rad/s), and dω/dt (rad/s²).
struct AeroEffect {
  Vec3 force = Vec3::Zero();
  Vec3 spin_rate = Vec3::Zero();
};
/// `viscosity`: the air's dynamic viscosity, Pa·s (air_viscosity(); 1.81e-5 at 20 °C).
AeroEffect aero_effect(const AeroModel& model, double density, double radius, const Vec3& v_rel,
                       const Vec3& omega, double viscosity = 1.81e-5);

}  // namespace sweetspot
