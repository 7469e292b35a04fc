// A pitcher who pitches (DESIGN §9): an arsenal (each type's mix, speed and spin with their
// spread, release and extension from pitches.toml), a plan by count (the zone when behind,
// chase pitches when ahead, more fastballs when he must throw a strike) and command (he
// misses his spot by a seeded amount). Seeded: the same seed, the same pitches.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "game/modes/baseball/pitching.hpp"
#include "game/rules/baseball_game.hpp"
#include "game/util/rng.hpp"

namespace sweetspot {

/// The baseball's radius (assets' "mlb"), m: the strike zone and the batter's body are judged
/// against any part of the ball.
inline constexpr double kBaseballRadius = 0.0369;

/// The strike zone at the plate for the league's typical batter: 17 in wide (the plate),
/// 1.6 to 3.5 ft high (MLB Rule 2.00 defines it by the batter's stance). Ball-centre limits
/// for a ball of radius `r`: any part of the ball over any part of the zone.
struct StrikeZone {
  static constexpr double kHalfWidth = 0.2159;  ///< m, 17 in / 2
  static constexpr double kLow = 1.6 * 0.3048, kHigh = 3.5 * 0.3048;  ///< m
  static bool contains(const Vec3& plate, double r);
  /// How far outside the zone the ball's centre passes (m, 0 inside): the larger of the
  /// side and height misses.
  static double outside_by(const Vec3& plate, double r);
};

struct PitcherProfile {
  std::string name = "league average";
  bool left_handed = false;
  std::vector<PitchType> arsenal;  ///< usage = the share of his pitches
  /// Pitch-to-pitch spread of one pitcher's type: 1.0 mph and 60 rpm (one standard deviation;
  /// ESTIMATE from Statcast game logs, where a starter's four-seamers span ~±2 mph and
  /// ~±120 rpm over a start).
  double speed_sd = 0.447, spin_rpm_sd = 60.0;
  /// How far from his spot the ball crosses the plate, one standard deviation per axis (m).
  /// PITCHf/x studies of the catcher's target put the average MLB miss near a foot
  /// (Sportvision COMMANDf/x, 2013); 0.20 m per axis is a mean miss of 0.25 m (10 in).
  double command_sd = 0.16;
};

/// The league's pitcher: the six types at their league averages and usage, thrown with the
/// right hand or, mirrored, the left.
PitcherProfile league_average_pitcher(const std::vector<PitchType>& types, bool left_handed = false);

/// The share of the league's pitchers who throw left-handed, starters and relievers:
/// left-handers threw 30.5 % of MLB's pitches in the first three innings and 22.4 % from the
/// 8th on (Lookout Landing, "Lefties in late innings", 2008, from the season's pitch data).
inline constexpr double kLeftStarterShare = 0.305, kLeftRelieverShare = 0.224;
/// Whether the pitcher drawn from `seed` throws left-handed, one of a `share` of them.
bool draws_left_handed(std::uint64_t seed, double share);

/// One pitch's plan: what and where he means to throw, then where his command puts it.
struct PlannedPitch {
  PitchCall call;          ///< the target after the miss (what is thrown)
  double aim_height = 0.0, aim_side = 0.0;  ///< the spot he meant, m
  bool in_zone_intent = false;
};

class Pitcher {
 public:
  Pitcher(PitcherProfile profile, std::uint64_t seed);
  /// The next pitch to a batter (`batter_left`: a left-handed batter) at this count.
  PlannedPitch next(const Count& count, bool batter_left);
  const PitcherProfile& profile() const { return profile_; }
  int pitches_thrown() const { return thrown_; }

 private:
  std::size_t choose_type(const Count& count);  ///< index into the arsenal

  PitcherProfile profile_;
  Rng rng_;
  int thrown_ = 0;
  std::vector<double> meant_;  ///< each type's zone share as he means it, through his command
  double meant_mix_ = 0.5;     ///< his mix's
};

/// The share of pitches he means for the zone at a count: 0.9-0.95 with three balls, 0.3 at
/// 0-2 and 1-2, 0.58 even, 0.08 more for each ball the batter is ahead.
/// ESTIMATE shaped by Statcast's zone rate by count (league Zone% ~49 %, lowest at 0-2,
/// highest at 3-0).
double zone_intent(const Count& count);
/// That intent for one type of his arsenal: the count's odds times the type's zone odds
/// (PitchType::zone_share) over his mix's, usage-weighted: over his mix the intent is kept.
/// With his command (`command_sd`, m), the share he means is the one that makes the type's
/// zone_share cross the zone, given how often a pitch meant for it, or meant to be
/// chased, does. 0: perfect command, the shares as published.
double type_zone_intent(double intent, const PitchType& type, const std::vector<PitchType>& arsenal, double command_sd = 0.0);

/// A right-handed batter's hands in his stance, held at his back shoulder over the inner line
/// of the box: m from the middle of the plate toward him, m up, and the reach of his fists and
/// gloves about that point (ESTIMATES; the cage's figure holds the bat there, batter_figure).
inline constexpr double kStanceHandsFromMiddle = 0.45, kStanceHandsHigh = 1.45, kStanceHandsReach = 0.05;

/// Where a pitch crossing at `plate` hits a batter standing in the box on his side (`left`:
/// a left-hander, on the first-base side): his body starts 0.55 m from the middle of the plate
/// (the box's inner line is 6 in off the plate's edge, the front of a batter's body ~10 in
/// beyond it; ESTIMATE) and spans 0.3–1.8 m up; his hands reach in over the box's line (the
/// hands are the batter's, Rule 5.05(b)(2): a pitch that hits them is a hit-by-pitch).
bool hits_batter(const Vec3& plate, bool left, double ball_radius);

}  // namespace sweetspot
