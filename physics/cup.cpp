#include "physics/cup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sweetspot {
namespace {

/// Rolling on the rim: the ball's kinetic energy is 7/10 m v² (a solid sphere rolling without
/// slip, I = 2/5 m r²), so along the rim gravity accelerates it by 5/7 of its share of g.
constexpr double kRollingGravity = 5.0 / 7.0;
/// The rim ride's time step (s) and the longest ride followed (s): a ball still circling
/// after that has lost its speed to the turf and drops.
constexpr double kRideStep = 2.0e-5;
constexpr double kRideLongest = 1.0;

/// The ball's centre in the rim's frame: ψ its tilt over the rim edge toward the hole
/// (0: straight above the edge; π/2: level with it, against the hole's wall), φ its angle
/// around the hole's axis.
struct RimState {
  double psi = 0.0, psi_dot = 0.0, phi = 0.0;
};

}  // namespace

double cup_capture_speed(const Cup& cup, double ball_radius, double offset) {
  const double b = std::abs(offset);
  if (b >= cup.radius) return 0.0;
  const double chord = 2.0 * std::sqrt(cup.radius * cup.radius - b * b);
  return std::max(0.0, (chord - ball_radius) * std::sqrt(kGravity / (2.0 * ball_radius)));
}

namespace {

/// The centre's straight path from→to seen in the green's plane at the hole (`up` its normal):
/// its closest approach to the hole's axis and where it crosses the hole's circle.
struct CupChord {
  Vec3 a = Vec3::Zero();        ///< from, relative to the axis, in the plane
  Vec3 d = Vec3::Zero();        ///< the path's step in the plane
  double len2 = 0.0;            ///< |d|²
  double s = 0.0;               ///< closest approach, a fraction of the way
  Vec3 closest = Vec3::Zero();  ///< a + s·d
  double offset = 0.0;          ///< |closest|, m
  double half = 0.0;            ///< half the crossing of the circle, a fraction of the way
  bool crosses = false;         ///< the line meets the circle (offset < radius)
};

CupChord cup_chord(const Cup& cup, const Vec3& from, const Vec3& to, const Vec3& up) {
  CupChord c;
  const auto flat = [&](const Vec3& p) { Vec3 d = p - cup.centre; return Vec3(d - d.dot(up) * up); };
  c.a = flat(from);
  c.d = flat(to) - c.a;
  c.len2 = c.d.squaredNorm();
  if (c.len2 <= 0.0) return c;
  c.s = -c.a.dot(c.d) / c.len2;
  c.closest = c.a + c.s * c.d;
  c.offset = c.closest.norm();
  if (c.offset >= cup.radius) return c;
  c.half = std::sqrt(cup.radius * cup.radius - c.offset * c.offset) / std::sqrt(c.len2);
  c.crosses = true;
  return c;
}

}  // namespace

double cup_entry(const Cup& cup, const Vec3& from, const Vec3& to, const Vec3& up) {
  const CupChord c = cup_chord(cup, from, to, up);
  if (!c.crosses || c.s + c.half < 0.0) return std::numeric_limits<double>::infinity();
  return c.s - c.half;
}

