// Internals of step() (physics/flight.hpp): the equations of motion, root finding on dense
// output, and the three kinds of step: airborne (air_step), a touch of a surface
// (touch_surface) and rolling (roll_step). The game never includes this header.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "physics/detail/aero_kernel.hpp"
#include "physics/detail/integrator.hpp"
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
/// loses, and a shot no longer jumps by a hop's length (25 cm for a 5 m/s ball, issue 22's
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
  ContactLayer layer;

  explicit Dynamics(const ShotModel& m, ContactLayer l = {})
      : model(&m),
        aero(*m.aero, m.air_density, m.ball.radius, m.air_viscosity, m.ball.mass),
        ground_height(m.terrain->reference_height()),
        still_air(m.environment.wind_speed == 0.0),
        layer(l) {}

  State9 operator()(double /*t*/, const State9& y) const {
    const Vec3 v = y.segment<3>(3);
    const Vec3 w = y.segment<3>(6);
    // Still air needs no profile (wind_at is a call with logs or powers otherwise).
    const Vec3 v_rel = still_air ? v : Vec3(v - wind_at(model->environment, y[1] - ground_height));
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

/// Root of g on [a, b] with g(a) > 0 >= g(b): Illinois-modified regula falsi, which keeps
/// the bracket and converges superlinearly. Returns a time where |g| < 1e-12 or the bracket
/// is below 1e-13 s.
template <class G>
double find_root(const G& g, double a, double b, double ga, double gb) {
  int side = 0;
  for (int i = 0; i < 80; ++i) {
    double c = (a * gb - b * ga) / (gb - ga);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double gc = g(c);
    if (std::abs(gc) < 1e-12) return c;
    if (gc > 0.0) {
      a = c;
      ga = gc;
      if (side == 1) gb *= 0.5;
      side = 1;
    } else {
      b = c;
      gb = gc;
      if (side == -1) ga *= 0.5;
      side = -1;
    }
    if (b - a < 1e-13) break;
  }
  return b;
}

/// Root of g on [a, b] with g(a) > 0 >= g(b), from the guess x0, for a g whose derivative
/// is at hand: gd(t) returns {g(t), g'(t)}. Newton steps, each kept inside the shrinking
/// bracket (a bisection where one would leave it): two or three evaluations from a good
/// guess where regula falsi takes eight. Same stopping rule as find_root.
template <class GD>
double find_root_newton(const GD& gd, double a, double b, double x0) {
  double x = (x0 > a && x0 < b) ? x0 : 0.5 * (a + b);
  for (int i = 0; i < 80; ++i) {
    const auto [g, dg] = gd(x);
    if (std::abs(g) < 1e-12) return x;
    (g > 0.0 ? a : b) = x;
    if (b - a < 1e-13) break;
    double next = x - g / dg;
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    x = next;
  }
  return b;
}

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
