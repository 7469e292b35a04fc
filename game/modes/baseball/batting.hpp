// The swing at a pitch and what becomes of the ball (DESIGN §9): timing and bat height go
// through the same bat–ball impact as every baseball shot; the flight, the fence and the
// foul lines decide home runs and fouls; a fielding model decides the rest.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "game/rules/run_shot.hpp"
#include "game/modes/baseball/pitching.hpp"

namespace sweetspot {

struct BatterSkill {
  std::string name;           ///< "pro", "amateur"
  double bat_speed = 32.0;    ///< m/s at the sweet spot, power swing
  double timing_sd_ms = 10.0; ///< spread of the swing's timing error, ms
  double height_sd = 0.010;   ///< m, spread of where the bat meets the ball vertically
  double eye_sd = 0.05;       ///< m, how far off the batter reads the pitch's location (takes)
};
/// pro: 71.5 mph (Statcast's 2024 average bat speed), timing 8 ms, height 4 mm; amateur:
/// 60 mph, 18 ms, 9 mm (ESTIMATES: a pro squares a batting-practice ball up; a high-school hitter).
const std::vector<BatterSkill>& batter_skills();
const BatterSkill& batter_skill(std::string_view name);

struct SwingInput {
  /// ms the bat arrives after the ideal moment (+ late: the ball is met deeper, nearer the
  /// hands, and goes the other way; − early: out front, toward the end of the bat, pulled).
  double timing_ms = 0.0;
  static constexpr Range kTiming{-150.0, 150.0};
  /// m the ball's centre is above the bat's axis where they meet (+ under the ball: lift and
  /// backspin; − over it: a grounder). ~15-25 mm makes a fly ball.
  double undercut = 0.012;
  static constexpr Range kUndercut{-0.08, 0.08};
  bool power = true;          ///< power swing (full bat speed) or contact swing (92 %, half the errors)
  bool left_handed = false;
};

/// Timing: 1.2° of swing direction per ms (±37 ms reaches the foul lines) and 3 mm along
/// the barrel per ms; a bat more than 45 ms early or late misses the ball entirely.
inline constexpr double kDirectionPerMs = 0.020943951;  // rad (1.2°)
inline constexpr double kBarrelPerMs = 0.003;            // m
inline constexpr double kMissTimingMs = 45.0;

enum class BattedOutcome { Strike, Foul, Out, Single, Double, Triple, HomeRun };
const char* to_string(BattedOutcome o);

struct SwingResult {
  bool contact = false;
  ShotResult shot;            ///< valid with contact: launch, flight, end
  BattedOutcome outcome = BattedOutcome::Strike;
  std::string fielder;        ///< who caught or fielded it ("CF", "SS", ...), "" for none
  bool barrel = false, hard_hit = false, sweet_spot = false;  ///< Statcast's classes
};

/// Statcast: hard-hit EV ≥ 95 mph; sweet spot LA 8–32°; barrel LA ≤ 50, EV ≥ 98,
/// 1.5·EV − LA ≥ 117, EV + LA ≥ 124 (EV mph, LA deg).
bool is_barrel(double ev_mph, double la_deg);

/// Swings at `pitch` with `bat` ("maple", bats.toml) for a batter whose power swing is
/// `bat_speed` m/s. Deterministic.
SwingResult swing_at(const Assets& assets, const PitchFlight& pitch, const SwingInput& in, double bat_speed,
                     const std::string& bat = "maple");

/// Home plate to the foot of the fence (m) at spray angle `spray` (rad, + toward first
/// base) on a world with a fence line; infinity outside its ends.
double fence_distance(const WorldAsset& world, double spray);

/// The fielding model alone, for a batted ball's shot on the ballpark (tests, the window).
/// Fielders at standard depths with Statcast's reaction, sprint speeds and arm strength; a
/// fly ball is caught if one reaches its landing spot in its hang time; a grounder is an out
/// when the fielder who reaches it first can throw to first base before the batter gets
/// there (4.47 s, Statcast's mean home-to-first); otherwise the batter takes the bases the
/// throw cannot beat him to. Throws fly through `aero` and `env` (throwing.hpp).
BattedOutcome field_ball(const ShotResult& shot, const AeroModel& aero, const Environment& env,
                         std::string* fielder = nullptr);

}  // namespace sweetspot
