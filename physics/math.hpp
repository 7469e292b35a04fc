// Sweetspot math: Eigen types and the few constants every physics file shares.
//
// World frame (DESIGN §2): right-handed, x downrange, y up, z to the right of the target
// line. SI units everywhere inside physics/.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sweetspot {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

inline constexpr double kPi = 3.14159265358979323846;
/// Standard gravity, m/s², acting along -y.
inline constexpr double kGravity = 9.80665;

inline constexpr double deg_to_rad(double deg) { return deg * (kPi / 180.0); }
inline constexpr double rad_to_deg(double rad) { return rad * (180.0 / kPi); }

inline const Vec3& up_axis() {
  static const Vec3 y{0.0, 1.0, 0.0};
  return y;
}

/// The cross-product matrix [a]× such that [a]× b = a × b.
inline Mat3 cross_matrix(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(),
       a.z(), 0.0, -a.x(),
       -a.y(), a.x(), 0.0;
  return m;
}

}  // namespace sweetspot
