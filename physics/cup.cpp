#include "physics/cup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sweetspot {
namespace {

/// Lip-out: the far rim turns the ball away from the centre by at most this (rad) and keeps
/// this share of its speed. ESTIMATES (see cup.hpp).
constexpr double kMaxLipTurn = 0.5 * kPi;
constexpr double kLipSpeedKept = 0.8;

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
  // Slow enough for its chord (Holmes): it drops.
  if (speed < cup_capture_speed(cup, ball_radius, offset)) {
    out.kind = CupPass::Kind::Holed;
    out.fraction = std::clamp(enter, 0.0, 1.0);
    out.velocity.setZero();
    return out;
  }
  // Lips out: turned away from the centre, the more the nearer the rim and the slower.
  const Vec3 side = closest.norm() > 0.0 ? Vec3(closest / closest.norm()) : Vec3::Zero();
  const double v0 = cup_capture_speed(cup, ball_radius, 0.0);
  const double turn = kMaxLipTurn * (offset / cup.radius) * std::min(1.0, v0 / speed);
  const Vec3 turned = std::cos(turn) * dir + std::sin(turn) * side;
  out.kind = CupPass::Kind::LipOut;
  out.fraction = std::clamp(s, 0.0, 1.0);
  out.velocity = kLipSpeedKept * speed * turned.normalized() + v.dot(up) * up;
  return out;
}

}  // namespace sweetspot
