// Statcast's bat tracking for one swing (DESIGN §9): bat speed at the sweet spot, how much
// of the possible exit speed the contact got (squared up), blasts, swing length, attack
// angle and direction. Defined as Baseball Savant defines them (bat tracking leaderboard
// glossary, 2024; M. Petriello, "Everything to know about Statcast's bat tracking", MLB.com
// 2024), computed from the swing the physics used.
#pragma once

#include "physics/equipment.hpp"

namespace sweetspot {

/// The swing as the physics struck with it.
struct SwingPath {
  double bat_speed = 0.0;     ///< m/s at the sweet spot at contact
  double attack_angle = 0.0;  ///< rad, + up: the sweet spot's path at contact
  /// rad, the sweet spot's path at contact in the batter's frame: + toward the opposite
  /// field (right field for a right-hander), − pull
  double direction = 0.0;
  double sweep = 0.0;         ///< rad the bat turns from the launch position to contact
  double tilt = 0.0;          ///< rad, the plane the bat's head turns in, from level
};

struct BatTracking {
  double bat_speed_mps = 0.0;
  double swing_length_m = 0.0;       ///< path of the bat's head from the start of the swing to contact
  double attack_angle_deg = 0.0;     ///< + up
  double attack_direction_deg = 0.0; ///< + toward the opposite field, − pull (FanGraphs' OPP/PULL)
  double swing_path_tilt_deg = 0.0;  ///< the swing's plane from level (Statcast's swing path tilt)
  double squared_up = 0.0;           ///< exit speed / the most the bat and pitch speeds allow; 0 for a miss
  bool is_squared_up = false;        ///< squared_up ≥ 0.8
  bool blast = false;                ///< squared up and fast: 100·squared_up + bat speed (mph) ≥ 164
  bool fast_swing = false;           ///< bat speed ≥ 75 mph
};

/// Statcast's collision efficiency at the sweet spot, q = 0.23 (EV_max = q·pitch + (1 + q)·bat;
/// Petriello 2024; Nathan, "the ball–bat collision efficiency", ~0.2 for wood at the sweet spot).
inline constexpr double kSquaredUpEfficiency = 0.23;
/// The most exit speed a bat speed and a pitch speed allow (m/s).
double max_exit_speed(double bat_speed, double pitch_speed);

/// `exit_speed` is 0 for a whiff. `pitch_speed` is the pitch's speed at the plate.
BatTracking track_swing(const SwingPath& swing, const BatSpec& bat, double pitch_speed, double exit_speed);

}  // namespace sweetspot
