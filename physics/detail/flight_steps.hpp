// Internals of step() (physics/flight.hpp): the equations of motion, root finding on dense
// output, and the three kinds of step: airborne (air_step), a touch of a surface
// (touch_surface) and rolling (roll_step). The game never includes this header.
#pragma once

#include <algorithm>
#include <cmath>

#include "physics/detail/integrator.hpp"
#include "physics/flight.hpp"

namespace sweetspot::detail {

using State9 = Eigen::Matrix<double, 9, 1>;
using Segment = DenseSegment<9>;

/// A surface within kFollowAngle of the one the ball rolls on is followed; a steeper one
/// (wall, bank) is struck.
inline const double kFollowCos = std::cos(kFollowAngle);

/// dy/dt of (position, velocity, spin) under gravity, drag, Magnus lift and spin decay.
struct Dynamics {
  const ShotModel* model;
  double inv_mass;
  double ground_height;

  explicit Dynamics(const ShotModel& m)
      : model(&m), inv_mass(1.0 / m.ball.mass), ground_height(m.terrain->reference_height()) {}

  State9 operator()(double /*t*/, const State9& y) const {
    const Vec3 v = y.segment<3>(3);
    const Vec3 w = y.segment<3>(6);
    const Vec3 v_rel = v - wind_at(model->environment, y[1] - ground_height);
    const AeroEffect fx = aero_effect(*model->aero, model->air_density, model->ball.radius, v_rel, w, model->air_viscosity);
    State9 d;
    d.segment<3>(0) = v;
    d.segment<3>(3) = fx.force * inv_mass - kGravity * up_axis();
    d.segment<3>(6) = fx.spin_rate;
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
  return std::clamp(0.1 * hop, 1e-3, 0.05);
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
