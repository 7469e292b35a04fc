#include "physics/launch.hpp"

#include <cmath>

namespace sweetspot {

SpinComponents decompose_spin(const Vec3& velocity, const Vec3& omega) {
  SpinComponents s;
  s.total = omega.norm();
  const double speed = velocity.norm();
  if (speed == 0.0) {
    // No direction of travel: call all of it backspin about ẑ so the numbers stay finite.
    s.backspin = omega.z();
    s.sidespin_right = -omega.y();
    s.axis_rad = std::atan2(s.sidespin_right, s.backspin);
    return s;
  }
  const Vec3 v_hat = velocity / speed;
  Vec3 h = v_hat.cross(up_axis());
  const double h_norm = h.norm();
  h = h_norm > 1e-12 ? Vec3(h / h_norm) : Vec3::UnitZ();
  const Vec3 u = h.cross(v_hat);
  s.backspin = omega.dot(h);
  s.sidespin_right = -omega.dot(u);
  s.rifle = omega.dot(v_hat);
  s.axis_rad = std::atan2(s.sidespin_right, s.backspin);
  return s;
}

LaunchMetrics measure_launch(const LaunchState& launch) {
  LaunchMetrics m;
  const Vec3& v = launch.velocity;
  m.ball_speed = v.norm();
  m.vertical_angle = std::atan2(v.y(), std::hypot(v.x(), v.z()));
  m.horizontal_angle = std::atan2(v.z(), v.x());
  m.spin = decompose_spin(v, launch.spin);
  return m;
}

LaunchState launch_from_metrics(double ball_speed, double vertical_angle, double horizontal_angle,
                                double spin_rate, double spin_axis, const Vec3& position) {
  LaunchState l;
  l.position = position;
  const double ch = std::cos(vertical_angle);
  l.velocity = ball_speed * Vec3(ch * std::cos(horizontal_angle), std::sin(vertical_angle),
                                 ch * std::sin(horizontal_angle));
  const Vec3 v_hat = l.velocity.norm() > 0.0 ? Vec3(l.velocity.normalized()) : Vec3::UnitX();
  Vec3 h = v_hat.cross(up_axis());
  h = h.norm() > 1e-12 ? Vec3(h.normalized()) : Vec3::UnitZ();
  const Vec3 u = h.cross(v_hat);
  // backspin = ω·h = S cos(axis), sidespin_right = -ω·u = S sin(axis)
  l.spin = spin_rate * (std::cos(spin_axis) * h - std::sin(spin_axis) * u);
  return l;
}

}  // namespace sweetspot
