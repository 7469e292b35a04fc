// A touch of a surface while airborne (or of a wall while rolling): the bounce through the
// impact solver, or the ball staying down (rolling, sinking in water).
#include <algorithm>

#include "physics/detail/flight_steps.hpp"

namespace sweetspot::detail {

ShotEvent touch_surface(const ShotModel& m, ShotState& s, const SurfaceContact& c) {
  ShotEvent ev;
  ev.contact = c;
  ev.velocity_in = s.velocity();
  ev.kind = s.landed ? ShotEventKind::Bounce : ShotEventKind::Landing;
  s.landed = true;
  const SurfaceMaterial& mat = m.terrain->material(c.material);
  if (mat.kind == SurfaceKind::Water) {
    // Water holds the ball where it touches: it sinks (the rules decide the penalty).
    s.y.segment<6>(3).setZero();
    s.support = c;
    s.phase = Phase::Rest;
    end_shot(s, EndReason::Rest);
    return ev;
  }
  if (m.cup) {
    // Dropping into the hole from the air: where it comes down inside the hole's circle,
    // Holmes's rule with its speed along the green decides (a pitch that dunks, a chip
    // that lands in the hole).
    const Vec3 d = c.point - m.cup->centre;
    const double offset = (d - d.dot(c.normal) * c.normal).norm();
    const Vec3 v = s.velocity();
    const double along = (v - v.dot(c.normal) * c.normal).norm();
    if (offset < m.cup->radius && along < cup_capture_speed(*m.cup, m.ball.radius, offset)) {
      s.y.segment<3>(0) = m.cup->centre - (m.cup->depth - m.ball.radius) * c.normal;
      s.y.segment<6>(3).setZero();
      s.support = c;
      s.phase = Phase::Rest;
      end_shot(s, EndReason::InCup);
      ev.kind = ShotEventKind::InCup;
      return ev;
    }
  }
  const BounceResult b = bounce_on_surface(mat, c.normal, s.velocity(), s.spin(), m.ball, m.settings.ground_firmness);
  ++s.bounces;
  Vec3 v = b.velocity;
  const double vn = v.dot(c.normal);
  if (vn < 0.0) v -= vn * c.normal;  // the crater tilt never sends the ball into the ground
  s.y.segment<3>(3) = v;
  s.y.segment<3>(6) = b.spin;
  s.phase = Phase::Bounce;
  s.step_size = hop_step(s);
  s.rate_valid = false;
  const bool walkable = c.normal.dot(up_axis()) > kFollowCos * 0.5;  // < ~63° slope
  if (walkable && std::max(vn, 0.0) < m.settings.roll_speed) {
    s.support = c;
    s.phase = Phase::Roll;
    s.skidding = true;
  }
  return ev;
}

}  // namespace sweetspot::detail
