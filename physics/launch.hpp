// Launch conditions: the ball state the instant it leaves the club or bat, and the
// launch-monitor numbers derived from it in TrackMan's conventions (DESIGN §2).
#pragma once

#include "physics/math.hpp"
#include "physics/range.hpp"

namespace sweetspot {

/// Ball state at separation, world frame, SI. What the flight accepts (validate_launch in
/// physics/flight.hpp) is LaunchNumbers' speed and spin ranges.
struct LaunchState {
  Vec3 position = Vec3::Zero();  ///< m; centre of the ball (y = radius on a flat tee box)
  Vec3 velocity = Vec3::Zero();  ///< m/s; a tour driver launches at ~75 m/s
  Vec3 spin = Vec3::Zero();      ///< rad/s; angular velocity, ~280 rad/s (2686 rpm) for a driver
};

/// Spin split about the ball's direction of travel (DESIGN §2). All rad/s except the axis.
struct SpinComponents {
  double total = 0.0;           ///< |ω|
  double backspin = 0.0;        ///< ω·h, h = normalize(v̂ × ŷ); + lifts the ball
  double sidespin_right = 0.0;  ///< -ω·u, u = h × v̂; + curves the ball right
  double rifle = 0.0;           ///< ω·v̂; gyro spin, gives no Magnus force
  double axis_rad = 0.0;        ///< atan2(sidespin_right, backspin); + curves right (slice for a right-hander)
};

/// Decomposes spin `omega` for a ball moving along `velocity`. For a ball moving straight
/// up or down (v̂ ∥ ŷ) the backspin axis is undefined and ẑ is used.
SpinComponents decompose_spin(const Vec3& velocity, const Vec3& omega);

/// Launch-monitor numbers, SI (angles in radians). Convert to display units at the edges.
struct LaunchMetrics {
  double ball_speed = 0.0;          ///< m/s
  double vertical_angle = 0.0;      ///< rad, + up
  double horizontal_angle = 0.0;    ///< rad, + right (toward +z)
  SpinComponents spin;
};

LaunchMetrics measure_launch(const LaunchState& launch);

/// Launch-monitor numbers as a shot's input (`flight`, launch-only scenarios, a launch
/// monitor's BallData). The speed and spin ranges are the validity of the flight models:
/// incompressible aerodynamics (below Mach ~0.45) and the spin parameters the aero fits
/// were measured over, extended to cover what the impact models can launch.
struct LaunchNumbers {
  double ball_speed = 0.0;        ///< m/s; tour driver 74.7, MLB exit velocity ~40
  static constexpr Range kBallSpeed{0.0, 150.0};
  double vertical_angle = 0.0;    ///< rad, + up
  static constexpr Range kVerticalAngle{-kPi / 2, kPi / 2};
  double horizontal_angle = 0.0;  ///< rad, + right
  static constexpr Range kHorizontalAngle{-kPi / 2, kPi / 2};
  double spin = 0.0;              ///< rad/s total; PW ~975 (9300 rpm); textbook friction can launch ~1700
  static constexpr Range kSpin{0.0, 2094.3951023931954};  ///< 20 000 rpm
  double spin_axis = 0.0;         ///< rad, + curves right; ±180° is pure topspin
  static constexpr Range kSpinAxis{-kPi, kPi};
};

/// Builds a launch state from launch-monitor numbers: speed (m/s), vertical and horizontal
/// launch angles (rad), total spin (rad/s), spin axis (rad, + curves right). The spin
/// vector is perpendicular to the velocity (no rifle spin). Position starts at `position`.
LaunchState launch_from_metrics(double ball_speed, double vertical_angle, double horizontal_angle,
                                double spin_rate, double spin_axis, const Vec3& position);

}  // namespace sweetspot
