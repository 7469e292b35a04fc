#include "physics/aero.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

// Golf spin decay: ~4 %/s at a tour driver's ball speed (167 mph = 74.66 m/s), taken
// proportional to air speed (Smits & Smith's decay scales with V/R; TrackMan data show
// ~4 %/s for drivers).
constexpr double kGolfDecayPerMetre = 0.04 / 74.66;

std::array<AeroModel, 3> build_models() {
  AeroModel ferguson;
  ferguson.name = "ferguson2022";
  ferguson.sport = "golf";
  ferguson.source =
      "Ferguson (2022), quadratic Cd(S), Cl(S) fit to 1040 launch-monitor shots: "
      "Cd = 0.1304 + 0.9287 S - 0.8259 S^2, Cl = 0.0504 + 1.2031 S - 1.1490 S^2";
  ferguson.d0 = 0.1304;
  ferguson.d1 = 0.9287;
  ferguson.d2 = -0.8259;
  ferguson.lift = LiftLaw::Quadratic;
  ferguson.l0 = 0.0504;
  ferguson.l1 = 1.2031;
  ferguson.l2 = -1.1490;
  // Both parabolas peak near S = 0.52 (Cl at 0.524, Cd at 0.562): hold S there.
  ferguson.s_max = 0.52;
  ferguson.decay_per_metre = kGolfDecayPerMetre;

  AeroModel smits;
  smits.name = "smits_smith1994";
  smits.sport = "golf";
  smits.source =
      "Smits & Smith (1994), 'A new aerodynamic model of a golf ball in flight', Science and "
      "Golf II: Cd = 0.24 + 0.18 S, Cl = 0.54 S^0.4";
  smits.d0 = 0.24;
  smits.d1 = 0.18;
  smits.lift = LiftLaw::Power;
  smits.l1 = 0.54;
  smits.l2 = 0.4;
  smits.s_max = 0.5;
  smits.decay_per_metre = kGolfDecayPerMetre;

  AeroModel nathan;
  nathan.name = "nathan";
  nathan.sport = "baseball";
  nathan.source =
      "A. M. Nathan, trajectory calculator: Cd = 0.3008 + 0.0292 (spin/1000 rpm), "
      "Cl = 1.120 S / (0.583 + 2.333 S), spin decay time constant ~30 s";
  nathan.d0 = 0.3008;
  nathan.d_krpm = 0.0292;
  nathan.lift = LiftLaw::Saturating;
  nathan.l0 = 0.583;
  nathan.l1 = 1.120;
  nathan.l2 = 2.333;
  nathan.decay_tau = 30.0;

  return {ferguson, smits, nathan};
}

const std::array<AeroModel, 3>& models() {
  static const std::array<AeroModel, 3> m = build_models();
  return m;
}

}  // namespace

AeroCoefficients AeroModel::coefficients(double s, double spin) const {
  const double sc = std::min(s, s_max);
  AeroCoefficients c;
  c.cd = d0 + d1 * sc + d2 * sc * sc + d_krpm * (radps_to_rpm(spin) / 1000.0);
  switch (lift) {
    case LiftLaw::Quadratic: c.cl = l0 + l1 * sc + l2 * sc * sc; break;
    case LiftLaw::Power: c.cl = sc > 0.0 ? l1 * std::pow(sc, l2) : 0.0; break;
    case LiftLaw::Saturating: c.cl = l1 * sc / (l0 + l2 * sc); break;
  }
  return c;
}

double AeroModel::spin_decay_rate(double speed) const {
  return decay_per_metre * speed + (decay_tau > 0.0 ? 1.0 / decay_tau : 0.0);
}

const AeroModel& aero_model(std::string_view name) {
  for (const AeroModel& m : models()) {
    if (m.name == name) return m;
  }
  std::string allowed;
  for (const auto& n : aero_model_names()) allowed += (allowed.empty() ? "" : ", ") + n;
  throw InputError("unknown aero model '" + std::string(name) + "' (allowed: " + allowed + ")");
}

std::vector<std::string> aero_model_names() {
  std::vector<std::string> names;
  for (const AeroModel& m : models()) names.push_back(m.name);
  return names;
}

const AeroModel& default_aero_model(std::string_view sport) {
  if (sport == "golf") return aero_model("ferguson2022");
  if (sport == "baseball") return aero_model("nathan");
  throw InputError("unknown sport '" + std::string(sport) + "' (allowed: golf, baseball)");
}

AeroEffect aero_effect(const AeroModel& model, double density, double radius, const Vec3& v_rel,
                       const Vec3& omega) {
  AeroEffect fx;
  const double speed = v_rel.norm();
  const double spin = omega.norm();
  fx.spin_rate = -model.spin_decay_rate(speed) * omega;
  if (speed <= 0.0) return fx;
  const Vec3 lift_dir_unnorm = omega.cross(v_rel);  // |ω × v_r| = ω⊥ |v_r|
  const double w_perp = lift_dir_unnorm.norm() / speed;
  const double s = radius * w_perp / speed;
  const AeroCoefficients c = model.coefficients(s, spin);
  const double q_area = 0.5 * density * kPi * radius * radius;  // ½ρA
  fx.force = -q_area * c.cd * speed * v_rel;
  if (w_perp > 0.0) fx.force += q_area * c.cl * speed * speed * (lift_dir_unnorm / (w_perp * speed));
  return fx;
}

}  // namespace sweetspot
