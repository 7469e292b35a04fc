// A player's bag as they measured it at the range (a bag-gapping session): per club, the
// mean carry and total, the carry's spread and the sideways spread, and how many shots
// measured them. `range --bag-out` writes it; `play --bag` and `round` give it to the caddie,
// who then suggests clubs by the player's own distances.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "game/content/assets.hpp"
#include "physics/range.hpp"

namespace sweetspot {

struct BagClub {
  std::string club;
  double carry = 0.0;      ///< m, mean carry
  double total = 0.0;      ///< m, mean total (carry and roll)
  double carry_sd = 0.0;   ///< m, the carry's standard deviation
  double side_sd = 0.0;    ///< m, sideways at landing, standard deviation about the aim line
  int shots = 0;           ///< shots measured
  static constexpr Range kDistance{0.0, 450.0};  ///< m: past any long-drive record (~440 m total)
  /// m: a full swing's mean carry; a metre is a whiff, not a club's number.
  static constexpr Range kCarry{1.0, 450.0};
  static constexpr Range kShots{1.0, 1000.0};
};

struct Bag {
  std::string player;
  std::string skill;           ///< the golfer skill that swung (its swing speed)
  std::vector<BagClub> clubs;  ///< longest first
};

/// Reads a bag file; InputError naming file:line and the key (an unknown club, a distance out
/// of range, a carry longer than the total, the same club twice, the putter, a skill not in
/// `skills`: the game's golfer skills, which live above this layer).
Bag load_bag(const Assets& assets, const std::filesystem::path& path, const std::vector<std::string>& skills);
/// The bag as TOML that load_bag() reads back to the same numbers.
std::string bag_toml(const Bag& bag);

}  // namespace sweetspot
