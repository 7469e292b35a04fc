// A touch of a surface while airborne (or of a wall while rolling): the bounce through the
// impact solver, or the ball staying down (rolling, sinking in water).
#include <algorithm>

#include "physics/detail/flight_steps.hpp"

namespace sweetspot::detail {
namespace {

// The ball stops at its position on `c`: sunk in water, in the cup, wedged.
void settle(ShotState& s, const SurfaceContact& c, EndReason why) {
  s.y.segment<6>(3).setZero();
  s.support = c;
  s.phase = Phase::Rest;
  end_shot(s, why);
}

}  // namespace

bool enter_crease(ShotState& s, const Vec3& n1, const Vec3& n2) {
  if (n1.dot(up_axis()) <= 0.05 || n2.dot(up_axis()) <= 0.05) return false;
  if (n1.cross(n2).norm() < 1e-3) return false;  // (nearly) one plane: no crease
  const Vec3 nc = (n1 + n2).normalized();
  if (nc.dot(up_axis()) < kFollowCos * 0.5) return false;  // the pair is a wall, not a floor
  s.crease_n1 = n1;
  s.crease_n2 = n2;
  s.phase = Phase::Roll;
  s.skidding = false;
  s.chatter = 0;
  return true;
}

ShotEvent touch_surface(const ShotModel& m, ShotState& s, const SurfaceContact& c) {
  ShotEvent ev;
  ev.contact = c;
  ev.velocity_in = s.velocity();
  ev.kind = s.landed ? ShotEventKind::Bounce : ShotEventKind::Landing;
  const SurfaceMaterial& mat = m.terrain->material(c.material);
  if (mat.kind != SurfaceKind::Water && c.fraction < 1e-6 && ev.velocity_in.dot(c.normal) >= 0.0 && s.landed) {
    // Already touching the face and not closing in on it (sliding along a trough's wall,
    // leaving a bank): nothing to bounce. The sweep reports such a touch at fraction 0 every
    // step, so a bounce that changes nothing would repeat for ever (200 000 zero-time bounces
    // to the step limit in the random-world soak). Set the ball just clear of the face and
    // fly on.
    const double clearance = c.normal.dot(s.position() - c.point) - m.ball.radius;
    if (clearance < 1e-6) s.y.segment<3>(0) += (1e-6 - clearance) * c.normal;
    s.rate_valid = false;
    ev.kind = ShotEventKind::Step;
    return ev;
  }
  s.landed = true;
  if (mat.kind == SurfaceKind::Water) {
    // Water holds the ball where it touches: it sinks (the rules decide the penalty).
    settle(s, c, EndReason::Rest);
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
      settle(s, c, EndReason::InCup);
      ev.kind = ShotEventKind::InCup;
      return ev;
    }
  }
  // A crease: gentle touches alternating between two faces (the ball bounces from one wall
  // of a trough to the other while it runs along it, else 200 000 times to the step limit).
  // After a few such touches it rolls in the crease, held by both.
  constexpr int kChatterTouches = 6;
  const Vec3 previous = s.last_touch_normal;
  s.last_touch_normal = c.normal;
  const bool gentle = -ev.velocity_in.dot(c.normal) < m.settings.roll_speed;
  const bool other_face = previous != Vec3::Zero() && (c.normal - previous).norm() > 1e-6;
  s.chatter = gentle && other_face ? s.chatter + 1 : (gentle ? s.chatter : 0);
  if (s.chatter >= kChatterTouches && enter_crease(s, previous, c.normal)) {
    const Vec3 d = previous.cross(c.normal).normalized();
    const Vec3 v = ev.velocity_in.dot(d) * d;
    s.y.segment<3>(3) = v;
    s.y.segment<3>(6) = (previous + c.normal).normalized().cross(v) / m.ball.radius;
    s.support = c;
    s.rate_valid = false;
    return ev;
  }
  // Wedged: a ball that keeps touching surfaces slower than the roll threshold without ever
  // settling into a roll is held between faces too steep to roll on (the floor of a narrow
  // V, a ball between a wall and a bank). Between such touches it rises at most
  // roll_speed²/2g (3 mm at 0.25 m/s), so it is at rest where it is, as a rigid-body engine
  // puts a body to sleep once its motion stays below a threshold (Box2D, Jolt). 20 touches:
  // a live micro-hop along a slope gains speed and breaks the run long before.
  constexpr int kWedgedTouches = 20;
  s.slow_touches = ev.velocity_in.norm() < m.settings.roll_speed ? s.slow_touches + 1 : 0;
  if (s.slow_touches >= kWedgedTouches) {
    settle(s, c, EndReason::Rest);
    ev.kind = ShotEventKind::Rest;
    return ev;
  }
  // The smooth surface's normal decides the bounce and whether it rolls on: a landing a
  // hair to either side of a facet edge then ends alike.
  // A ball grazing in toward the facet but away from the smooth surface (at a bend the smooth
  // normal leans over) bounces off the facet: an impact must separate it from what it touches.
  const Vec3 smooth = m.terrain->bounce_normal(c);
  const Vec3 surface_normal = s.velocity().dot(smooth) < 0.0 ? smooth : c.normal;
  const BounceResult b =
      bounce_on_surface(mat, surface_normal, s.velocity(), s.spin(), m.ball, m.settings.ground_firmness);
  ++s.bounces;
  s.support = c;  // the surface the hop leaves (its contact layer, ContactLayer)
  Vec3 v = b.velocity;
  const double vn = v.dot(c.normal);
  if (vn < 0.0) v -= vn * c.normal;  // the crater tilt never sends the ball into the ground
  s.y.segment<3>(3) = v;
  s.y.segment<3>(6) = b.spin;
  s.phase = Phase::Bounce;
  s.step_size = hop_step(s);
  s.rate_valid = false;
  const bool walkable = c.normal.dot(up_axis()) > kFollowCos * 0.5;  // < ~63° slope
  // Leaving speed off the smooth surface; but a ball not moving away from the facet it
  // touches at all (running along it, at a bend the smooth normal leans over) cannot fly:
  // it would touch the same facet again at once, over and over.
  const double leaving = v.dot(c.normal) > 0.0 ? std::max(v.dot(surface_normal), 0.0) : 0.0;
  s.hop_layer = walkable ? hop_layer_share(m, leaving) : 0.0;  // a wall has no layer to skim
  // A bank too steep to walk (> 63°) still carries a ball that touches it gently twice in a
  // row: it rolls and slides down to its foot instead of micro-hopping down it, each hop
  // shorter than the last (in the random-world soak, 200 000 hops of ~1 ms down a 62.4°
  // face to the step limit). Gentle touches alternating between two steep faces are a
  // crease instead (the chatter above). A face turned past vertical carries nothing.
  const bool same_face_again = gentle && previous != Vec3::Zero() && (c.normal - previous).norm() <= 1e-6;
  const bool carries = walkable || (same_face_again && c.normal.dot(up_axis()) > 0.05);
  if (carries && leaving < m.settings.roll_speed) {
    s.chatter = 0;
    s.support = c;
    s.phase = Phase::Roll;
    s.skidding = true;
  }
  return ev;
}

}  // namespace sweetspot::detail
