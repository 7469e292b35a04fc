// Rolling: the skid until the contact point grips, then steps along the ground under
// gravity along the slope, rolling resistance and air drag, following the terrain's facets,
// leaving it over an edge, striking walls, stopping exactly where the speed runs out.
#include <algorithm>
#include <cmath>

#include "physics/detail/flight_steps.hpp"

namespace sweetspot::detail {
namespace {

/// Ball bottom more than this above the support plane: the ground fell away, fly.
constexpr double kLeaveGap = 0.01;  // m
/// A sweep along the face a ball rolls on starts this far off it (m), so that face, which
/// the ball moves along, is not met at the start while any other is (1 µm: far below the
/// centimetre the game resolves, far above the round-off of a position ~1 km from the origin).
constexpr double kOffFace = 1e-6;

/// The still air's deceleration per v² (1/m) of a ball rolling like the Stimpmeter's
/// (1.83 m/s, spinning with the roll), along the ground: 5/7 of the drag on a free ball.
/// A putt rolls far below the drag crisis, where Cd does not change with speed, so k holds
/// for the whole putt.
double stimp_air_drag(const ShotModel& m) {
  const double v = 1.83, r = m.ball.radius;
  const Vec3 vel(v, 0.0, 0.0), spin(0.0, 0.0, -v / r);
  const double f = -aero_effect(*m.aero, m.air_density, r, vel, spin, m.air_viscosity).force.x();
  return (5.0 / 7.0) * f / (m.ball.mass * v * v);
}

/// `v` turned into the plane of normal `n`, keeping its speed: a ball rolling onto a
/// differently sloped face.
Vec3 turned_into_plane(Vec3 v, const Vec3& n) {
  const double before = v.norm();
  v -= v.dot(n) * n;
  const double after = v.norm();
  if (after > 0.0) v *= before / after;
  return v;
}

/// A ball rolling p + v·t + ½a·t² along one face's plane towards a concave bend: the first
/// time in [0, limit] its centre comes within r of the plane of `face` (where it touches
/// both faces), from g(t) = g0 + (n'·v)t + ½(n'·a)t², g0 > 0, in the form of the root that
/// keeps its precision when the quadratic term is small. Negative when the ball starts on
/// or under that plane, or does not reach it by `limit`.
double time_to_plane(const SurfaceContact& face, double r, const Vec3& p, const Vec3& v, const Vec3& a, double limit) {
  const double g0 = face.normal.dot(p - face.point) - r;
  if (!(g0 > 0.0)) return -1.0;
  const double qa = 0.5 * face.normal.dot(a), qb = face.normal.dot(v);
  const double denom = -qb + std::sqrt(std::max(qb * qb - 4.0 * qa * g0, 0.0));
  if (!(denom > 0.0)) return -1.0;
  const double t = 2.0 * g0 / denom;
  return t <= limit ? t : -1.0;
}

/// The velocity of a rolling ball whose centre was put `lift` m higher (a step's end moved
/// out of a face it ended inside, at a corner of several faces where no single bend could be
/// met first; up to a few mm): its speed pays for the height, ½·(7/5)·v² + g·h held, down to
/// rest. Lifted for free, a ball rocking in such a corner would gain ~0.02 J/kg a time.
/// Lifts under a nanometre are a step's round-off about its face's plane (every step's end
/// is put back onto its face): they keep the speed, and cost no square root.
Vec3 paid_for_lift(const Vec3& v, double lift) {
  if (!(lift > 1e-9)) return v;
  const double v2 = v.squaredNorm();
  if (v2 == 0.0) return v;
  const double left = v2 - (10.0 / 7.0) * kGravity * lift;
  return left > 0.0 ? Vec3(v * std::sqrt(left / v2)) : Vec3::Zero();
}

void set_rolling(ShotState& s, const Vec3& p, const Vec3& v, const Vec3& n, double r) {
  s.y.segment<3>(0) = p;
  s.y.segment<3>(3) = v;
  s.y.segment<3>(6) = n.cross(v) / r;
}

/// The ground under a ball that moved from p to p1 along its support's plane. Past a concave
/// edge (the plane turns up: a bank, the far side of a hollow, a slope meeting the flat) the
/// plane's extension runs into the next facet, p1 up to |p1 - p| inside it; the query starts
/// that much higher so the facet is still found above the ball's bottom (else a ball rolling
/// down a slope onto the flat starts its search under the flat and falls out of the world).
/// The gap is then measured from p1 itself by the caller.
bool ground_under(const Terrain& terrain, const Vec3& p, const Vec3& p1, double r, double reach, SurfaceContact* under) {
  const double lift = (p1 - p).norm();
  return terrain.support(p1 + lift * up_axis(), r, reach + lift, under);
}

ShotEvent go_airborne(ShotState& s, double dt, const Vec3& p1, const Vec3& v1) {
  s.t += dt;
  s.y.segment<3>(0) = p1;
  s.y.segment<3>(3) = v1;
  s.phase = Phase::Bounce;
  s.hop_layer = 0.0;  // off an edge: in the air, no contact layer
  s.step_size = hop_step(s);
  s.rate_valid = false;
  ShotEvent ev;
  ev.kind = ShotEventKind::Airborne;
  return ev;
}

/// Skid until the contact point grips: kinetic friction µ g cosθ acts against the slip of
/// the contact point, and the slope's pull acts on the centre (not on the spin), so on a
/// slope the slip turns as it shrinks. For a solid sphere the slip changes at
/// (1 + m R²/I) µ g cosθ = 3.5 µ g cosθ from friction. Integrated in steps of at most 1 ms
/// (a putt skids ~0.1 s); on the flat this is the closed form (slip falls linearly, v ends
/// at 5/7 of v0 for a ball struck without spin). The skid follows the ground like the roll:
/// at most kSkidChunk at a time on one facet, then the ground under the ball is found again
/// (else a 0.7 s skid runs on along one facet's plane beyond its edge, under the
/// neighbouring facet, and the ball falls out of the world).
constexpr double kSkidChunk = 0.02;  // s; at the fastest skid (~80 m/s) 1.6 m, a facet or two
ShotEvent skid(const ShotModel& m, ShotState& s) {
  const double r = m.ball.radius;
  const SurfaceContact& c = s.support;
  const Vec3 n = c.normal;
  Vec3 p = s.position();
  Vec3 v = s.velocity();
  Vec3 w = s.spin();
  p -= (n.dot(p - c.point) - r) * n;
  v -= v.dot(n) * n;
  const SurfaceMaterial& mat = m.terrain->material(c.material);
  const double cos_slope = std::max(n.dot(up_axis()), 0.1);
  const Vec3 pull = -kGravity * (up_axis() - n.dot(up_axis()) * n);  // along the slope
  const double k = 1.0 + m.ball.mass * r * r / m.ball.inertia;
  const double decel = mat.mu * kGravity * cos_slope;
  bool gripped = mat.mu <= 0.0;
  double elapsed = 0.0;
  for (int i = 0; i < 2000 && !gripped && elapsed < kSkidChunk; ++i) {
    const Vec3 slip = v + w.cross(-r * n);
    const double slip_speed = slip.norm();
    if (slip_speed < 1e-6) {
      gripped = true;
      break;
    }
    // Time to grip if friction alone acted; steps of ≤ 1 ms follow the slope's turning.
    const double t_grip = slip_speed / (k * decel);
    const double dt = std::min(t_grip, 1e-3);
    const Vec3 f = -decel * (slip / slip_speed);  // friction acceleration of the centre
    p += v * dt + 0.5 * (f + pull) * dt * dt;
    v += (f + pull) * dt;
    // The friction torque: ω changes by (R n × m f)/I · dt... as a contact at -R n.
    w += (m.ball.mass / m.ball.inertia) * (-r * n).cross(f) * dt;
    elapsed += dt;
    if (dt == t_grip) gripped = true;
  }
  s.t += elapsed;
  if (gripped) w = w.dot(n) * n + n.cross(v) / r;
  // Follow the ground under the new position, as a roll step does.
  SurfaceContact under = c;
  const double reach = kLeaveGap + 0.1 * v.norm() * elapsed;
  const bool found = ground_under(*m.terrain, s.position(), p, r, reach, &under);
  const bool into_face = found && under.normal.dot(n) < kFollowCos && under.normal.dot(p - under.point) - r < 0.0 &&
                         v.dot(under.normal) < 0.0;
  if (into_face && -v.dot(under.normal) < m.settings.roll_speed) {
    p -= (under.normal.dot(p - under.point) - r) * under.normal;
    s.y.segment<3>(0) = p;
    s.y.segment<3>(3) = v;
    s.y.segment<3>(6) = w;
    if (enter_crease(s, n, under.normal)) {
      // Skidded gently into a second face that carries it too: a crease, as a roll that
      // meets one gently (roll_step). Struck instead, each touch would put the ball back into
      // a skid on the face it came from, which runs it into the other again some µs later:
      // 2 850 touches down a 60° V before it stops (random-world soak).
      s.support = under;
      return ShotEvent{};
    }
  }
  if (into_face) {
    // Skidded into a face that turns up sharply (a concave edge): strike it from outside.
    p -= (under.normal.dot(p - under.point) - r) * under.normal;
    s.y.segment<3>(0) = p;
    s.y.segment<3>(3) = v;
    s.y.segment<3>(6) = w;
    s.skidding = false;
    s.phase = Phase::Bounce;
    under.fraction = 0.0;
    return touch_surface(m, s, under);
  }
  if (found && under.normal.dot(n) < kFollowCos && under.normal.dot(p - under.point) - r <= 0.0 &&
      enter_crease(s, n, under.normal)) {
    // Skidded along into a steeper face that holds it too (not into it: that is struck
    // above): a crease, rolled along as roll_step does. Flying off here would touch the first
    // face again at once, for ever (200 000 zero-time touches in the random-world soak).
    s.y.segment<3>(0) = p;
    s.y.segment<3>(3) = v;
    s.y.segment<3>(6) = w;
    return ShotEvent{};
  }
  if (!found || under.normal.dot(p - under.point) - r > kLeaveGap || under.normal.dot(n) < kFollowCos) {
    s.y.segment<3>(6) = w;
    s.skidding = false;
    // Did the chunk run into a face on the way? The far side of a V can rise more steeply
    // than the ground query's lift sees: p ends under it, nothing is found, and the ball
    // would fly on from inside the ground. Such a ball meets that face where the sweep says,
    // at the chunk's time there.
    const Vec3 p0 = s.position();
    SurfaceContact hit;
    Vec3 along = n;
    ++s.counters.sweeps;
    if (m.terrain->sweep(p0, p, r, &hit, &along)) {
      s.t -= (1.0 - hit.fraction) * elapsed;
      s.y.segment<3>(0) = p0 + hit.fraction * (p - p0);
      s.y.segment<3>(3) = v;
      s.phase = Phase::Bounce;
      hit.fraction = 0.0;
      return touch_surface(m, s, hit);
    }
    return go_airborne(s, 0.0, p, v);  // over an edge or onto a much steeper face
  }
  p -= (under.normal.dot(p - under.point) - r) * under.normal;
  if (under.normal != n) {
    const double speed = v.norm();
    v -= v.dot(under.normal) * under.normal;
    if (v.norm() > 0.0) v *= speed / v.norm();
  }
  s.support = under;
  s.y.segment<3>(0) = p;
  s.y.segment<3>(3) = v;
  s.y.segment<3>(6) = w;
  s.skidding = !gripped;
  ShotEvent ev;
  if (!m.terrain->inside(p)) {
    end_shot(s, EndReason::LeftWorld);
    ev.kind = ShotEventKind::LeftWorld;
  }
  return ev;
}

/// Counts a roll from the face `from` onto `to` at velocity `v`: true once the ball has gone
/// back and forth between the same two faces kValleyCrossings times in a row (it is then
/// held in the valley between them; the caller may put it in their crease). Back means onto
/// the face it came from and against its last crossing's direction across the two faces'
/// bend: a ball rolling straight on over a run of facets whose normals alternate between
/// two (a terrain grid's cells, each split by a diagonal) meets the same pair of faces again
/// and again but always going the same way, and rolls on: held in a crease it would keep
/// only its speed along the bend's line, ~0 where the line runs across its path.
bool count_valley_crossing(ShotState& s, const Vec3& from, const Vec3& to, const Vec3& v) {
  constexpr int kValleyCrossings = 4;
  const Vec3 across = to - from;
  const bool reversed = v.dot(across) * s.last_cross_velocity.dot(across) < 0.0;
  const bool back = s.last_touch_normal != Vec3::Zero() && (to - s.last_touch_normal).norm() < 1e-9 && reversed;
  s.chatter = back ? s.chatter + 1 : 1;
  s.last_touch_normal = from;
  s.last_cross_velocity = v;
  return s.chatter >= kValleyCrossings;
}

/// The end of a roll or crease step at p1 on `under`: out of the world's box, at rest where
/// the step stopped, or rolling on.
ShotEvent end_of_roll_step(const Terrain& terrain, ShotState& s, const Vec3& p1, bool stops, const SurfaceContact& under) {
  ShotEvent ev;
  if (!terrain.inside(p1)) {
    end_shot(s, EndReason::LeftWorld);
    ev.kind = ShotEventKind::LeftWorld;
    return ev;
  }
  if (stops) {
    s.y.segment<6>(3).setZero();
    s.phase = Phase::Rest;
    end_shot(s, EndReason::Rest);
    ev.kind = ShotEventKind::Rest;
    ev.contact = under;
  }
  return ev;
}

/// One step along a crease (see enter_crease): the ball moves along d = n1 × n2 only; the
/// velocity into either face is taken by the two contacts, the slope of the crease line
/// pulls it (5/7 of gravity's component, a rolling sphere), rolling resistance holds it with
/// the weight the two faces carry together (their mean normal). It leaves the crease when
/// the ground under it is no longer one of the two faces (the crease ended: plain rolling
/// again, or a fall over an edge), and rests where the crease's slope cannot move it.
ShotEvent crease_step(const ShotModel& m, ShotState& s, double until) {
  ShotEvent ev;
  const Terrain& terrain = *m.terrain;
  const double r = m.ball.radius;
  const Vec3 n1 = s.crease_n1, n2 = s.crease_n2;
  const Vec3 d = n1.cross(n2).normalized();
  const Vec3 nc = (n1 + n2).normalized();
  const double g_along = -(5.0 / 7.0) * kGravity * up_axis().dot(d);
  const double resist = rolling_resistance_on(m, terrain.material(s.support.material)) * kGravity *
                        std::max(nc.dot(up_axis()), 0.0);
  const Vec3 p = s.position();
  double u = s.velocity().dot(d);
  const double limit = std::min(m.settings.max_time, until) - s.t;
  const double dt = std::min(std::clamp(0.25 / std::max(std::abs(u), 1e-3), 1.0 / 240.0, 0.1), limit);
  const double dir = u != 0.0 ? (u > 0.0 ? 1.0 : -1.0) : (g_along > 0.0 ? 1.0 : -1.0);
  const double a = g_along - resist * dir;
  double step = dt;
  bool stops = false;
  if (std::abs(g_along) <= resist && (std::abs(u) < m.settings.rest_speed || (u + a * dt) * u <= 0.0)) {
    step = std::abs(u) > 0.0 && a != 0.0 ? std::min(std::abs(u / a), dt) : 0.0;
    stops = true;
  }
  // Turns back inside the step (up a crease line that will carry it down again): the step
  // ends where it turns, as a roll step's does. Held against the first direction for the
  // whole step, the resistance would drive the ball back down the line instead of braking
  // it: up to 0.06 J/kg gained a turn, rocking a ball along a crease (random-world soak).
  const bool turns = !stops && u != 0.0 && (u + a * dt) * u < 0.0;
  if (turns) step = std::abs(u / a);
  const Vec3 p1 = p + d * (u * step + 0.5 * a * step * step);
  const double u1 = stops || turns ? 0.0 : u + a * step;
  const Vec3 v1 = u1 * d;
  const auto leave_crease = [&] { s.crease_n1 = s.crease_n2 = Vec3::Zero(); };
  // A wall across the crease: strike it.
  // Swept from just off both faces (nc leans away from each), so the two faces it rests on are
  // not met at the start and a wall across the crease is.
  SurfaceContact hit;
  const Vec3 off = 1e-5 * nc;
  bool swept = false, met = false;  // the sweep below, done at most once a step
  const auto met_on_way = [&] {
    if (!swept) {
      swept = true;
      ++s.counters.sweeps;
      met = terrain.sweep(p + off, p1 + off, r, &hit, nullptr) && (hit.normal - n1).norm() > 1e-6 &&
            (hit.normal - n2).norm() > 1e-6;
    }
    return met;
  };
  const auto strike = [&] {
    leave_crease();
    s.t += hit.fraction * step;
    set_rolling(s, p + hit.fraction * (p1 - p), u * d, nc, r);
    s.phase = Phase::Bounce;
    return touch_surface(m, s, hit);
  };
  if (!stops && terrain.may_touch_steep(p, p1, r) && met_on_way()) return strike();
  SurfaceContact under = s.support;
  if (!ground_under(terrain, p, p1, r, kLeaveGap + 0.1 * std::abs(u) * step + r, &under)) {
    // As in the skid: a face met on the way (p1 under it, so the query saw nothing).
    if (met_on_way()) return strike();
    leave_crease();
    return go_airborne(s, step, p1, v1);
  }
  const bool same_face = (under.normal - n1).norm() < 1e-6 || (under.normal - n2).norm() < 1e-6;
  s.t += step;
  s.y.segment<3>(0) = p1;
  s.y.segment<3>(3) = v1;
  s.y.segment<3>(6) = nc.cross(v1) / r;
  if (!same_face) {
    // The crease ended: roll (or fly) on from the face now under the ball.
    leave_crease();
    const double gap = under.normal.dot(p1 - under.point) - r;
    if (gap > kLeaveGap) return go_airborne(s, 0.0, p1, v1);
    s.support = under;
    // Onto a face that rises ahead (gap < 0): from where the ball meets its plane, as a roll
    // step does at a concave bend. Lifted onto it at the step's end with the speed it had
    // gained below it, a ball would gain ~0.6 mm of height each time it ran out of a crease,
    // and run back into the crease, out and in again to the time limit (random-world soak).
    const double t_bend = gap < 0.0 ? time_to_plane(under, r, p, u * d, a * d, step) : -1.0;
    if (t_bend >= 0.0) {
      s.t -= step - t_bend;
      const Vec3 vb = (u + a * t_bend) * d;
      set_rolling(s, p + d * (u * t_bend + 0.5 * a * t_bend * t_bend), vb - vb.dot(under.normal) * under.normal,
                  under.normal, r);
      return ev;
    }
    if (gap < 0.0 && met_on_way()) return strike();  // other ground between (as in roll_step)
    const Vec3 v_on = paid_for_lift(v1, -gap * under.normal.dot(up_axis()));
    set_rolling(s, p1 - gap * under.normal, v_on - v_on.dot(under.normal) * under.normal, under.normal, r);
    return ev;
  }
  s.support = under;
  return end_of_roll_step(terrain, s, p1, stops, under);
}

}  // namespace

double rolling_resistance_on(const ShotModel& m, const SurfaceMaterial& mat) {
  const double stimp = mat.kind == SurfaceKind::Green && m.settings.green_stimp > 0.0 ? m.settings.green_stimp : mat.stimp;
  return stimp > 0.0 ? rolling_resistance_from_stimp(stimp, stimp_air_drag(m)) : mat.rolling_resistance;
}

ShotEvent roll_step(const ShotModel& m, ShotState& s, double until) {
  ShotEvent ev;
  if (out_of_budget(m, s)) {
    end_shot(s, EndReason::StepLimit);
    ev.kind = ShotEventKind::StepLimit;
    return ev;
  }
  ++s.counters.roll_steps;
  if (s.skidding) return skid(m, s);
  if (s.crease_n1 != Vec3::Zero()) return crease_step(m, s, until);
  const Terrain& terrain = *m.terrain;
  const double r = m.ball.radius;
  const SurfaceContact c = s.support;
  const Vec3 n = c.normal;
  const SurfaceMaterial& mat = terrain.material(c.material);
  const Vec3 p = s.position();
  const Vec3 v = s.velocity();

  const double cos_t = n.dot(up_axis());
  const Vec3 slope_acc = (5.0 / 7.0) * -kGravity * (up_axis() - cos_t * n);  // rolling sphere
  const double resist = rolling_resistance_on(m, mat) * kGravity * cos_t;
  const double speed = v.norm();
  const bool holds = slope_acc.norm() <= resist;  // static: the slope cannot start it
  if (speed == 0.0 && holds) {
    s.y.segment<3>(6).setZero();
    s.phase = Phase::Rest;
    end_shot(s, EndReason::Rest);
    ev.kind = ShotEventKind::Rest;
    ev.contact = c;
    return ev;
  }
  const Vec3 dir = speed > 0.0 ? Vec3(v / speed) : Vec3(slope_acc.normalized());
  // Air drag matters on a fast roll (a ball skidding out at 80 m/s loses more to the air
  // than to the turf); its part along the surface acts through the centre, so a rolling
  // sphere feels 5/7 of it. Lift on the topspin only presses into the ground. The wind is
  // the grass's (ground_wind_at), not the flight's profile.
  const Vec3 wind = ground_wind_at(m.environment, r);
  // The drag at the step's start, as c·|v_r|·v_r along the face (c from the aero model:
  // ½ρA·Cd, with Cd at this speed and spin).
  double drag_c = 0.0;
  if (speed > 0.0) {
    const Vec3 v_rel = v - wind;
    const Vec3 f = aero_effect(*m.aero, m.air_density, r, v_rel, n.cross(v) / r, m.air_viscosity).force;
    const double rel2 = v_rel.squaredNorm();
    if (rel2 > 0.0) drag_c = -f.dot(v_rel) / (rel2 * std::sqrt(rel2));
  }
  // Acceleration along the face of a ball rolling at u in direction u_dir: slope, drag and
  // the turf's resistance against the motion.
  const auto accel_at = [&](const Vec3& u, const Vec3& u_dir) {
    const Vec3 u_rel = u - wind;
    const Vec3 drag = (-drag_c * u_rel.norm()) * u_rel;
    return Vec3(slope_acc + (5.0 / 7.0) / m.ball.mass * (drag - drag.dot(n) * n) - resist * u_dir);
  };
  const double limit = std::min(m.settings.max_time, until) - s.t;
  // At most 0.5 m and 0.25 s a step: with the middle's acceleration below, a roll in such steps
  // rests within 1.2 mm (median) and 6.4 mm (95th percentile) of one in steps
  // a twentieth as long, 3 000 random golf launches on golf_hole, worst 4.4 cm.
  constexpr double kStepLength = 0.5, kStepTime = 0.25;  // m, s
  double dt = std::min(std::clamp(kStepLength / std::max(speed, 1e-3), 1.0 / 240.0, kStepTime), limit);
  Vec3 a = accel_at(v, dir);
  // A ball the slope moves that the step would turn more than its own speed (starting from
  // near rest, or slow across a slope): no direction holds over such a step for the turf's
  // resistance, and a resistance held along a direction the motion left pushes the ball on
  // (random-world soak: a ball at 4 mm/s on a 14° slope gains 0.03 J/kg in one 0.25 s
  // step). The step lasts the time the slope takes to change the velocity by its
  // speed; from near rest that time doubles each step, 6 steps to the 0.25 s of a full one.
  if (!holds && a.squaredNorm() * dt * dt > speed * speed) dt = std::min(dt, std::max(speed / a.norm(), 1.0 / 240.0));
  // The step's motion: constant acceleration along the face, the one at the step's middle
  // (the midpoint rule, second order in the step; the drag there scaled from the start's
  // with |v_r|², Cd held: a rolling ball's S stays at 1, and over a 0.5 m step its Re, and
  // with it Cd through the crisis or the rise past it, barely moves).
  // The acceleration at the step's start (first order) would leave the drag's fall with
  // speed to the step length: in steps of 0.25 m and 0.1 s, against a roll in steps a tenth
  // as long, the rests of 3 000 random golf launches on golf_hole are 3.3 mm off at the
  // median and 25 mm at the 95th percentile (707 over 1 cm); at the middle, 0.4 mm and
  // 2.8 mm (12 over 1 cm).
  // A ball that loses half its speed by the middle is about to stop (the stop below is
  // exact) and slow enough that drag no longer matters: there the middle's direction would
  // be the slope's and round-off's, not the motion's, so the start's acceleration is kept.
  if (speed > 0.0) {
    const Vec3 vm = v + 0.5 * dt * a;
    if (vm.dot(v) >= 0.5 * speed * speed) a = accel_at(vm, vm.normalized());
  }
  const auto position_after = [&](double t) { return p + v * t + 0.5 * a * t * t; };
  Vec3 v1 = v + a * dt;
  Vec3 p1 = p + 0.5 * (v + v1) * dt;
  double step_t = dt;
  bool stops = false;
  const double along = -a.dot(dir);  // deceleration along the motion
  if (holds && speed > 0.0 && along > 0.0 && (v1.dot(v) <= 0.0 || speed < m.settings.rest_speed)) {
    // Comes to rest inside the step: advance exactly to the stop.
    step_t = speed / along;
    p1 = position_after(step_t);
    v1 = Vec3::Zero();
    stops = true;
  } else if (!holds && speed > 0.0 && along > 0.0 && speed / along < dt) {
    // Turns back inside the step (rolling up a slope that will carry it down again): the
    // step ends where its motion along `dir` stops. Held against the first direction for the
    // whole step, the turf's resistance would drive the ball down the slope on the way back
    // instead of braking it: with 0.25 s steps a ball rocking across a V's floor keeps its
    // amplitude for 300 bounces (random-world soak).
    step_t = speed / along;
    p1 = position_after(step_t);
    v1 = v + a * step_t;
  }
  // The hole: the ball drops, lips out, or meets the flagstick.
  if (m.cup) {
    const Vec3 up = n;
    const auto flat_dist = [&](const Vec3& q) {
      const Vec3 d = q - m.cup->centre;
      return (d - d.dot(up) * up).norm();
    };
    if (s.over_cup && flat_dist(p) > m.cup->radius + r) s.over_cup = false;
    const bool near_cup = !s.over_cup && flat_dist(p) < 2.0 * (m.cup->radius + speed * step_t + r);
    bool at_rim = false;
    if (near_cup) {
      // A step that reaches the hole's rim ends there, so the hole judges the speed the ball
      // arrives with, not the speed it had up to 0.5 m before (at a putt's 0.6 m/s² that is up
      // to 0.15 m/s fast: a 1.2 m/s putt would ride over a 1.31 m/s capture). Along the chord
      // ĉ the step's motion is (v·ĉ)t + ½(a·ĉ)t² (the rim within 1 mm is taken as reached).
      const double enter = cup_entry(*m.cup, p, p1, up);
      const double chord = (p1 - p).norm();
      if (enter < 1.0 && enter * chord > 1e-3) {
        const Vec3 dir_c = (p1 - p) / chord;
        const double u = v.dot(dir_c), ac = a.dot(dir_c), dist = enter * chord;
        const double disc = std::max(u * u + 2.0 * ac * dist, 0.0);
        const double t_rim = 2.0 * dist / (u + std::sqrt(disc));
        if (t_rim > 0.0 && t_rim < step_t) {
          step_t = t_rim;
          p1 = position_after(t_rim);
          v1 = v + a * t_rim;
          stops = false;
          at_rim = true;
        }
      }
    }
    if (near_cup && !at_rim) {
      const CupPass pass = pass_over_cup(*m.cup, r, p, p1, v, up);
      if (pass.kind != CupPass::Kind::Miss) {
        const double f = pass.fraction;
        s.t += f * step_t + pass.time_on_rim;
        if (pass.kind == CupPass::Kind::Holed) {
          s.y.segment<3>(0) = m.cup->centre - (m.cup->depth - r) * up;
          s.y.segment<6>(3).setZero();
          s.phase = Phase::Rest;
          end_shot(s, EndReason::InCup);
          ev.kind = ShotEventKind::InCup;
          ev.contact = c;
          return ev;
        }
        set_rolling(s, p + f * (p1 - p) + pass.leave_offset, pass.velocity, n, r);
        s.over_cup = true;
        ev.kind = ShotEventKind::LipOut;
        ev.contact = c;
        return ev;
      }
    }
  }
  // Walls and banks in the way: a rolling ball that strikes one bounces off it into the air.
  SurfaceContact hit;
  // A face met on the way (p -> p1): a crease when it carries the ball too, else a bounce.
  const auto strike = [&](const SurfaceContact& met) {
    const double f = met.fraction;
    const Vec3 at = p + f * (p1 - p);
    // The velocity where the ball meets the face: the step's, interpolated along the chord,
    // with the speed the step's constant acceleration gives at that point, |v|² + 2a·(at − p).
    // The chord's fraction is not the step's time's, and the interpolated velocity alone runs
    // ahead of the ball's energy on a step that speeds up (random-world soak: up to 0.07 J/kg
    // gained on meeting a face, rocking a ball in a hollow).
    Vec3 vf = v + f * (v1 - v);
    const double vf2 = vf.squaredNorm();
    if (vf2 > 0.0) vf *= std::sqrt(std::max(v.squaredNorm() + 2.0 * a.dot(at - p), 0.0) / vf2);
    if (met.normal.dot(n) >= kFollowCos) {
      // A gentle concave bend (a slope meeting the flat, the far side of a hollow): roll on
      // onto the new face from where the ball meets it, keeping its speed.
      const Vec3 vb = turned_into_plane(vf, met.normal);
      s.t += f * step_t;
      // Back and forth across the same bend, as across an edge or a seam below: the floor of
      // a valley between the two faces, each sending the ball back onto the other (uncounted
      // at the seam, a ball in the random-world soak rocks for 35 s to the step limit).
      if (count_valley_crossing(s, n, met.normal, vf) && enter_crease(s, n, met.normal)) {
        s.support = met;
        set_rolling(s, at, vb, met.normal, r);
        return crease_step(m, s, until);
      }
      s.support = met;
      set_rolling(s, at, vb, met.normal, r);
      ShotEvent bend;
      bend.contact = met;
      return bend;
    }
    if (-vf.dot(met.normal) < m.settings.roll_speed && enter_crease(s, n, met.normal)) {
      // Rolled gently into a second face that also carries it: a crease (no bounce).
      s.t += f * step_t;
      set_rolling(s, at, vf, n, r);
      return crease_step(m, s, until);
    }
    s.t += f * step_t;
    set_rolling(s, at, vf, n, r);
    s.phase = Phase::Bounce;
    ShotEvent touched = touch_surface(m, s, met);
    if (!s.ended) {
      s.phase = Phase::Bounce;
      s.skidding = false;
    }
    return touched;
  };
  // A face met on the way p -> p1 (other than the one rolled on): swept at most once a step.
  bool swept = false, met = false;
  const auto met_on_way = [&] {
    if (!swept) {
      swept = true;
      ++s.counters.sweeps;
      met = terrain.sweep(p, p1, r, &hit, &n);
    }
    return met;
  };
  // Any face met on the way p -> p1, gentle ones too (met_on_way passes over faces the ball
  // could roll onto): swept from just off the face rolled on, which the ball moves along.
  const auto first_face_on_way = [&](SurfaceContact* first) {
    ++s.counters.sweeps;
    return terrain.sweep(p + kOffFace * n, p1 + kOffFace * n, r, first, nullptr);
  };
  if (terrain.may_touch_steep(p, p1, r) && met_on_way()) return strike(hit);
  // Follow the ground under the new position.
  SurfaceContact under = c;  // the current support is the cache hint
  // Leaving the ground: first make sure the step did not run into a face on the way (a V
  // whose far side rises more steeply than the step's lift can see: p1 ends under it, the
  // ground query from there finds nothing, and the ball would fly on from inside the
  // ground, out of the world).
  const auto leave = [&]() { return met_on_way() ? strike(hit) : go_airborne(s, step_t, p1, v1); };
  if (!ground_under(terrain, p, p1, r, kLeaveGap + 0.1 * speed * step_t, &under)) return leave();
  const double gap = under.normal.dot(p1 - under.point) - r;
  if (under.normal.dot(n) < kFollowCos && gap < 0.0) {
    // The ground turned up sharply ahead (a concave edge: the far wall of a hollow, a bank
    // not steep enough to count as a wall) and p1 is inside it: meet it where the ball
    // first touches it instead of flying on from inside it.
    if (met_on_way()) return strike(hit);
    // No first touch on the way: the ball began the step already against that face (at the
    // crease between the faces, within a rounding of it). It meets the face where the step
    // began; flying on from p1, inside the ground, would let it fall through the world (a
    // ball rolling down into a V-shaped ditch).
    under.fraction = 0.0;
    return strike(under);
  }
  // The ground fell away (or turned sharply): the ball leaves it and flies. Fell away means
  // more than a free ball would have fallen from the old face's plane over the step,
  // ½·g·cosθ·t²: past a gentle convex edge the ground drops v·t·sinα, which a ball outruns
  // only for 2v·sinα/g (a hop of v²sin²α/2g: 4 mm at 5.6 m/s over 3°). A fixed 1 cm would
  // make leaving depend on the step's length (a 0.5 m step takes off over a 3° edge where
  // steps a twentieth as long roll on: 82 cm further at rest).
  const double fall = 0.5 * kGravity * std::max(cos_t, 0.0) * step_t * step_t;
  if (gap > std::max(kLeaveGap, fall) || under.normal.dot(n) < kFollowCos) return leave();
  // Onto another material (a fairway's edge into the rough, the fringe onto the green, the
  // edge of a pond): the step would run on with the old one's resistance past the seam, up
  // to its whole length (up to 50 cm), so where the seam falls inside a step would move the
  // rest by centimetres (3.6 cm against the 1e-13 reference in a random-launch sample). The
  // step ends at the seam instead, under the constant acceleration it was taken with (also
  // a step that stops: the motion holds up to the stop), and the next starts there on the
  // new material. The seam is found by bisection on the ground's material along the way (the
  // faces of two materials need not share an edge: one may overlap the other): 9 halvings
  // of a step of at most 50 cm place it within about 1 mm. Only a step that changes
  // material pays for it (about one in a shot).
  if (under.material != c.material) {
    double lo = 0.0, hi = step_t;
    SurfaceContact at = under;  // the ground the halvings last found on the new side
    for (int i = 0; i < 9; ++i) {
      const double mid = 0.5 * (lo + hi);
      const Vec3 pm = position_after(mid);
      SurfaceContact probe = c;  // the old support is the cache hint
      const bool found = ground_under(terrain, p, pm, r, kLeaveGap + 0.1 * speed * mid, &probe);
      if (found && probe.material == c.material) {
        lo = mid;
      } else {
        hi = mid;
        if (found) at = probe;
      }
    }
    // (A query again at hi with another hint can answer the other of two overlapping faces:
    // the halvings' own answer is kept.) On the new material, gently turned, within reach:
    Vec3 pm = position_after(hi);
    if (hi < step_t && at.material != c.material && at.normal.dot(n) >= kFollowCos) {
      const double gm = at.normal.dot(pm - at.point) - r;
      if (gm <= kLeaveGap) {
        // Onto the new face, as a step's end is; across a concave bend (gm < 0) where the
        // ball meets the new face's plane, before the seam: lifted onto it at the seam with
        // the speed it had gained below it, a ball rocking in a hollow of two materials would
        // gain ~g·1 mm a crossing, as much as its motion at 0.1 m/s, and never come to rest
        // (random-world soak).
        const double t_bend = gm < 0.0 ? time_to_plane(at, r, p, v, a, hi) : -1.0;
        double lift = 0.0;
        if (t_bend >= 0.0) {
          hi = t_bend;
          pm = position_after(hi);
        } else {
          // Other ground between the ball and the seam (as below) is met first. Only between:
          // a face the ball would meet past the seam is not in its way, it turns onto the new
          // material here first. Two faces across a seam that are coplanar up to round-off
          // leave the ball nanometres under the new one's plane; the sweep from just off the
          // face then meets that same face centimetres past the seam, and a step ended there
          // would run on the old material's resistance (a roll from the fairway across a
          // corner of rough would rest 2 cm from the 1e-13 reference).
          SurfaceContact first;
          const Vec3 chord = p1 - p;
          const double seam_fraction = (pm - p).dot(chord) / chord.squaredNorm();
          if (gm < 0.0 && first_face_on_way(&first) && first.fraction < seam_fraction) return strike(first);
          lift = -gm * at.normal.dot(up_axis());
          pm -= gm * at.normal;
        }
        const Vec3 vm = turned_into_plane(paid_for_lift(v + a * hi, lift), at.normal);
        s.support = at;
        s.t += hi;
        set_rolling(s, pm, vm, at.normal, r);
        // Back and forth across a seam that is also the edge of a valley (both faces of
        // another material): held there as at any valley's edge below (uncounted, a ball in
        // the random-world soak takes every crossing here for 35 s to the step limit).
        if (at.normal != n && count_valley_crossing(s, n, at.normal, v + a * hi) && (v + a * hi).dot(at.normal) < 0.0 &&
            enter_crease(s, n, at.normal)) {
          return crease_step(m, s, until);
        }
        // Rolled into water: it sinks where it enters.
        return end_of_roll_step(terrain, s, pm, terrain.material(at.material).kind == SurfaceKind::Water, at);
      }
    }
  }
  if (under.normal != n && gap < 0.0) {
    // A concave bend inside the step (a bowl's facets rise ahead of the ball). Run on along
    // its start's plane, below the next facet's, and put back onto the ground at its end, the
    // ball would rise by the gap with the speed it had gained along the lower plane, and
    // every step up a faceted curve would gain that potential energy (in the random-world
    // soak a ball in a faceted bowl rocks at ~2 m/s to the shot's 300 s). The step ends where
    // the ball meets the next facet's plane instead, as a sweep ends it at a steeper bend,
    // and turns into it there.
    const double t_bend = time_to_plane(under, r, p, v, a, step_t);
    if (t_bend >= 0.0) {
      const Vec3 at = position_after(t_bend);
      const Vec3 vb = v + a * t_bend;
      s.t += t_bend;
      s.support = under;
      set_rolling(s, at, turned_into_plane(vb, under.normal), under.normal, r);
      if (count_valley_crossing(s, n, under.normal, vb) && vb.dot(under.normal) < 0.0 && enter_crease(s, n, under.normal))
        return crease_step(m, s, until);
      return end_of_roll_step(terrain, s, at, false, under);
    }
    // The ball starts under that face's plane already: other ground lies between (the face
    // is not the next one along). The first face the ball meets on the way ends the step, as
    // a wall does.
    SurfaceContact first;
    if (first_face_on_way(&first)) return strike(first);
  }
  v1 = paid_for_lift(v1, -gap * under.normal.dot(up_axis()));
  p1 -= gap * under.normal;
  if (under.normal != n) {
    // Rolling back and forth across the same edge between two faces: a valley whose faces
    // are each too steep to hold the ball but gentle enough to roll on (left alone it creeps
    // along the valley for a minute to the time limit). Held by both, it rolls along
    // their crease line instead, and rests where that line is flat enough.
    if (count_valley_crossing(s, n, under.normal, v1) && v1.dot(under.normal) < 0.0 && enter_crease(s, n, under.normal)) {
      s.t += step_t;
      s.support = under;
      set_rolling(s, p1, v1 - v1.dot(under.normal) * under.normal, under.normal, r);
      return crease_step(m, s, until);
    }
    // Onto a differently sloped facet: turn the velocity into its plane, keeping speed.
    v1 = turned_into_plane(v1, under.normal);
  }
  s.support = under;
  s.t += step_t;
  set_rolling(s, p1, v1, under.normal, r);
  const SurfaceMaterial& now = terrain.material(under.material);
  if (now.kind == SurfaceKind::Water) stops = true;  // rolled into water: it sinks there
  return end_of_roll_step(terrain, s, p1, stops, under);
}

}  // namespace sweetspot::detail
