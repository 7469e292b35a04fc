// Rigid body: parameters (mass, body-frame inertia) and state (pose, velocities).
#pragma once

#include "physics/math.hpp"

namespace sweetspot {

/// A rigid body's state and mass properties, world frame, SI. Plain data: copy it freely.
struct RigidBody {
  double mass = 1.0;                   ///< kg; golf ball 0.04593, driver head ~0.204, bat ~0.9
  Mat3 inertia_body = Mat3::Identity();///< kg·m² about the CG in body axes; golf ball 8.36e-6 on the diagonal
  Quat orientation = Quat::Identity(); ///< body → world rotation
  Vec3 position = Vec3::Zero();        ///< m; centre of gravity
  Vec3 velocity = Vec3::Zero();        ///< m/s; of the CG
  Vec3 angular_velocity = Vec3::Zero();///< rad/s

  /// Inertia tensor about the CG in world axes: R I Rᵀ.
  Mat3 inertia_world() const {
    const Mat3 r = orientation.toRotationMatrix();
    return r * inertia_body * r.transpose();
  }
  Mat3 inverse_inertia_world() const {
    const Mat3 r = orientation.toRotationMatrix();
    return r * inertia_body.inverse() * r.transpose();
  }
  /// Velocity of the material point at world position p.
  Vec3 point_velocity(const Vec3& p) const {
    return velocity + angular_velocity.cross(p - position);
  }
  double kinetic_energy() const {
    return 0.5 * mass * velocity.squaredNorm() +
           0.5 * angular_velocity.dot(inertia_world() * angular_velocity);
  }
};

/// Solid sphere inertia, 0.4 m R² on the diagonal (DESIGN §3 uses it for both balls).
inline Mat3 solid_sphere_inertia(double mass, double radius) {
  return Mat3::Identity() * (0.4 * mass * radius * radius);
}

}  // namespace sweetspot
