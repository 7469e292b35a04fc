#include "game/render/swing_pose.hpp"

#include <algorithm>
#include <cmath>

namespace sweetspot {

double swing_pre_roll(const std::optional<ImpactorPlacement>& impactor, const std::string& impactor_mesh) {
  // Any delivered motion: a tap-in's putter moves at ~0.3 m/s, and a nominal impactor
  // (launch numbers without a delivery) at none.
  if (!impactor || impactor_mesh.empty() || impactor->velocity.norm() <= kMinDeliveredSpeed) return 0.0;
  return swing_shape(impactor_mesh).downswing;
}

const SwingShape& swing_shape(const std::string& impactor_mesh) {
  if (impactor_mesh == "bat") return kBatSwing;
  if (impactor_mesh == "putter_head") return kPutterSwing;
  return kClubSwing;
}

Vec3 head_frame_shaft_axis() {
  const double lie = deg_to_rad(60.0);
  return Vec3(-0.05, std::sin(lie), -std::cos(lie)).normalized();
}

ImpactorPlacement swing_pose(const ImpactorPlacement& impact, const Vec3& contact, const Vec3& shaft, double t,
                             const SwingShape& shape) {
  const double speed = impact.velocity.norm();
  if (speed < 1e-6 || t == 0.0 || shape.radius <= 0.0 || shape.downswing <= 0.0) return impact;
  const Vec3 v = impact.velocity / speed;
  // The swing plane holds the velocity and the shaft. The pivot lies in it at `radius` from
  // the contact, square to the velocity (the shaft's part across it), so the arc's tangent
  // at impact is the delivered velocity. The plane turns about k = v x s: a small positive
  // turn moves the contact by R k x (-s) = +R v.
  Vec3 s_perp = shaft - shaft.dot(v) * v;
  if (s_perp.norm() < 1e-9) return impact;  // velocity along the shaft: no plane to swing in
  s_perp.normalize();
  const Vec3 k = v.cross(s_perp);
  const Vec3 pivot = contact + shape.radius * s_perp;
  const double omega = speed / shape.radius;
  double theta = 0.0;
  if (t < 0.0) {
    // Angular speed growing linearly from 0 at -T to omega at 0:
    // theta(t) = omega ((t + T)^2 / (2T) - T / 2), theta(0) = 0, theta'(0) = omega.
    const double T = shape.downswing, u = std::max(t, -T) + T;
    theta = omega * (u * u / (2.0 * T) - T / 2.0);
  } else {
    // Slowing evenly from omega to rest at the finish F, reached at t_f = 2F / omega:
    // theta(t) = omega t - omega^2 t^2 / (4F), theta'(0) = omega, theta(t_f) = F.
    double F = std::max(shape.finish, 0.0);
    if (shape.follow_per_backswing > 0.0)  // the backswing's arc: omega T / 2 (above)
      F = std::min(F, shape.follow_per_backswing * omega * shape.downswing / 2.0);
    const double tf = 2.0 * F / omega, u = std::min(t, tf);
    theta = F > 0.0 ? omega * u - omega * omega * u * u / (4.0 * F) : 0.0;
  }
  const Quat turn(Eigen::AngleAxisd(theta, k));
  ImpactorPlacement out = impact;
  out.position = pivot + turn * (impact.position - pivot);
  out.orientation = (turn * impact.orientation).normalized();
  return out;
}

}  // namespace sweetspot
