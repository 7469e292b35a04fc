// The swing at a pitch and what becomes of the ball (DESIGN §9): timing and bat height go
// through the same bat–ball impact as every baseball shot; the flight, the fence and the
// foul lines decide home runs and fouls; a fielding model decides the rest.
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "game/rules/run_shot.hpp"
#include "game/modes/baseball/bat_tracking.hpp"
#include "game/modes/baseball/fielding.hpp"
#include "game/modes/baseball/pitching.hpp"
#include "physics/equipment.hpp"

namespace sweetspot {

/// Statcast's league-average swing path tilt, 32° (MLB glossary, "Swing Path (Tilt)", 2024:
/// hitters range from ~20° to ~50°): the plane the bat's head turns in, from level.
inline constexpr double kLeagueSwingTilt = 0.5585;  // rad (32°)

struct BatterSkill {
  std::string name;           ///< "pro", "amateur"
  double bat_speed = 32.0;    ///< m/s at the sweet spot, power swing
  double timing_sd_ms = 10.0; ///< spread of the swing's timing error, ms
  double height_sd = 0.010;   ///< m, spread of where the bat meets the ball vertically
  double eye_sd = 0.05;       ///< m, how far off his eye puts the pitch's location: he takes or swings, and aims, by it
  /// Live pitching (hitter.hpp): how often he reads a pitch's type before he must commit,
  /// and the spread of his read of the time to contact and of the height where it arrives.
  double recognition = 0.5;
  double read_timing_sd_ms = 12.0;
  double read_height_sd = 0.03;  ///< m
  double read_reach_sd = 0.05;   ///< m, along the barrel: how far from him it arrives
  /// m: the pitch he sees this far outside the zone he offers at e^-1 as often as one in it.
  double discipline = 0.07;
  double attack_angle = 0.175;   ///< rad, his swing's usual attack angle (met on time)
  double swing_tilt = kLeagueSwingTilt;  ///< rad, the plane his bat's head turns in, from level
  double sweep = 2.65;           ///< rad the bat turns from his launch position to contact
  double sprint_speed = 8.23;    ///< m/s, his top running speed (27 ft/s: Statcast's league average)
  /// His bat speed from swing to swing, one standard deviation as a share of his average:
  /// 4.3 % (3.1 mph for the league's 71.5), read as a normal spread off Statcast's fast-swing
  /// shares of hitters with known averages (J. Rodríguez 76.2 mph with 65 % of swings at 75+,
  /// M. Garver 71.0 with ~10 %).
  double bat_speed_sd = 0.043;
};
/// pro: the league's average hitter: 71.5 mph (Statcast's 2024 average bat speed), an attack
/// angle of 10° when met on time in the league's 32° plane (Statcast's league ~10°; FanGraphs'
/// hard-hit middle fastballs ~8°), a 7.3 ft swing (Statcast 2024 average swing length: 2.65 rad
/// of the maple bat's 0.84 m from the knob, where it turns), 27 ft/s; batting-practice timing
/// 5 ms (13° of bat at 2.7°/ms) and height 4 mm (ESTIMATES: a pro squares a batting-practice
/// ball up). amateur: a high-school hitter, 60 mph, 10 ms, 9 mm, 6° on time (ESTIMATES). Their
/// reads of live pitching: hitter.hpp.
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
  /// m the ball passes farther from the batter than the sweet spot would meet it (+ toward
  /// the tip; past the tip the bat misses).
  double reach_error = 0.0;
  static constexpr Range kReach{-0.5, 0.5};
  double attack_angle = 0.175;  ///< rad, + up: the sweet spot's climb when met on time
  static constexpr Range kAttackAngle{-0.5, 0.7};
  /// rad: the plane the bat's head turns in, from level; at least |attack_angle| (a path
  /// cannot climb more steeply than its plane).
  double swing_tilt = kLeagueSwingTilt;
  static constexpr Range kSwingTilt{0.0, 1.2};
  double sweep = 2.65;          ///< rad, the bat's turn from the launch position to contact
  double effort = 1.0;          ///< share of his bat speed he swings with (a two-strike swing is shorter)
  static constexpr Range kEffort{0.5, 1.0};
  /// m/s this swing's bat runs faster (+) or slower than his average (BatterSkill::bat_speed_sd).
  double speed_error = 0.0;
  static constexpr Range kSpeedError{-8.0, 8.0};
  /// rad past square where he means to meet the ball on the sweet spot (+ out front: pulled;
  /// − deep: the other way): contact_lead_for the pitch's location. `timing_ms` is his error
  /// against that moment.
  double contact_lead = 0.0;
  static constexpr Range kContactLead{-0.6, 0.6};
  /// m toward the hands from the sweet spot where he means to meet the ball (aim.hpp: a bot
  /// aims inside by what his scatter makes worth it); `reach_error` is the ball's line
  /// against that aim. 0 = the sweet spot.
  double aim_inside = 0.0;
  static constexpr Range kAimInside{0.0, 0.3};
};

