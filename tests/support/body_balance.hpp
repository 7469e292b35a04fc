// Momentum, angular momentum and kinetic energy of a rigid body in the world frame: the
// conservation checks of the impact tests.
#pragma once

#include "physics/body.hpp"

namespace sweetspot::test {

inline Mat3 world_inertia(const RigidBody& b) {
  const Mat3 r = b.orientation.toRotationMatrix();
  return r * b.inertia_body * r.transpose();
}
inline Vec3 momentum(const RigidBody& b) { return b.mass * b.velocity; }
/// About the world origin.
inline Vec3 angular_momentum(const RigidBody& b) {
  return b.position.cross(momentum(b)) + world_inertia(b) * b.angular_velocity;
}
inline double kinetic(const RigidBody& b) {
  return 0.5 * b.mass * b.velocity.squaredNorm() + 0.5 * b.angular_velocity.dot(world_inertia(b) * b.angular_velocity);
}

}  // namespace sweetspot::test
