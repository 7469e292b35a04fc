// Internals of step() (physics/flight.hpp): the equations of motion, root finding on dense
// output, and the three kinds of step: airborne (air_step), a touch of a surface
// (touch_surface) and rolling (roll_step). The game never includes this header.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <string>

#include "physics/detail/aero_kernel.hpp"
#include "physics/detail/integrator.hpp"
#include "physics/root_find.hpp"
#include "physics/flight.hpp"

namespace sweetspot::detail {

using State9 = Eigen::Matrix<double, 9, 1>;
using Segment = DenseSegment<9>;

/// A surface within kFollowAngle of the one the ball rolls on is followed; a steeper one
/// (wall, bank) is struck.
inline const double kFollowCos = std::cos(kFollowAngle);

/// Rolling resistance per unit weight on a surface (stimp-derived on greens).
double rolling_resistance_on(const ShotModel& m, const SurfaceMaterial& mat);

/// The surface's contact layer: a hop that never rises above it still meets what resists a
/// roll (grass blades, the turf it presses), so it is slowed as a roll is. The layer is as
/// high as the highest hop the roll threshold turns into a roll, h = roll_speed²/2g (3.2 mm
/// at 0.25 m/s): a hop just above the threshold then loses what the roll just below it
/// loses, and a shot does not jump by a hop's length (25 cm for a 5 m/s ball in a
/// random-launch sample) when a rounding turns one bounce into a roll. The share fades
/// linearly with the hop's apex, v_n²/2g at the bounce, from all of it at h to none at 2h;
/// it is fixed for the hop (ShotState::hop_layer), so the equations stay smooth and the
/// result does not depend on where the integrator's steps fall. A ball that rolls off an
/// edge is in the air: no layer. Like the roll's resistance it slows the spin with the
/// centre, so a rolling ball's hop keeps it rolling.
inline double hop_layer_share(const ShotModel& m, double vn) {
  if (m.settings.roll_speed <= 0.0) return 0.0;
  return std::clamp(2.0 - (vn * vn) / (m.settings.roll_speed * m.settings.roll_speed), 0.0, 1.0);
}

struct ContactLayer {
  bool on = false;
  Vec3 normal = Vec3::UnitY();
  double decel = 0.0;  ///< m/s², the roll's resistance (rolling resistance · g · cos slope) times the share

  static ContactLayer of(const ShotModel& m, const ShotState& s) {
    ContactLayer l;
    if (!s.landed || s.hop_layer <= 0.0) return l;
    l.on = true;
    l.normal = s.support.normal;
    l.decel = s.hop_layer * rolling_resistance_on(m, m.terrain->material(s.support.material)) * kGravity *
              std::max(l.normal.dot(up_axis()), 0.0);
    return l;
  }

  /// Acceleration on a ball moving at v: against its motion along the surface.
  Vec3 acceleration(const Vec3& v) const {
    const Vec3 vt = v - v.dot(normal) * normal;
    // Full strength above 5 cm/s (the rest speed's scale); linear below, so a ball hopping
    // straight up is not shaken by a force that flips with its tiny sideways speed.
    constexpr double kFullBelow = 0.05;  // m/s
    return (-decel / std::max(vt.norm(), kFullBelow)) * vt;
  }
};

/// dy/dt of (position, velocity, spin) under gravity, drag, Magnus lift and spin decay, and
/// the contact layer's resistance on the hops after landing.
struct Dynamics {
  const ShotModel* model;
  AeroKernel aero;
  double ground_height;
  bool still_air;
  /// The flight's wind profile until the ball lands, the surface's log law after (its hops:
  /// ground_wind_at).
  WindProfile profile;
  ContactLayer layer;

  /// `landed`: the ball has touched the ground; its hops then measure the wind's height from
  /// `hop_ground`, the height of the surface the hop left (the log law is the air over the
  /// turf the ball bounces on, not over the world's reference).
  Dynamics(const ShotModel& m, bool landed, double hop_ground, ContactLayer l = {})
      : model(&m),
        aero(*m.aero, m.air_density, m.ball.radius, m.air_viscosity, m.ball.mass, m.seam_side_force),
        ground_height(landed ? hop_ground : m.terrain->reference_height()),
        still_air(m.environment.wind_speed == 0.0),
        profile(landed ? WindProfile::Logarithmic : m.environment.wind_profile),
        layer(l) {}

