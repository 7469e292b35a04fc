#include "game/modes/baseball/bat_tracking.hpp"

#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr double kSquaredUp = 0.8;    // Statcast: at least 80 % of the possible exit speed
constexpr double kBlastSum = 164.0;   // Statcast: 100·squared-up fraction + bat speed (mph)
constexpr double kFastSwing = 75.0;   // mph, Statcast's "fast swing"

}  // namespace

double max_exit_speed(double bat_speed, double pitch_speed) {
  return kSquaredUpEfficiency * pitch_speed + (1.0 + kSquaredUpEfficiency) * bat_speed;
}

BatTracking track_swing(const SwingPath& s, const BatSpec& bat, double pitch_speed, double exit_speed) {
  BatTracking t;
  t.bat_speed_mps = s.bat_speed;
  // The bat turns about its pivot at the knob: its head runs on a circle of the length beyond
  // the pivot.
  t.swing_length_m = bat.pivot_to_tip() * s.sweep;
  t.attack_angle_deg = rad_to_deg(s.attack_angle);
  t.attack_direction_deg = rad_to_deg(s.direction);
  t.swing_path_tilt_deg = rad_to_deg(s.tilt);
  const double possible = max_exit_speed(s.bat_speed, pitch_speed);
  t.squared_up = possible > 0.0 ? exit_speed / possible : 0.0;
  t.is_squared_up = t.squared_up >= kSquaredUp;
  t.blast = t.is_squared_up && 100.0 * t.squared_up + mps_to_mph(s.bat_speed) >= kBlastSum;
  t.fast_swing = mps_to_mph(s.bat_speed) >= kFastSwing;
  return t;
}

}  // namespace sweetspot
