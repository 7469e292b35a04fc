// The grip threshold of a strike: the friction coefficient µ above which the launch stops
// changing. Below it the ball slides on the face for part of the contact and friction sets
// the spin; above it the patch sticks, the tangential impulse is what sticking needs
// (rigid model: J_t/J_n of the sticking solution; compliant model: the Mindlin spring's
// largest force ratio), and turning µ up does nothing. Tuning panels and sweeps show it so
// a flat response to µ explains itself.
#pragma once

#include <string>

#include "game/rules/run_shot.hpp"

namespace sweetspot {

/// How close a launch must come to the fully stuck (µ = ImpactMaterial::kMu.max) launch to
/// count as "no longer changing": ball speed within 0.01 m/s (0.02 mph), launch angle
/// within 0.01°, spin within 0.2 % + 1 rpm. A launch monitor resolves 0.1 mph, 0.1° and
/// ~1 % of spin, so differences inside these are invisible to any reader.
struct GripTolerance {
  double ball_speed = 0.01;        ///< m/s
  double angle = 0.01 * 0.017453292519943295;  ///< rad
  double spin_fraction = 0.002;    ///< of the spin
  double spin = 0.10471975511965977;  ///< rad/s (1 rpm)
};

/// The smallest face µ (in the units of ImpactMaterial::mu, before the lie's factor) whose
/// launch matches the fully stuck launch within `tol`, found by bisection over
/// [0, kMu.max] to 1e-4 (about 16 launches, no flight). 0 when friction does not matter
/// (a head-on strike, or the frictionless model).
double mu_grip(const ResolvedShot& shot, const GripTolerance& tol = {});

}  // namespace sweetspot
