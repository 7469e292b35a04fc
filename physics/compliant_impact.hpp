// An impact with duration (DESIGN §3): two rigid bodies, the impactor (club head
// or bat) and the ball, pressed together through the ball's compliant contact layer for
// the ~0.4–0.7 ms the ball is on the face, integrated in time. While the ball is on the
// face the head turns and the contact point and normal move with it, so gear effect, the
// face's bulge and roll, and the speed dependence of spin come out of the mechanics rather
// than from an instantaneous impulse.
//
// The contact law, per unit of the ball's overlap δ with the impactor's surface:
//   normal      F_n = k δ^{3/2} (1 + λ δ̇)          Hertz with Hunt–Crossley damping; λ is set so
//                                                    that a head-on impact returns the normal COR
//                                                    e at the approach speed (the scaled contact is
//                                                    integrated once per e; Flores et al. 2011's
//                                                    closed form λ ≈ 8(1−e)/(5 e v) returns 0.820
//                                                    for a requested 0.830).
//   tangential  dF_t = −k_t u_t dt, |F_t| ≤ µ F_n    an elastic shear of the contact patch
//               k_t = κ · dF_n/dδ = κ · (3/2) k δ^{1/2}  (Mindlin: κ = 2(1−ν)/(2−ν), or the ball's
//               − c_t u_t, c_t = β κ λ k δ^{3/2}        measured ratio) that grips, stretches and
//                                                    slips (Coulomb), incremental as Mindlin &
//                                                    Deresiewicz's (pressing harder adds no force
//                                                    without stretch), damped like the normal law
//                                                    by the rubber's shear hysteresis β.
//                                                    Its release at separation is the measured
//                                                    tangential rebound of balls (Maw, Barber &
//                                                    Fawcett 1976; Cross 2002): the ball leaves a
//                                                    steep face over-spinning (e_t ≈ 0.3 on a
//                                                    wedge), a shallow one nearer rolling.
// β and µ are fitted once for a ball: the golf ball to TrackMan's PGA irons and woods, the
// baseball to laboratory oblique impacts on bats (balls.toml).
//
// The rigid solve_impact (physics/impact.hpp) stays for the textbook's models and is this
// model's limit: as k → ∞ with µ = 0 both give the same result (a test holds it).
#pragma once

#include <string>

#include "physics/body.hpp"
#include "physics/equipment.hpp"
#include "physics/impact.hpp"
#include "physics/math.hpp"
#include "physics/range.hpp"

namespace sweetspot {

/// The shape of the impactor near the contact, in its SURFACE frame: for a club the HEAD
/// FRAME (origin at the face centre, +x out of the face), for a bat the BAT FRAME (origin at
/// the knob, +x along the axis), for a plane its own (+x the normal).
struct ImpactSurface {
  enum class Kind { Face, Barrel, Plane };
  Kind kind = Kind::Plane;
  double bulge_radius = 1e4;   ///< m, Face: heel-toe curvature (x = -(z²/2Rb + y²/2Rr))
  double roll_radius = 1e4;    ///< m, Face: sole-crown curvature
  const BatSpec* bat = nullptr;  ///< Barrel: radius profile along +x

  /// The surface point nearest `p` (surface frame) and the unit outward normal there.
  void closest(const Vec3& p, Vec3* point, Vec3* normal) const;
};

/// What the compliant solve needs beyond the two bodies.
struct CompliantContact {
  BallCompliance ball;            ///< the ball's contact layer (balls.toml)
  ImpactMaterial material;        ///< e(v) curve (× the location factor), µ, friction model
  double cor_factor = 1.0;        ///< e multiplier at this contact (face COR map, bat's barrel profile)
  int steps_per_contact = 400;    ///< time steps over the estimated contact duration
};

struct CompliantImpactInput {
  RigidBody impactor;             ///< world frame, CG pose and velocities
  Quat surface_rotation = Quat::Identity();  ///< surface frame -> impactor body frame
  Vec3 surface_origin = Vec3::Zero();       ///< surface frame origin in the body frame (m, from the CG)
  ImpactSurface surface;
  RigidBody ball;                 ///< a sphere: inertia_body = I·1
  double ball_radius = 0.021335;  ///< m
  CompliantContact contact;
};

struct CompliantImpactResult {
  RigidBody impactor_after;       ///< at separation (pose moved, velocities changed)
  RigidBody ball_after;
  Vec3 impulse = Vec3::Zero();    ///< N·s on the ball over the contact
  double normal_impulse = 0.0;    ///< N·s along the mean normal (impulse · n̄)
  double tangential_impulse = 0.0;///< N·s, |impulse − normal part|
  double duration = 0.0;          ///< s the ball was on the face
  double max_compression = 0.0;   ///< m, largest overlap δ
  double e_used = 0.0;            ///< normal COR the damping was set for (curve × cor_factor)
  double energy_loss = 0.0;       ///< J, kinetic energy before − after (≥ 0)
  ContactKind contact = ContactKind::Grip;  ///< Grip when the patch stuck at some time, Slip when it slid throughout
  Vec3 mean_normal = Vec3::UnitX();///< unit, the impulse-weighted contact normal (world)
  Vec3 first_contact = Vec3::Zero();///< m, world, where the surfaces first touched
  int steps = 0;                  ///< time steps taken
};

/// Empty when the input is valid (finite, positive masses, the ball touching the surface
/// or within 0.1 mm and approaching), otherwise a message naming what is wrong.
std::string validate_compliant_impact(const CompliantImpactInput& in);

/// Integrates the contact from first touch to separation. Requires a valid input.
/// Deterministic. Momentum is conserved to round-off (every force acts on both bodies at
/// one point), and energy is lost, never created (the damping and the friction only dissipate).
CompliantImpactResult solve_compliant_impact(const CompliantImpactInput& in) noexcept;

}  // namespace sweetspot