CupPass pass_over_cup(const Cup& cup, double ball_radius, const Vec3& from, const Vec3& to, const Vec3& v,
                      const Vec3& up) {
  CupPass out;
  out.velocity = v;
  // Work in the green's plane at the hole; nothing happens unless this step reaches the
  // hole's circle.
  const CupChord c = cup_chord(cup, from, to, up);
  if (!c.crosses) return out;
  const Vec3 &a = c.a, &d = c.d, &closest = c.closest;
  const double len2 = c.len2, s = c.s, offset = c.offset, half = c.half;
  const double enter = s - half;
  if (enter > 1.0 || s + half < 0.0) return out;
  const Vec3 vt = v - v.dot(up) * up;
  const double speed = vt.norm();
  if (speed <= 0.0) return out;
  const Vec3 dir = vt / speed;
  const double drop_time = std::sqrt(2.0 * ball_radius / kGravity);  // to fall a ball radius
  if (cup.flagstick && offset < ball_radius + cup.stick_radius) {
    // Strikes the stick: rebound off the cylinder (normal from the axis to the ball centre),
    // then Holmes's rule over the whole time the centre is over the hole: the time before the
    // stick plus the time along the new path to the rim (less a radius) must let it fall a
    // radius. A centred putt that would jump the hole is sent back across it and drops; a
    // glancing one is turned toward the near rim and rides out.
    const double contact = ball_radius + cup.stick_radius;
    const double back = std::sqrt(std::max(0.0, contact * contact - offset * offset) / len2);
    const double at = s - back;
    const Vec3 pos = a + at * d;
    const Vec3 n = pos.norm() > 0.0 ? Vec3(pos / pos.norm()) : Vec3(-dir);
    const double vn = vt.dot(n);
    const Vec3 after = vt - (1.0 + cup.stick_restitution) * std::min(vn, 0.0) * n;
    const double new_speed = after.norm();
    out.fraction = std::clamp(at, 0.0, 1.0);  // may lie past this step: the pass is decided now
    const double before = std::max(0.0, at - enter) * std::sqrt(len2) / speed;
    double rest = 0.0;
    if (new_speed > 1e-9) {
      const Vec3 nd = after / new_speed;
      const double pd = pos.dot(nd);
      const double to_rim = -pd + std::sqrt(pd * pd + cup.radius * cup.radius - pos.squaredNorm());
      rest = std::max(0.0, to_rim - ball_radius) / new_speed;
    }
    if (new_speed < 1e-3 || before + rest >= drop_time) {
      out.kind = CupPass::Kind::Holed;
      out.velocity.setZero();
      return out;
    }
    out.kind = CupPass::Kind::Stick;
    out.velocity = after + v.dot(up) * up;
    return out;
  }
  const double R = cup.radius, r = ball_radius;
  // Where the centre reaches the hole's circle, and the velocity there split into its part
  // toward the hole's axis and its part along the rim.
  const Vec3 at_rim = a + enter * d;
  const Vec3 e1 = at_rim / at_rim.norm();   // outward, from the axis to the entry point
  const Vec3 e2 = up.cross(e1).normalized(); // along the rim
  const double inward = -vt.dot(e1), along = vt.dot(e2);
  out.fraction = std::clamp(enter, 0.0, 1.0);
  const auto holed = [&](double time) {
    out.kind = CupPass::Kind::Holed;
    out.time_on_rim = time;
    out.velocity.setZero();
    return out;
  };
  const auto lips_out = [&](const Vec3& leave, const Vec3& velocity, double time) {
    out.kind = CupPass::Kind::LipOut;
    out.leave_offset = leave - at_rim;
    out.time_on_rim = time;
    out.velocity = velocity + v.dot(up) * up;
    return out;
  };
  if (inward * inward >= kGravity * r) {
    // Too fast toward the axis to follow the rim's edge down (the edge would have to pull):
    // the ball leaves it and falls over the hole (Holmes). Slow enough for its chord: it drops.
    if (speed < cup_capture_speed(cup, r, offset)) return holed(0.0);
    // Faster: its front meets the far rim's edge and it tips over it. The edge grips (the
    // turf's cut), so the ball's angular momentum about the edge is kept through the blow
    // (the blow acts at the edge) and the ball leaves pivoting about it: up, over and turned
    // toward the hole's middle, the more the farther the edge lies round from straight ahead.
    // The blow's loss is what slows it; Holmes's rule alone says it gets over.
    const Vec3 side = closest.norm() > 0.0 ? Vec3(closest / closest.norm()) : Vec3::Zero();
    const double half_chord = std::sqrt(std::max(0.0, R * R - offset * offset));
    // x: along the path from its closest approach to the axis; the ball fell from the entry.
    const auto height = [&](double x) {
      const double t = (x + half_chord) / speed;
      return r - 0.5 * kGravity * t * t;
    };
    const auto clear = [&](double x) {  // > 0 while the ball's surface is short of the edge
      const double z = height(x), rho = std::hypot(offset, x);
      return z > 0.0 && (R - rho) * (R - rho) + z * z > r * r;
    };
    double lo = 0.0, hi = half_chord;
    if (clear(lo)) {
      constexpr int kScan = 256;
      for (int k = 1; k <= kScan; ++k) {
        const double x = half_chord * k / kScan;
        if (!clear(x)) {
          hi = x;
          break;
        }
        lo = x;
      }
      for (int k = 0; k < 50; ++k) {
        const double mid = 0.5 * (lo + hi);
        (clear(mid) ? lo : hi) = mid;
      }
    } else {
      hi = 0.0;
    }
    const double x = hi, t = (x + half_chord) / speed, z = std::max(height(x), 0.0);
    const Vec3 centre = offset * side + x * dir;  // in the plane, from the axis
    const double rho = centre.norm();
    const Vec3 radial = rho > 0.0 ? Vec3(centre / rho) : dir;
    const Vec3 arm = -(R - rho) * radial + z * up;  // from the edge to the ball's centre
    const Vec3 vel = speed * dir - kGravity * t * up;
    const Vec3 spin = up.cross(vt) / r;  // rolling when it left the green
    const double mass = 1.0, inertia = 0.4 * mass * r * r;  // per unit mass: only ratios matter
    const Vec3 about_edge = mass * arm.cross(vel) + inertia * spin;
    const Mat3 pivot_inertia =
        inertia * Mat3::Identity() + mass * (arm.squaredNorm() * Mat3::Identity() - arm * arm.transpose());
    const Vec3 pivot = pivot_inertia.ldlt().solve(about_edge);
    const double energy = 0.5 * pivot.dot(pivot_inertia * pivot);
    // Over the edge it rolls on the green (7/10 m v²) the way the pivot carries its top.
    Vec3 heading = pivot.cross(up);
    heading -= heading.dot(up) * up;
    const double leave_speed = std::sqrt(2.0 * energy / (1.4 * mass));
    if (heading.norm() < 1e-12 || leave_speed < 1e-6) return lips_out(centre, Vec3::Zero(), t);
    return lips_out(centre, leave_speed * heading.normalized(), t);
  }
  // Slow toward the axis: the ball rolls onto the rim's edge and rides it, gravity tipping it
  // into the hole and its turn around the hole's axis flinging it out (Hogan & Antali 2025's
  // rim lip-out). Its centre moves on the torus of radius r about the edge: with ρ = R − r sinψ
  // and rolling's 7/10 m v², the Lagrangian gives
  //     ψ'' = −ρ cosψ φ'²/r + (5/7)(g/r) sinψ,   ρ² φ' = R·(speed along the rim) constant,
  // and the edge pushes while g cosψ − r ψ'² + ρ φ'² sinψ > 0.
  const double h = R * along;
  RimState st;
  st.psi_dot = inward / r;
  const auto rho_of = [&](double psi) { return R - r * std::sin(psi); };
  const auto accel = [&](double psi) {
    const double rho = rho_of(psi), phi_dot = h / (rho * rho);
    return -rho * std::cos(psi) * phi_dot * phi_dot / r + kRollingGravity * kGravity / r * std::sin(psi);
  };
  double time = 0.0;
  while (true) {
    // One RK4 step of (ψ, ψ', φ).
    const auto phi_rate = [&](double psi) { const double rho = rho_of(psi); return h / (rho * rho); };
    const double dt = kRideStep;
    const double p1 = st.psi_dot, a1 = accel(st.psi), f1 = phi_rate(st.psi);
    const double p2 = st.psi_dot + 0.5 * dt * a1, a2 = accel(st.psi + 0.5 * dt * p1), f2 = phi_rate(st.psi + 0.5 * dt * p1);
    const double p3 = st.psi_dot + 0.5 * dt * a2, a3 = accel(st.psi + 0.5 * dt * p2), f3 = phi_rate(st.psi + 0.5 * dt * p2);
    const double p4 = st.psi_dot + dt * a3, a4 = accel(st.psi + dt * p3), f4 = phi_rate(st.psi + dt * p3);
    st.psi += dt / 6.0 * (p1 + 2.0 * p2 + 2.0 * p3 + p4);
    st.psi_dot += dt / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    st.phi += dt / 6.0 * (f1 + 2.0 * f2 + 2.0 * f3 + f4);
    time += dt;
    const double rho = rho_of(st.psi), phi_dot = h / (rho * rho);
    const double press = kGravity * std::cos(st.psi) - r * st.psi_dot * st.psi_dot + rho * phi_dot * phi_dot * std::sin(st.psi);
    const bool off_edge = st.psi < 0.0 || (press < 0.0 && st.psi_dot < 0.0);
    if (off_edge) {
      const Vec3 out_dir = std::cos(st.phi) * e1 + std::sin(st.phi) * e2;
      const Vec3 round = -std::sin(st.phi) * e1 + std::cos(st.phi) * e2;
      const Vec3 velocity = -r * std::cos(st.psi) * st.psi_dot * out_dir + rho * phi_dot * round;
      return lips_out(rho * out_dir, velocity, time);
    }
    // Against the hole's wall, off the edge toward the middle, or still circling after a
    // second: it drops.
    if (st.psi >= 0.5 * kPi || press < 0.0 || time > kRideLongest) return holed(time);
  }
}

}  // namespace sweetspot
