#include "game/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

constexpr double kMargin = 0.84;  // fraction of the half-image the framed points may use

// Distance along -forward from `centre` at which every point fits a frustum of the given
// tangents (horizontal, vertical), with the points centred on `centre`.
double fit_distance(const std::vector<Vec3>& points, const Vec3& centre, const Vec3& f, const Vec3& s, const Vec3& u,
                    double tan_h, double tan_v) {
  double d = 1.0;
  for (const Vec3& p : points) {
    const Vec3 r = p - centre;
    const double z = r.dot(f);
    d = std::max(d, std::abs(r.dot(s)) / (tan_h * kMargin) - z);
    d = std::max(d, std::abs(r.dot(u)) / (tan_v * kMargin) - z);
  }
  return d;
}

// Centre of the points' extent in the (s, u) plane, keeping its depth at the mean.
Vec3 extent_centre(const std::vector<Vec3>& points, const Vec3& s, const Vec3& u) {
  double s_lo = 1e300, s_hi = -1e300, u_lo = 1e300, u_hi = -1e300;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) {
    s_lo = std::min(s_lo, p.dot(s));
    s_hi = std::max(s_hi, p.dot(s));
    u_lo = std::min(u_lo, p.dot(u));
    u_hi = std::max(u_hi, p.dot(u));
    mean += p;
  }
  mean /= static_cast<double>(points.size());
  const Vec3 f = s.cross(u);
  return 0.5 * (s_lo + s_hi) * s + 0.5 * (u_lo + u_hi) * u + mean.dot(f) * f;
}

Camera look_along(const std::vector<Vec3>& points, const Vec3& forward, const Vec3& up_hint, double aspect) {
  Camera c;
  c.up = up_hint;
  const Vec3 f = forward.normalized();
  const Vec3 s = f.cross(up_hint).normalized();
  const Vec3 u = s.cross(f);
  const Vec3 centre = extent_centre(points, s, u);
  const double tan_v = std::tan(c.fov_y / 2);
  const double d = fit_distance(points, centre, f, s, u, tan_v * aspect, tan_v);
  c.eye = centre - d * f;
  c.target = centre;
  c.near_m = std::max(0.5, 0.02 * d);
  return c;
}

// Behind and above the ball, looking along its horizontal motion: the chase view.
Camera chase_camera(const ShotFraming& framing) {
  Camera c;
  Vec3 dir = framing.ball_velocity;
  dir.y() = 0;
  dir = dir.norm() > 0.5 ? dir.normalized() : framing.aim;
  // Close enough that the club or bat at impact reads at t = 0.
  c.eye = framing.ball - 3.5 * dir + Vec3(0, 1.3, 0);
  c.target = framing.ball + 4.0 * dir;
  c.near_m = 0.1;
  return c;
}

// The landing area from behind and above, along the way the ball came down, 25 degrees
// down: the descending leg, the bounces and the ball all in view.
Camera landing_camera(const ShotFraming& framing, double aspect) {
  const Vec3 f =
      (framing.landing_aim * std::cos(deg_to_rad(25.0)) - Vec3::UnitY() * std::sin(deg_to_rad(25.0))).normalized();
  std::vector<Vec3> points = framing.finish;
  // At least ~12 m of ground around the ball, so a ball that stopped by the landing point
  // is seen on its patch of grass, not as a speck filling the image.
  for (const Vec3& d : {Vec3(6, 0, 0), Vec3(-6, 0, 0), Vec3(0, 0, 6), Vec3(0, 0, -6)}) points.push_back(framing.ball + d);
  return look_along(points, f, Vec3::UnitY(), aspect);
}

Camera follow_camera(const ShotFraming& framing, double aspect) {
  const Camera chase = chase_camera(framing);
  // Like a broadcast cutting to the landing camera: the turn starts one second before the
  // landing and ends at it (a home run's shot ends there), eased at both ends.
  if (framing.finish.empty() || framing.since_landing < -1.0) return chase;
  return blend_cameras(chase, landing_camera(framing, aspect), ease_in_out(framing.since_landing + 1.0));
}

}  // namespace

CameraKind parse_camera_kind(std::string_view name) {
  if (name == "behind") return CameraKind::Behind;
  if (name == "side") return CameraKind::Side;
  if (name == "top") return CameraKind::Top;
  if (name == "follow") return CameraKind::Follow;
  throw InputError("camera '" + std::string(name) + "' is not one of: behind, side, top, follow");
}

const char* to_string(CameraKind k) {
  switch (k) {
    case CameraKind::Behind: return "behind";
    case CameraKind::Side: return "side";
    case CameraKind::Top: return "top";
    case CameraKind::Follow: return "follow";
  }
  return "?";
}

Vec3 Camera::forward() const { return (target - eye).normalized(); }
Vec3 Camera::right() const { return forward().cross(up).normalized(); }
Vec3 Camera::true_up() const { return right().cross(forward()); }