/// The bat the game's hitters swing, bots and player alike (bats.toml: 33 in maple).
inline constexpr const char* kGameBat = "maple";

/// Nearer the hands than this (m from the tip) the ball meets the hands, not the bat: the
/// contact is taken there.
inline constexpr double kHandsFromTip = 0.45;

/// Hitting it where it is pitched: the hands can come in toward the body or reach out only so
/// far, so a batter meets an inside pitch out front, with the bat already turned toward the
/// pull side, and lets an outside one travel deeper (R. K. Adair, The Physics of Baseball,
/// ch. 3; HITf/x: the mean spray angle runs from pulled on the inside edge to the other way on
/// the outside edge, ~20° across the plate's 0.43 m: D. Allen, "How strong is the tendency to
/// pull the ball?", Baseball Analysts, 2009). kLeadPerInside: rad of lead per m the pitch is
/// nearer him than the plate's middle (ESTIMATE from that spread).
inline constexpr double kLeadPerInside = 0.9;  // rad/m
/// `inside`: m the pitch crosses nearer the batter than the middle of the plate (− away).
double contact_lead_for(double inside);
/// m `plate` (where a pitch crosses) lies nearer a batter of that side than the plate's
/// middle: + z is away from a right-handed batter.
inline double inside_by(const Vec3& plate, bool left_handed) { return (left_handed ? 1.0 : -1.0) * plate.z(); }

/// m: the spread of where a hitter's bat passes the ball along the barrel, his read of its
/// reach and his eye's error together (Hitter::read draws both).
inline double reach_scatter(const BatterSkill& skill) { return std::hypot(skill.read_reach_sd, skill.eye_sd); }

/// Timing turns the bat's direction at contact by its angular speed: the sweet spot's speed
/// over its distance from the pivot. The bat turns about a point very close to its knob (A. M.
/// Nathan, J. J. Crisco, R. M. Greenwald, D. A. Russell & L. V. Smith, "A comparative study of
/// baseball bat performance", Sports Eng. 13 (2011) 153; bats.toml), ~2.7°/ms for 71.5 mph on
/// the maple bat, so ~10 ms early or late sends the ball down a foul line (R. K. Adair, The
/// Physics of Baseball: "1/100 s early, the ball goes foul down the left-field line"). Where
/// the turned bat meets the ball: meet_ball. Returns rad for `ms` milliseconds off time.
inline double bat_turn(double bat_speed, const BatSpec& bat, double ms) { return bat_speed / bat.sweet_arm() * 1e-3 * ms; }

/// Where the bat's axis crosses the ball's path. The bat turns about its pivot in the plane
/// of its path (spanned by the on-time path, climbing at `attack`, and the level bat axis,
/// +z toward the tip); met `early` rad past square (− late), the axis is turned that much
/// toward the pitcher, and the ball is met where its line crosses it: off time farther out
/// along the bat (reach/cos φ from the pivot for a ball flying square to the bat), out front
/// when early and deep when late, and there higher or lower against the bat by how the ball's
/// line leaves the plane (a pitch descending as steeply as the bat climbs stays in it).
struct BallCrossing {
  bool crosses = false;    ///< false: the ball's line runs along the turned bat (no crossing)
  double from_pivot = 0.0; ///< m along the bat's axis from the pivot toward the tip
  double undercut = 0.0;   ///< m, the ball's centre above the bat's axis there (+ under the ball)
  double ahead = 0.0;      ///< m the ball is met ahead of the on-time point (+ toward the pitcher)
};
/// `ball_dir`: the ball's direction of flight near the plate in the batter's frame (x toward
/// the pitcher, y up, z away from a right-handed batter); `vertical_bat_angle`: the bat's on
/// time (− head down); `reach`: m from the pivot to the ball's line on time along the bat;
/// `undercut`: the ball's centre above the axis on time.
BallCrossing meet_ball(const Vec3& ball_dir, double attack, double vertical_bat_angle, double reach, double undercut,
                       double early);

