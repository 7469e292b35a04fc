#include "physics/aero.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/detail/aero_kernel.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
AeroCoefficients AeroModel::coefficients(double s, double spin, double re) const {
  return detail::aero_coefficients(*this, s, spin, re, 1.0 / crisis_width, lift_onset > 0.0 ? 1.0 / lift_onset : 0.0);
}

double AeroModel::spin_decay_rate(double speed, double density) const {
  return (decay_per_metre * speed + (decay_tau > 0.0 ? 1.0 / decay_tau : 0.0)) * (density / kSpinDecayReferenceDensity);
}

const char* to_string(LiftLaw l) {
  switch (l) {
    case LiftLaw::Quadratic: return "quadratic";
    case LiftLaw::Power: return "power";
    case LiftLaw::Saturating: return "saturating";
  }
  return "?";
}

bool lift_law_from_string(std::string_view name, LiftLaw* out) {
  for (const LiftLaw l : {LiftLaw::Quadratic, LiftLaw::Power, LiftLaw::Saturating}) {
    if (name == to_string(l)) {
      *out = l;
      return true;
    }
  }
  return false;
}

std::string validate_aero_model(const AeroModel& m) {
  const std::string who = "aero model '" + m.name + "': ";
  for (double c : {m.d0, m.d1, m.d2, m.d_krpm, m.l0, m.l1, m.l2, m.s_max, m.decay_per_metre, m.decay_tau,
                   m.lift_onset, m.crisis_re, m.crisis_rise, m.crisis_width, m.drag_re_slope})
    if (!std::isfinite(c)) return who + "coefficients must be finite numbers";
  if (!(m.s_max > 0.0)) return who + "s_max must be > 0";
  if (!(m.decay_per_metre >= 0.0) || !(m.decay_tau >= 0.0)) return who + "spin decay terms must be >= 0";
  if (!(m.lift_onset >= 0.0 && m.lift_onset < m.s_max)) return who + "lift_onset must be in [0, s_max)";
  if (!(m.crisis_rise >= 0.0 && m.crisis_rise <= 1.5 && m.crisis_re >= 0.0 && m.crisis_width > 0.0))
    return who + "drag crisis: re >= 0, 0 <= rise <= 1.5 (a smooth sphere's Cd rises ~0.3 below its crisis), width > 0";
  // Past the crisis Cd climbs gently (tour_fit: 0.058 per 1e5); 0.3 per 1e5 would double a
  // golf ball's Cd between a wedge's launch (Re 1.2e5) and a driver's (2.2e5), which no
  // measured ball does. A Cd that falls with Re is the crisis's job, not this term's.
  if (!(m.drag_re_slope >= 0.0 && m.drag_re_slope <= 0.3))
    return who + "drag_re_slope must be in [0, 0.3] (Cd per 1e5 of Reynolds number past the crisis)";
  if (m.drag_re_slope > 0.0 && !(m.crisis_rise > 0.0))
    return who + "drag_re_slope is measured from the drag crisis: give drag_crisis too";
  // A crisis narrower than Re 100 (0.04 m/s for a golf ball) is a step the integrator cannot
  // resolve; the measured ones span ~1e4 (Bearman & Harvey).
  if ((m.crisis_rise > 0.0 || m.drag_re_slope > 0.0) && !(m.crisis_width >= 100.0))
    return who + "drag crisis: width must be at least 100 (in Reynolds number)";
  if (m.lift == LiftLaw::Saturating && !(m.l0 > 0.0 && m.l2 >= 0.0))
    return who + "a saturating lift law needs l0 > 0 and l2 >= 0 (no pole at positive S)";
  // Spin decay faster than e-fold in 0.1 s or within 1 m of flight is no ball's (a golf
  // ball's is ~20-30 s); a hostile file's 1e-300 s makes the integrator's steps vanish.
  if (m.decay_tau > 0.0 && m.decay_tau < 0.1) return who + "decay_tau must be 0 (none) or at least 0.1 s";
  if (m.decay_per_metre > 1.0) return who + "decay_per_metre must be at most 1 per m";
  // Drag must stay positive over the fitted range, or the ball would be pushed forward; and
  // bounded: a sphere's Cd is ~0.1-0.6 and its Cl under 0.6 in any regime a ball flies in,
  // so a coefficient past 2 is a typo (a hostile drag = [1e300, ...] sends the state to inf).
  // Checked at every Reynolds number a ball meets, from rest to a 150 m/s golf ball into the
  // strongest wind aloft (~5.5e5: kMaxReynolds), through the crisis, and at no spin and at the launch
  // limit's 20 000 rpm (the Nathan drag term grows with spin): a negative d0 hides behind the
  // rise past the crisis at Re 2e5 and shows at a wedge's 1.2e5.
  const double w = m.crisis_width;
  const double res[] = {0.0, 2.5e4, 5e4, m.crisis_re - 2.0 * w, m.crisis_re, m.crisis_re + 2.0 * w,
                        1e5, 1.5e5, 2e5, 3e5, 4e5, 6e5};
  for (const double spin : {0.0, 2094.3951023931954}) {
    for (const double re : res) {
      if (!(re >= 0.0)) continue;
      for (int i = 0; i <= 50; ++i) {
        const double sp = m.s_max * i / 50.0;
        const AeroCoefficients c = m.coefficients(sp, spin, re);
        if (!(c.cd > 0.0)) return who + "Cd must be > 0 for every S in [0, s_max], Re in [0, 6e5], spin up to 20 000 rpm";
        if (!(c.cd <= 2.0) || !(std::abs(c.cl) <= 2.0))
          return who + "Cd and |Cl| must stay at most 2 for every S in [0, s_max], Re in [0, 6e5], spin up to 20 000 rpm";
      }
    }
  }
  return {};
}

AeroEffect aero_effect(const AeroModel& model, double density, double radius, const Vec3& v_rel,
                       const Vec3& omega, double viscosity) {
  // The integrator's kernel with a unit mass: its acceleration is the force.
  AeroEffect fx;
  detail::AeroKernel(model, density, radius, viscosity, 1.0).evaluate(v_rel, omega, &fx.force, &fx.spin_rate);
  return fx;
}

}  // namespace sweetspot
