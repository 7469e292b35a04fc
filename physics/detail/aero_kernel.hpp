// The aero law of physics/aero.hpp in the form the integrator evaluates it: the shot's
// constants (½ρA/m, ρD/µ, 1/width, 1/onset) folded in once per step instead of once per
// evaluation, the acceleration returned instead of the force, and the square roots and
// divisions of an evaluation independent of each other so they overlap in the pipeline.
// A flight evaluates it ~130 times per shot: as the plain law, a fifth of a golf shot's time.
// The law itself lives here once; aero_effect() (physics/aero.cpp) is this kernel with a
// unit mass and no seam wake (a pitch's: ShotModel::seam_side_force).
#pragma once

#include <algorithm>
#include <cmath>

#include "physics/aero.hpp"
#include "physics/units.hpp"

namespace sweetspot::detail {

/// Cd and Cl at spin parameter `s`, total spin `spin` (rad/s), Reynolds number `re`.
/// `inv_width` = 1/crisis_width, `inv_onset` = 1/lift_onset (0 when none).
[[gnu::always_inline]] inline AeroCoefficients aero_coefficients(const AeroModel& m, double s, double spin, double re,
                                                                 double inv_width, double inv_onset) {
  const double sc = std::min(s, m.s_max);
  AeroCoefficients c;
  c.cd = m.d0 + m.d1 * sc + m.d2 * sc * sc;
  if (m.d_krpm != 0.0) c.cd += m.d_krpm * (radps_to_rpm(spin) / 1000.0);
  if (m.crisis_rise > 0.0 || m.drag_re_slope != 0.0) {
    // Above the crisis by more than kCrisisTail widths the laminar fraction 1/(1 + e^x) is
    // under e^-40 ≈ 4e-18, far below one ulp of any Cd (> 0.05): skip the exp.
    constexpr double kCrisisTail = 40.0;
    const double x = (re - m.crisis_re) * inv_width;
    const double above = (re - m.crisis_re) * 1e-5;  // Re past the crisis, in units of 1e5
    if (x < kCrisisTail) {
      // rise · laminar fraction 1/(1 + e^x) plus the supercritical rise · turbulent fraction
      // e^x/(1 + e^x), over one division: smooth through the crisis (a kink at Re_c cost the
      // step control millimetres of carry). With no slope the sum is exactly the rise.
      const double e = std::exp(std::max(x, -50.0));
      c.cd += (m.crisis_rise + m.drag_re_slope * above * e) / (1.0 + e);
    } else if (m.drag_re_slope != 0.0) {
      c.cd += m.drag_re_slope * above;
    }
  }
  switch (m.lift) {
    case LiftLaw::Quadratic: c.cl = m.l0 + m.l1 * sc + m.l2 * sc * sc; break;
    case LiftLaw::Power: c.cl = sc > 0.0 ? m.l1 * std::pow(sc, m.l2) : 0.0; break;
    case LiftLaw::Saturating: c.cl = m.l1 * sc / (m.l0 + m.l2 * sc); break;
  }
  if (m.lift_onset > 0.0 && sc < m.lift_onset) c.cl *= sc * inv_onset;
  return c;
}

struct AeroKernel {
  const AeroModel* model;
  double radius;        ///< m
  double accel_per_cd;  ///< ½ρA/m (1/m): the drag acceleration is this · Cd · |v|²
  double re_per_speed;  ///< ρD/µ (s/m)
  double inv_width;     ///< 1/crisis_width
  double inv_onset;     ///< 1/lift_onset, 0 when none
  double decay_per_metre;  ///< the model's decay_per_metre at this air's density (1/m)
  double decay_const;      ///< 1/decay_tau at this air's density (1/s), 0 when none
  double side_accel;       ///< ½ρA·C_s/m (1/m) of a seam-shifted wake (ShotModel::seam_side_force), 0 when none

  AeroKernel(const AeroModel& m, double density, double r, double viscosity, double mass, double seam_side_force = 0.0)
      : model(&m),
        radius(r),
        accel_per_cd(0.5 * density * kPi * r * r / mass),
        re_per_speed(density * 2.0 * r / viscosity),
        inv_width(1.0 / m.crisis_width),
        inv_onset(m.lift_onset > 0.0 ? 1.0 / m.lift_onset : 0.0),
        decay_per_metre(m.decay_per_metre * (density / kSpinDecayReferenceDensity)),
        decay_const(m.decay_tau > 0.0 ? (density / kSpinDecayReferenceDensity) / m.decay_tau : 0.0),
        side_accel(0.5 * density * kPi * r * r / mass * seam_side_force) {}

  /// Acceleration (m/s²) of a ball moving at `v_rel` through the air with spin `omega`
  /// (rad/s), and its spin's rate of change (rad/s²).
  [[gnu::always_inline]] inline void evaluate(const Vec3& v_rel, const Vec3& omega, Vec3* accel, Vec3* spin_rate) const {
    const AeroModel& m = *model;
    const double speed2 = v_rel.squaredNorm();
    const double speed = std::sqrt(speed2);
    *spin_rate = -(decay_per_metre * speed + decay_const) * omega;
    if (speed2 == 0.0) {  // (a NaN velocity goes on, so the integrator sees the NaN)
      *accel = Vec3::Zero();
      return;
    }
    const Vec3 lift_dir = omega.cross(v_rel);  // |ω × v_r| = |ω| |v_r| sin(ω, v_r)
    const double spin = omega.norm();
    const double inv_speed = 1.0 / speed;
    const double inv_spin = spin > 0.0 ? 1.0 / spin : 0.0;
    const double s = radius * spin * inv_speed;  // R |ω| / |v_r|
    const AeroCoefficients c = aero_coefficients(m, s, spin, speed * re_per_speed, inv_width, inv_onset);
    // Drag -½ρA·Cd·|v_r|·v_r; lift ½ρA·Cl·|v_r|²·(ω × v_r)/(|ω||v_r|); per unit mass.
    *accel = (-accel_per_cd * c.cd * speed) * v_rel + (accel_per_cd * c.cl * speed * inv_spin) * lift_dir;
    if (side_accel != 0.0) {
      // The seam-shifted wake: |v_r × (ω × v_r)| = |v_r| |ω × v_r|, so this is ½ρA·C_s·|v_r|²/m
      // along v̂_r × m̂. A ball spinning about its line of flight has no Magnus direction to
      // hold its seams' place by: none.
      const double lift_norm = lift_dir.norm();
      if (lift_norm > 0.0) *accel += (side_accel * speed / lift_norm) * v_rel.cross(lift_dir);
    }
  }
};

}  // namespace sweetspot::detail