/// The attack angle where the bat meets the ball, `turned` rad round its arc from where it
/// would on time (+ late). The sweet spot runs on a circle in a plane tilted `tilt` from
/// level; at β round from the circle's lowest point its path climbs at sin α = sin(tilt)·sin β.
/// On time it climbs at `attack`, so early contact, farther round the arc, climbs more steeply
/// and late contact less: the pulled fly ball and the late grounder the other way. A level
/// plane keeps a level path.
double attack_angle_at(double attack, double tilt, double turned);
/// The bat's vertical angle at the same point of the arc (− head below the hands): the axis
/// runs from the circle's centre to the sweet spot, down the plane's slope by sin(tilt)·cos β;
/// ~−30° on time for a 10° path in the league's 32° plane. A level plane keeps a level bat.
double vertical_bat_angle_at(double attack, double tilt, double turned);

struct SwingResult {
  bool contact = false;
  ShotResult shot;            ///< valid with contact: launch, flight, end
  BattedOutcome outcome = BattedOutcome::Strike;
  std::string fielder;        ///< who caught or fielded it ("CF", "SS", ...), "" for none
  FieldingPlay play;          ///< the fielders' play on a batted ball (contact)
  bool barrel = false, hard_hit = false, sweet_spot = false;  ///< Statcast's classes
  /// The ball went on back toward the catcher, within 20° of the pitch's own line: caught,
  /// a foul tip is a strike even with two strikes (MLB Rule 5.09(a)(2) via the definition of
  /// a foul tip). ESTIMATE of the cone a catcher's mitt covers.
  bool foul_tip = false;
  BatTracking tracking;       ///< Statcast's bat tracking for the swing (misses too)
  /// The contact (with contact): how long the ball was on the bat (s) and the impulse it took
  /// along the normal (N·s), what its sound is made from.
  double contact_time = 0.0, normal_impulse = 0.0;
  /// With contact: m from the tip where the ball met the bat (the end cap past 0).
  double impact_from_tip = 0.0;
  /// Where the bat's axis crossed the ball's line (meet_ball): the ball's centre above it (m,
  /// + the bat passed under the ball), and whether that was past the end of the bat, farther
  /// than the ball's edge reaches its end cap: why a swing missed. Past the end the height is
  /// the bat's set against the ball on time (the swing's undercut), not the axis's extension.
  double crossing_undercut = 0.0;
  bool past_end = false;
  /// The bat was through the zone (turned past a right angle, early) or not yet round (late)
  /// when the ball went by: no crossing on the bat at all.
  bool through = false;
};

/// The foul-tip cone around the pitch's line (see SwingResult::foul_tip).
inline constexpr double kFoulTipCone = 0.349;  // rad, 20°

/// Where on `bat` a ball met `from_tip` m from the tip was struck, in a hitter's words: "on
/// the barrel" where the bat keeps at least kBarrelCorFactor of its restitution (bats.toml's
/// cor_profile: the maple's 3.3-10.6 in from the tip, a ball there leaving within a few mph of
/// the plateau's), else "off the end of the bat" out toward the tip or "in on the hands" toward
/// the handle.
inline constexpr double kBarrelCorFactor = 0.9;
const char* contact_spot(const BatSpec& bat, double from_tip);

/// Statcast: hard-hit EV ≥ 95 mph; sweet spot LA 8–32°; barrel LA ≤ 50, EV ≥ 98,
/// 1.5·EV − LA ≥ 117, EV + LA ≥ 124 (EV mph, LA deg).
bool is_barrel(double ev_mph, double la_deg);

/// Who fields a batted ball: a team's defense, the batter's speed, and the draws of
/// catches and misplays (none: the likelier result, no misplays).
struct FieldingSetup {
  const Defense* defense = nullptr;  ///< nullptr: the league's
  double batter_sprint = 8.23;       ///< m/s
  Rng* rng = nullptr;
  bool field = true;  ///< false: the flight alone (home run, foul or in play), nobody fields it
};

/// Swings at `pitch` with `bat` (bats.toml) for a batter whose power swing is
/// `bat_speed` m/s. Deterministic for a given `fielding.rng` state.
SwingResult swing_at(const Assets& assets, const PitchFlight& pitch, const SwingInput& in, double bat_speed,
                     const std::string& bat = kGameBat, const FieldingSetup& fielding = {});

/// Home plate to the foot of the fence (m) at spray angle `spray` (rad, + toward first
/// base) on a world with a fence line; infinity outside its ends.
double fence_distance(const WorldAsset& world, double spray);

}  // namespace sweetspot
