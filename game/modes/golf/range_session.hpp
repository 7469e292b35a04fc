// The practice range and its bag-gapping session: full swings with each club on a flat range
// (the same physics and air as the course), each shot's carry, total and side recorded, and
// per club the mean and the spread: the player's own bag, which the caddie and the map's
// rings then use. A bot of a skill hits them headless; the window's player hits them by hand.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "game/content/bag_file.hpp"
#include "game/modes/golf/bot.hpp"

namespace sweetspot {

struct RangeShot {
  std::string club;
  double carry = 0.0, total = 0.0, side = 0.0;  ///< m; side + right of the target line
};

class RangeSession {
 public:
  RangeSession(const Assets& assets, const GolferSkill& skill, const Environment& air = {});
  /// One full swing with `club` and these meter inputs, recorded. InputError for a club not in
  /// the bag (or the putter). `shot`, when given, receives the physics with its samples (for
  /// drawing it).
  const RangeShot& hit(const std::string& club, const MeterInput& meter, ShotResult* shot = nullptr);
  const std::vector<RangeShot>& shots() const { return shots_; }
  /// Per club hit, longest first: mean carry and total, their spreads (sample standard
  /// deviation; 0 for a single shot), the shot count. Of the first `first` shots only: a
  /// view leaves out the ball still in the air, whose carry it has not shown yet.
  Bag bag(const std::string& player, std::size_t first = std::numeric_limits<std::size_t>::max()) const;
  /// Which way `club` misses, over the first `first` shots: the landings' mean side of the
  /// target line (m, + right) and their sample standard deviation about it (0 under two).
  struct SideMiss {
    double mean = 0.0;
    double sd = 0.0;
    int shots = 0;
  };
  SideMiss side_miss(const std::string& club, std::size_t first = std::numeric_limits<std::size_t>::max()) const;

 private:
  const Assets* assets_;  // a pointer: a session is assignable (a new session)
  GolferSkill skill_;
  Environment air_;
  std::vector<RangeShot> shots_;
};

/// A bag-gapping session by a bot of `skill`: `shots` full swings with each club of the bag
/// but the putter, its meter errors drawn from `seed`.
Bag gap_bag(const Assets& assets, const GolferSkill& skill, int shots, std::uint64_t seed);

/// The caddie's stock from a measured bag.
std::vector<GolfBot::Stock> bag_stock(const Bag& bag);

}  // namespace sweetspot