Eigen::Matrix4d Camera::view() const {
  const Vec3 f = forward(), s = right(), u = true_up();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4d Camera::projection(double aspect) const {
  const double t = 1.0 / std::tan(fov_y / 2);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = -(far_m + near_m) / (far_m - near_m);
  m(2, 3) = -2.0 * far_m * near_m / (far_m - near_m);
  m(3, 2) = -1.0;
  return m;
}

std::optional<Eigen::Vector2d> Camera::project(const Vec3& p, int width, int height) const {
  const Eigen::Vector4d clip = projection(double(width) / height) * view() * p.homogeneous();
  if (clip.w() <= near_m) return std::nullopt;
  const double x = clip.x() / clip.w(), y = clip.y() / clip.w();
  return Eigen::Vector2d((x + 1.0) * 0.5 * width, (1.0 - y) * 0.5 * height);
}

double Camera::metres_per_pixel(const Vec3& p, int height) const {
  const double depth = std::max((p - eye).dot(forward()), near_m);
  return 2.0 * depth * std::tan(fov_y / 2) / height;
}

Vec3 aim_line(double aim) { return Vec3(std::cos(aim), 0.0, std::sin(aim)); }

void Bounds::add(const Vec3& p) {
  min = min.cwiseMin(p);
  max = max.cwiseMax(p);
}

Bounds shot_bounds(const ShotTrajectory& trajectory) {
  Bounds b;
  if (trajectory.samples.empty()) return b;
  b.min = b.max = trajectory.samples.front().position;
  for (const auto& s : trajectory.samples) b.add(s.position);
  return b;
}

TrajectorySample sample_at(const ShotTrajectory& trajectory, double t, std::size_t* index) {
  const auto& s = trajectory.samples;
  if (s.empty()) {
    if (index) *index = 0;
    return {};
  }
  if (t <= s.front().t) {
    if (index) *index = 0;
    return s.front();
  }
  if (t >= s.back().t) {
    if (index) *index = s.size() - 1;
    return s.back();
  }
  const auto it = std::upper_bound(s.begin(), s.end(), t, [](double v, const TrajectorySample& x) { return v < x.t; });
  const std::size_t i = static_cast<std::size_t>(it - s.begin()) - 1;
  if (index) *index = i;
  const auto& a = s[i];
  const auto& b = s[i + 1];
  const double span = b.t - a.t;
  const double w = span > 0 ? (t - a.t) / span : 0.0;
  TrajectorySample out = a;
  out.t = t;
  out.position = a.position + w * (b.position - a.position);
  out.velocity = a.velocity + w * (b.velocity - a.velocity);
  out.spin = a.spin + w * (b.spin - a.spin);
  return out;
}

ShotFraming shot_framing(const ShotTrajectory& trajectory, double t) {
  ShotFraming f;
  const auto& s = trajectory.samples;
  if (s.empty()) {
    f.points.push_back(Vec3::Zero());
    f.points.push_back(Vec3(100.0, 0.0, 0.0));
    return f;
  }
  // At most ~400 points: framing needs the shape, not every integrator step.
  const std::size_t stride = std::max<std::size_t>(1, s.size() / 400);
  for (std::size_t i = 0; i < s.size(); i += stride) f.points.push_back(s[i].position);
  f.points.push_back(s.back().position);
  f.launch = s.front().position;
  Vec3 d = s.back().position - f.launch;
  d.y() = 0;
  f.aim = d.norm() > 1.0 ? d.normalized() : Vec3::UnitX();
  Vec3 to_landing = trajectory.summary.landing_position - f.launch;
  to_landing.y() = 0;
  f.landing_aim = trajectory.summary.hang_time_s > 0.0 && to_landing.norm() > 1.0 ? to_landing.normalized() : f.aim;
  const TrajectorySample at = sample_at(trajectory, t);
  f.ball = at.position;
  f.ball_velocity = at.velocity;
  const double land = trajectory.summary.hang_time_s;
  if (land > 0.0) {
    f.since_landing = t - land;
    // The descending leg: the last third of the flight's time (the ball falls from about
    // its apex height there), then everything up to the time shown.
    const double from = s.front().t + (2.0 / 3.0) * (land - s.front().t);
    const std::size_t fine = std::max<std::size_t>(1, s.size() / 800);
    for (std::size_t i = 0; i < s.size() && s[i].t <= std::max(t, land); i += fine)
      if (s[i].t >= from) f.finish.push_back(s[i].position);
    f.finish.push_back(f.ball);
  }
  return f;
}

Camera frame_shot(CameraKind kind, const ShotFraming& framing, int width, int height, const FrameWindow& window) {
  const double aspect = double(width) / height;
  const Vec3 up = Vec3::UnitY();
  // Side, Top and Behind look along the target line, not along this shot, so a slice or a
  // pull shows as a curve away from the line.
  Vec3 aim(framing.target_line.x(), 0.0, framing.target_line.z());
  aim = aim.norm() > 1e-9 ? Vec3(aim.normalized()) : Vec3::UnitX();
  const Vec3 right = aim.cross(up);  // +z for a +x line (DESIGN §2: z right)
  switch (kind) {
    case CameraKind::Side: {
      // From the right of the shot, looking down side_down, so downrange runs left to right.
      const Vec3 f = (-right * std::cos(framing.side_down) - up * std::sin(framing.side_down)).normalized();
      return look_along(framing.points, f, up, aspect);
    }
    case CameraKind::Top: {
      // Straight down. The up hint picks which way downrange runs: along the image's long
      // axis when the shot is longer than it is wide (a straight drive fills a wide image
      // instead of a thin strip up its middle).
      double along_lo = 1e300, along_hi = -1e300, across_lo = 1e300, across_hi = -1e300;
      for (const Vec3& p : framing.points) {
        along_lo = std::min(along_lo, p.dot(aim));
        along_hi = std::max(along_hi, p.dot(aim));
        across_lo = std::min(across_lo, p.dot(right));
        across_hi = std::max(across_hi, p.dot(right));
      }
      const bool long_shot = along_hi - along_lo >= across_hi - across_lo;
      const bool downrange_right = long_shot == (aspect >= 1.0);
      // up hint -z: image right = (-y) x (-z) = +x (downrange right, the target line's left up).
      return look_along(framing.points, -up, downrange_right ? Vec3(-right) : aim, aspect);
    }
    case CameraKind::Follow:
      return follow_camera(framing, aspect);
    case CameraKind::Behind:
      break;
  }
  // Behind: the eye stands behind the launch point and turns to centre the shot's angular
  // extent on the window; it steps back until the extent fits a field of view of at most 60°.
  // The window in normalised device coordinates (x right, y up, -1..1): its half sizes and
  // its centre (the whole image: halves of 1 about 0, and no turn below).
  const double win_half_x = window.right - window.left, win_half_y = window.bottom - window.top;
  const double win_x = window.left + window.right - 1.0, win_y = 1.0 - window.top - window.bottom;
  Camera c;
  for (double back : {14.0, 20.0, 30.0, 45.0, 70.0, 110.0, 170.0, 260.0, 420.0}) {
    // A little to the right of the line (like a TV tower behind the tee), so a straight
    // shot's near rising leg and far falling leg separate by parallax instead of drawing
    // one vertical hairpin.
    c.eye = framing.launch - back * aim + 0.18 * back * right + Vec3(0, 3.0 + 0.25 * back, 0);
    double yaw_lo = 1e9, yaw_hi = -1e9, pitch_lo = 1e9, pitch_hi = -1e9;
    for (const Vec3& p : framing.points) {
      const Vec3 r = p - c.eye;
      const double ahead = r.dot(aim);
      const double yaw = std::atan2(r.dot(right), ahead);
      const double pitch = std::atan2(r.y(), std::hypot(ahead, r.dot(right)));
      yaw_lo = std::min(yaw_lo, yaw);
      yaw_hi = std::max(yaw_hi, yaw);
      pitch_lo = std::min(pitch_lo, pitch);
      pitch_hi = std::max(pitch_hi, pitch);
    }
    const double need_v = std::max(std::tan(0.5 * (pitch_hi - pitch_lo)) / (kMargin * win_half_y),
                                   std::tan(0.5 * (yaw_hi - yaw_lo)) / (kMargin * aspect * win_half_x));
    const double fov = 2.0 * std::atan(need_v);
    c.fov_y = std::max(fov, deg_to_rad(30.0));
    // Turned so the extent's centre lands on the window's: a point at NDC y sits
    // atan(y·tan(fov/2)) above the view's axis (across, the same scaled by the aspect).
    const double tan_v = std::tan(0.5 * c.fov_y);
    const double yaw = 0.5 * (yaw_lo + yaw_hi) - std::atan(win_x * tan_v * aspect),
                 pitch = 0.5 * (pitch_lo + pitch_hi) - std::atan(win_y * tan_v);
    const Vec3 dir = (std::cos(pitch) * (std::cos(yaw) * aim + std::sin(yaw) * right) + std::sin(pitch) * up);
    c.target = c.eye + 50.0 * dir;
    if (fov <= deg_to_rad(60.0)) break;
  }
  return c;
}

double ease_in_out(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

Camera blend_cameras(const Camera& a, const Camera& b, double w) {
  w = std::clamp(w, 0.0, 1.0);
  if (w >= 1.0) return b;
  Camera c = b;
  c.eye = a.eye + w * (b.eye - a.eye);
  c.target = a.target + w * (b.target - a.target);
  c.fov_y = a.fov_y + w * (b.fov_y - a.fov_y);
  c.near_m = std::min(a.near_m, b.near_m);
  // The up hints blended: equal hints (the chase and landing views) stay exactly as they
  // are; opposite ones (never from our cameras) would cancel, so b's is kept.
  const Vec3 up = a.up + w * (b.up - a.up);
  c.up = up.norm() > 1e-6 ? Vec3(up.normalized()) : b.up;
  if ((c.target - c.eye).norm() < 1e-9) c.target = c.eye + b.forward();
  return c;
}

Camera frame_shot(CameraKind kind, const ShotTrajectory& trajectory, double t, int width, int height) {
  return frame_shot(kind, shot_framing(trajectory, t), width, height);
}

}  // namespace sweetspot
