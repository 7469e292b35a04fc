// A hitter who can miss (DESIGN §9): he sees the pitch until he must commit to his swing,
// then swings where he expects it. A pitch he reads right arrives about where he expects; one
// he has not read he takes for the fastball he sits on, and it keeps the rest of its own break
// and pace to itself: he is early on a changeup and over a curveball. Whether he swings at all
// depends on where he sees it and the count, and he swings where he sees it.
// The whiff comes from the bat's path missing the ball's (swing_at), not from a rate.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "game/modes/baseball/batting.hpp"
#include "game/modes/baseball/pitcher.hpp"
#include "game/util/rng.hpp"

namespace sweetspot {

/// The commit point: a batter must start his ~0.15 s swing about 0.175 s before the ball
/// arrives (R. K. Adair, The Physics of Baseball, 3rd ed., ch. 3: the decision is made with the
/// ball ~25 ft from the plate); what the ball does after that he cannot see in time.
inline constexpr double kCommitTime = 0.175;  // s

/// What a batter knows of a pitcher's types: each one's usual flight time and break (his
/// mean pitch of the type thrown to the middle of the zone), and his fastball (his fastest
/// type): what a batter who has not read the type expects. Hitters sit on the fastball and
/// adjust to the rest ("look fastball, adjust to the breaking ball"): the pitch that beats him
/// unread is the slower one he is early on and over, which is why Statcast's whiffs per swing
/// run ~13-21 % on fastballs and ~26-32 % on breaking and off-speed pitches (FanGraphs, "Know
/// Your Averages 2024", from Statcast).
struct ScoutingReport {
  struct Type {
    std::string type;
    double flight_time = 0.0, vertical_break = 0.0, horizontal_break = 0.0;
  };
  std::vector<Type> types;
  Type fastball;
  const Type& of(const std::string& type) const;
};
ScoutingReport scout(const Assets& assets, const PitcherProfile& pitcher);

/// His read of one pitch at the commit point: where he expects it at the plate and when.
struct PitchRead {
  bool recognized = false;
  double height_error = 0.0;  ///< m, where it arrives above where he expects it
  double away_error = 0.0;    ///< m, farther from him than he expects it
  double timing_error_ms = 0.0;  ///< ms his swing arrives after the ball (− early)
  Vec3 seen = Vec3::Zero();   ///< where he thinks it crosses the plate
};

/// With two strikes a hitter shortens up: Statcast's 2024 bat tracking has two-strike swings
/// ~3 % slower and ~5 % shorter than the rest (league ~69.5 against 71.5 mph; ~7.0 against
/// 7.3 ft); the shorter, later-starting swing steadies his read (ESTIMATE: 10 % less spread in
/// his timing, height and reach).
inline constexpr double kTwoStrikeEffort = 0.97, kTwoStrikeSweep = 0.95, kTwoStrikeSpread = 0.9;

/// The share of pitches he swings at when he sees them in the zone, by count: 0.6 with no
/// strikes, 0.72 with one, 0.9 with two, 0.2 at 3-0 (ESTIMATES shaped by Statcast's Z-Swing%
/// by count, league ~67 %).
double zone_swing_share(const Count& count);

class Hitter {
 public:
  /// `aim_inside`: where along his bat he aims (aim_inside() of his skill and bat).
  Hitter(const BatterSkill& skill, bool left_handed, std::uint64_t seed, double aim_inside);
  double aim_inside() const { return aim_inside_; }  ///< m, where along his bat he aims
  /// His read of `pitch` of type `type` (its name) from `pitcher` as he sees it at the commit point.
  PitchRead read(const PitchFlight& pitch, const std::string& type, const ScoutingReport& pitcher, const Count& count);
  /// Whether he offers at the pitch as he read it.
  bool swings(const PitchRead& read, const Count& count);
  /// The swing he takes at it: with two strikes a shorter, slower, steadier one.
  SwingInput swing(const PitchRead& read, const Count& count);
  const BatterSkill& skill() const { return skill_; }
  bool left_handed() const { return left_; }

 private:
  BatterSkill skill_;
  bool left_;
  double aim_inside_;
  Rng rng_;
};

}  // namespace sweetspot