  /// The ball's velocity through the air in state y.
  Vec3 air_velocity(const State9& y) const {
    const Vec3 v = y.segment<3>(3);
    // Still air needs no profile (wind_at is a call with logs or powers otherwise).
    return still_air ? v : Vec3(v - wind_at(model->environment, y[1] - ground_height, profile));
  }

  /// The spin parameter S = R|ω|/|v_r| of state y (as the aero kernel takes it).
  double spin_parameter(const State9& y) const {
    const Vec3 v_rel = air_velocity(y);
    const double speed2 = v_rel.squaredNorm();
    return speed2 > 0.0 ? model->ball.radius * std::sqrt(y.segment<3>(6).squaredNorm() / speed2) : 0.0;
  }

  State9 operator()(double /*t*/, const State9& y) const {
    const Vec3 v = y.segment<3>(3);
    const Vec3 w = y.segment<3>(6);
    const Vec3 v_rel = air_velocity(y);
    Vec3 accel, spin_rate;
    aero.evaluate(v_rel, w, &accel, &spin_rate);
    State9 d;
    d.segment<3>(0) = v;
    d.segment<3>(3) = accel - kGravity * up_axis();
    d.segment<3>(6) = spin_rate;
    if (layer.on) {
      // As on a roll, the resistance slows the spin with the centre (ω = n × v / R kept), or
      // the spin left over would drive the ball on at the next touch.
      const Vec3 a = layer.acceleration(v);
      d.segment<3>(3) += a;
      d.segment<3>(6) += layer.normal.cross(a) / model->ball.radius;
    }
    return d;
  }
};

/// The position a fraction θ in [0, 1] of the way through the step (no division by h).
inline Vec3 position_at_fraction(const Segment& s, double th) {
  const double th1 = 1.0 - th;
  return s.r1.segment<3>(0) +
         th * (s.r2.segment<3>(0) + th1 * (s.r3.segment<3>(0) + th * (s.r4.segment<3>(0) + th1 * s.r5.segment<3>(0))));
}

inline Vec3 position_at(const Segment& s, double t) {
  return Vec3(s.component(t, 0), s.component(t, 1), s.component(t, 2));
}

/// True when the time or step budget is spent.
inline bool out_of_budget(const ShotModel& m, const ShotState& s) {
  return s.t >= m.settings.max_time || s.counters.flight_steps + s.counters.roll_steps >= m.settings.max_steps;
}

inline void end_shot(ShotState& s, EndReason why) {
  s.ended = true;
  s.end = why;
}

/// First trial step after a bounce: a tenth of the hop's vacuum flight time.
inline double hop_step(const ShotState& s) {
  const double hop = 2.0 * std::max(s.y[4], 0.0) / kGravity;
  return std::clamp(1.0 * hop, 1e-3, 1.0);
}

/// One airborne step: an integrator step, cut at the first contact (which is resolved).
/// Steps shorter than kNoProgress (s) make no progress; kStalledSteps of them in a row are a
/// ball held where it is (step()) or, in free flight, equations too stiff to go on (air_step).
inline constexpr double kNoProgress = 1e-7;
inline constexpr int kStalledSteps = 64;

/// Refuses a flight the models cannot carry on (`what` happened), naming ball.mass and
/// ball.radius. Cold and out of line: its message is built only when it throws.
[[noreturn, gnu::cold, gnu::noinline]] void refuse_unrepresentable(const ShotModel& m, const std::string& what);

ShotEvent air_step(const ShotModel& m, ShotState& s, double until);
/// The ball at contact `c` (its position on the contact): land, bounce, sink or start to roll.
ShotEvent touch_surface(const ShotModel& m, ShotState& s, const SurfaceContact& c);

/// Two faces that hold the ball between them (a ditch's floor, a V between facets, a trough
/// between steep walls): both face up, they are not parallel, and their mean normal is one
/// a ball can roll on. Then the ball rolls in the crease (roll_step), moving along n1 × n2
/// only; returns false (and changes nothing) otherwise.
bool enter_crease(ShotState& s, const Vec3& n1, const Vec3& n2);
/// One rolling step (the skid to pure rolling first, when due).
ShotEvent roll_step(const ShotModel& m, ShotState& s, double until);

}  // namespace sweetspot::detail
