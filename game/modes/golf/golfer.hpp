// Golfers: a skill level sets how fast a player swings and how far their three-click meter
// inputs stray (DESIGN §9: tour, scratch, amateur, beginner). The bots draw their errors from
// these; a human's errors are their own.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "game/content/equipment_file.hpp"
#include "physics/range.hpp"

namespace sweetspot {

struct GolferSkill {
  std::string name;           ///< "tour", "scratch", "amateur", "beginner"
  double driver_speed = 50.5; ///< m/s, full swing with the driver; every club scales with it
  /// Standard deviations of the bot's meter errors and putting: the third click's timing
  /// (ms), the power click (fraction of the chosen power), and on the green the speed (fraction)
  /// and start line (rad).
  double accuracy_sd_ms = 10.0;
  double power_sd = 0.02;
  double putt_speed_sd = 0.05;
  double putt_aim_sd = 0.012;
};

/// The four skills. Driver speeds: tour 113 mph (TrackMan PGA average), scratch 105, a
/// 15-handicap amateur 93, a beginner 80 (TrackMan's published handicap averages put the
/// scratch and 15-handicap male golfer near 105 and 93 mph). Errors: ESTIMATES chosen so a
/// tour bot's drives scatter ~±20 yd sideways (PGA TOUR fairways hit ~60 %) and each level
/// below roughly doubles the spread; putts miss by a speed (6 %) and start-line (0.8°) spread
/// that holes ~half of 2.5 m putts for a tour player (Broadie 2014, Every Shot Counts: tour
/// players hole ~50 % from 8 ft) and fewer as the skill falls. The bot reads greens
/// perfectly; its start-line spread stands for misreads too.
const std::vector<GolferSkill>& golfer_skills();
/// The skill by name; InputError listing the names.
const GolferSkill& golfer_skill(std::string_view name);
/// The skills' names, in golfer_skills() order.
std::vector<std::string> golfer_skill_names();

/// A golfer's full-swing club speed (m/s) with `club`: the club's tour speed scaled by the
/// golfer's driver speed over the tour's. The putter's is the same for everyone.
double full_swing_speed(const GolferSkill& g, const ClubInfo& club);

/// The 14-club bag every golfer carries (Rule 4.2): driver, 3- and 5-wood, hybrid, 4- to
/// 9-iron, PW, SW, LW, putter, in order from longest to shortest.
const std::vector<std::string>& golf_bag();

}  // namespace sweetspot
