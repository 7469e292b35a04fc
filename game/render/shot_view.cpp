#include "game/render/shot_view.hpp"

#include <algorithm>
#include <cmath>

#include "physics/units.hpp"

namespace sweetspot {

std::optional<ImpactorPlacement> impactor_placement(const ShotResult& r) {
  if (!r.has_impactor) return std::nullopt;
  ImpactorPlacement p;
  p.position = r.impactor_at_impact.position;
  p.orientation = r.impactor_at_impact.orientation;
  p.velocity = r.impactor_at_impact.velocity;
  return p;
}

ShotTrajectory ball_at_rest(const Vec3& centre) {
  ShotTrajectory t;
  TrajectorySample s;
  s.position = centre;
  s.phase = Phase::Rest;
  t.samples = {s, s};
  t.summary.landing_position = t.summary.rest_position = centre;
  return t;
}

ImpactorPlacement club_at_address(const Vec3& centre, const Vec3& aim, double ball_radius) {
  LaunchState along;
  along.position = centre;
  along.velocity = aim;
  return nominal_impactor(false, along, ball_radius, 0.0);
}

Camera full_shot_address_camera(const Vec3& ball, const Vec3& aim) {
  const double down = deg_to_rad(5.0);
  Camera c;
  c.eye = ball - 9.0 * aim + Vec3(0.0, 2.6, 0.0);
  c.target = c.eye + 50.0 * (std::cos(down) * aim - std::sin(down) * Vec3::UnitY());
  c.fov_y = deg_to_rad(30.0);
  return c;
}

Camera putt_address_camera(const Vec3& ball, const Vec3& aim, double to_pin) {
  const Vec3 right(-aim.z(), 0.0, aim.x());
  Camera c;
  // High enough to see over the golfer: he stands ~0.75 m left of the line, his head ~1.6 m
  // up. From 1.9 m the sight line over his head met the green ~25 m out and he hid most of
  // the slope arrows left of the line; from 3.2 m it meets it ~8.5 m out (eye height x 4 m /
  // (3.2 - 1.7)). Higher, a long putt's flag leaves the top of the frame while the ball is
  // held above the meter.
  c.eye = ball - 4.0 * aim + 0.6 * right + Vec3(0.0, 3.2, 0.0);
  // The flag's top at the cup (the green taken as level): past ~40 ft the tilt that holds
  // the ball above the meter leaves it out of the top of the frame (a 61 ft chip's cloth
  // was cut off), so the lens widens, 2.5° at a time up to 60°, until it is in.
  const Vec3 flag_top = ball + to_pin * aim + Vec3(0.0, kFlagstickHeight, 0.0);
  for (double fov = 45.0;; fov += 2.5) {
    c.target = ball + (std::min(to_pin, 12.0) + 0.5) * aim;
    c.target.y() = ball.y() - 0.2;
    c.fov_y = deg_to_rad(fov);
    // Looking that far ahead alone puts a long putt's ball at the image's bottom edge, under
    // the meter (the bottom ~110 px of the window): tilt down until the ball is no lower
    // than 55 % of the half-height below the centre, which clears the meter in any window
    // 500 px or taller and keeps the cup and the flag of a 40 ft putt in view.
    const Vec3 to_ball = ball - c.eye, to_target = c.target - c.eye;
    const double ball_dip = std::atan2(-to_ball.y(), std::hypot(to_ball.x(), to_ball.z()));
    const double half = std::tan(0.5 * c.fov_y);
    const double max_below_centre = std::atan(0.55 * half);
    const double flat = std::hypot(to_target.x(), to_target.z());
    const double least_pitch = ball_dip - max_below_centre;
    if (std::atan2(-to_target.y(), flat) < least_pitch) c.target.y() = c.eye.y() - flat * std::tan(least_pitch);
    // The flag's top within 90 % of the half-height above the centre.
    const Vec3 to_flag = flag_top - c.eye, forward = (c.target - c.eye).normalized();
    const double ahead = to_flag.dot(forward);
    const double up = to_flag.dot(c.true_up());
    if (fov >= 60.0 || (ahead > 0.0 && up / ahead <= 0.9 * half)) return c;
  }
}

Camera clear_view_of(const Camera& c, const Vec3& ball, const Terrain& world) {
  // m: the golfer's head over the ball, the sweep's radius (the near plane and a margin),
  // the nearest a framing of the whole golfer holds, the height over him of the last resort.
  constexpr double kHead = 1.7, kClearance = 0.5, kNearest = 3.0, kAbove = 2.5;
  constexpr double kStep = kPi / 12.0;  // 15°
  constexpr int kSteps = 6;             // up to 90°: side-on
  const Vec3 head = ball + Vec3(0.0, kHead, 0.0);
  // How far from his head toward `eye` the view is clear (the whole way when nothing is hit).
  auto clear_reach = [&](const Vec3& eye) {
    SurfaceContact hit;
    const double whole = (eye - head).norm();
    if (!world.sweep(head, eye, kClearance, &hit, nullptr)) return whole;
    return std::max(0.0, hit.fraction * whole - kClearance);
  };
  // The rig (eye and target) turned by `a` about the vertical through his head.
  auto swung = [&](double a) {
    const Quat q(Eigen::AngleAxisd(a, Vec3::UnitY()));
    Camera out = c;
    out.eye = head + q * (c.eye - head);
    out.target = head + q * (c.target - head);
    return out;
  };
  // How far below the horizontal `p` lies from `eye` (rad).
  auto below = [](const Vec3& eye, const Vec3& p) {
    const Vec3 d = p - eye;
    return std::atan2(-d.y(), std::hypot(d.x(), d.z()));
  };
  // The rig brought in along its own line to `reach` m from his head, looking the same way,
  // its lens widened as a camera operator's would be so the ball, nearer and lower, stays in
  // the picture with the line ahead: no lower than the full-shot view holds it, kBallShare
  // of the half-height below the centre (above the swing meter), up to kWidest.
  constexpr double kBallShare = 0.72, kWidest = kPi * 75.0 / 180.0;  // 75°
  auto brought_in = [&](const Camera& rig, double reach) {
    Camera out = rig;
    out.eye = head + reach * (rig.eye - head).normalized();
    out.target = rig.target + (out.eye - rig.eye);
    const double ball_below_centre = below(out.eye, ball) - below(out.eye, out.target);
    const double half = std::atan(std::tan(ball_below_centre) / kBallShare);
    out.fov_y = std::clamp(2.0 * half, rig.fov_y, std::max(rig.fov_y, kWidest));
    return out;
  };
  // A swung rig looks `a` off his line, and the pin with it. Turned back toward the line
  // about its own eye as far as keeps the golfer and the ball within kEdge of the image's
  // half-width (at 16:10, the narrowest window the game opens), the lens widened for it up to
  // kWidest: the player sees where he aims past the trees, the golfer at one side.
  constexpr double kEdge = 0.85, kAspect = 1.6;
  const Vec3 along(c.forward().x(), 0.0, c.forward().z());
  auto toward_line = [&](const Camera& rig) {
    const Vec3 f = rig.forward();
    const double off = std::atan2(f.cross(along).y(), f.dot(along));
    auto yawed = [&](double a) {
      Camera out = rig;
      out.target = rig.eye + Quat(Eigen::AngleAxisd(a, Vec3::UnitY())) * (rig.target - rig.eye);
      return out;
    };
    // The lens (fov_y) that holds p within kEdge of the half-width, seen from `v`.
    auto lens_for = [&](const Camera& v, const Vec3& p) {
      const Vec3 d = p - v.eye;
      const double across = std::atan2(std::abs(d.dot(v.right())), d.dot(v.forward()));
      return 2.0 * std::atan(std::tan(std::min(across / kEdge, 0.49 * kPi)) / kAspect);
    };
    const int steps = static_cast<int>(std::ceil(std::abs(off) / deg_to_rad(1.0)));
    for (int i = steps; i > 0; --i) {
      Camera v = yawed(off * i / steps);
      const double lens = std::max({v.fov_y, lens_for(v, ball), lens_for(v, head)});
      if (lens <= std::max(v.fov_y, kWidest)) {
        v.fov_y = lens;
        return v;
      }
    }
    return rig;
  };
  const double own = clear_reach(c.eye);
  if (own >= (c.eye - head).norm()) return c;
  if (own >= kNearest) return brought_in(c, own);
  for (int k = 1; k <= kSteps; ++k) {
    for (const double sign : {1.0, -1.0}) {
      const Camera turned = swung(sign * k * kStep);
      const double reach = clear_reach(turned.eye);
      if (reach >= (turned.eye - head).norm()) return toward_line(turned);
      if (reach >= kNearest) return toward_line(brought_in(turned, reach));
    }
  }
  // Hemmed in: over his head, looking down past him at the ball and the first metre of the
  // line (the ball ~12° below the image's centre), from behind him on his own line.
  const Vec3 look = c.target - c.eye;
  Vec3 ahead(look.x(), 0.0, look.z());
  ahead = ahead.norm() > 1e-9 ? Vec3(ahead.normalized()) : Vec3::UnitX();
  Camera out = c;
  out.eye = head - std::min(own, 1.0) * ahead + Vec3(0.0, kAbove, 0.0);
  out.target = ball + ahead;
  return out;
}

ImpactorPlacement nominal_impactor(bool bat, const LaunchState& launch, double ball_radius, double bat_length) {
  const Vec3 n = launch.velocity.norm() > 0.0 ? Vec3(launch.velocity.normalized()) : Vec3::UnitX();
  const double yaw = std::atan2(n.z(), n.x());
  ImpactorPlacement p;
  if (bat) {
    constexpr double kSweetFromTip = 0.1524, kBarrelRadius = 0.033;  // Statcast sweet spot; MLB barrel
    const Quat q = Quat(Eigen::AngleAxisd(-yaw, Vec3::UnitY())) * Quat(Eigen::AngleAxisd(-kPi / 2, Vec3::UnitY()));
    const Vec3 flat(n.x(), 0, n.z());
    const Vec3 back = flat.norm() > 0.0 ? Vec3(flat.normalized()) : Vec3::UnitX();
    const Vec3 contact = launch.position - (ball_radius + kBarrelRadius) * back;
    p.orientation = q;
    p.position = contact - (bat_length - kSweetFromTip) * (q * Vec3::UnitX());
    return p;
  }
  const double loft = std::asin(std::clamp(n.y(), -1.0, 1.0));
  p.orientation = Quat(Eigen::AngleAxisd(-yaw, Vec3::UnitY())) * Quat(Eigen::AngleAxisd(loft, Vec3::UnitZ()));
  p.position = launch.position - ball_radius * (p.orientation * Vec3::UnitX());
  return p;
}

ShotSceneInput scene_input_for(const Assets& assets, const ResolvedShot& s, const ShotResult& r) {
  ShotSceneInput in;
  in.assets = &assets;
  in.world = s.world;
  in.distance_unit = s.sport->distance_unit;
  in.ball_radius = s.ball.radius;
  in.tee = s.start_surface == "tee" && s.spec.placement.teed;
  in.impactor = impactor_placement(r);
  in.impactor_mesh = in.impactor ? r.impactor_mesh : "";
  in.target_line = aim_line(r.aim);
  return in;
}

RenderRequest render_request_for(const Assets& assets, const ResolvedShot& s, const ShotResult& r) {
  return render_request_of(scene_input_for(assets, s, r));
}

}  // namespace sweetspot
