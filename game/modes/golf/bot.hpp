// A bot golfer (DESIGN §9): it reads the hole like a player — which club reaches, where to
// aim, how hard to putt — by trying the stroke on the physics it is about to play (a caddie
// who knows the course), then swings with seeded random meter errors drawn from its skill.
// It makes the game testable headless and is the opponent in the window.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "game/modes/golf/round.hpp"
#include "game/util/rng.hpp"

namespace sweetspot {

/// Where a ball lies against the line it was aimed on: metres along and to the right of the
/// line from `from` toward direction `line` (rad right of +x).
struct AlongAcross {
  double along, across;
};
AlongAcross relative(const Vec3& from, double line, const Vec3& p);

class GolfBot {
 public:
  /// A full swing's carry and total, per club of the bag: error-free on flat fairway, or as a
  /// player measured them (then `spread` is their carry's standard deviation).
  struct Stock {
    std::string club;
    double carry = 0.0, total = 0.0;  ///< m
    double spread = 0.0;              ///< m, carry standard deviation (0: not measured)
    double side_spread = 0.0;         ///< m, sideways standard deviation at landing
  };
  /// `bag`: the carries the player measured (a bag-gapping session); the clubs it lacks (or
  /// all, when empty) carry as this skill's error-free full swings on flat fairway.
  GolfBot(const Assets& assets, const GolferSkill& skill, std::uint64_t seed, std::vector<Stock> bag = {});

  /// A putt's pace: it aims to finish this far past the cup (Pelz's 17 in, 0.43 m, holes the
  /// most).
  static constexpr double kPuttPast = 0.43;  // m

  /// The stroke it means to play from where the round's ball lies: no errors. `passed_over`,
  /// when given, is set to the club it would have played but for a tree in the way of it or
  /// of its misses ("5-iron"), empty when the trees changed no club.
  StrokeInput intend(const GolfRound& round, std::string* passed_over = nullptr) const;
  /// intend() with this skill's meter errors drawn from the bot's seeded generator.
  StrokeInput plan(const GolfRound& round);
  /// A full swing with this skill's meter errors drawn (the range).
  MeterInput full_swing();

  const std::vector<Stock>& stock() const { return stock_; }
  /// `club`'s entry in the stock; nullptr when the bag has no such club.
  const Stock* stock_of(const std::string& club) const {
    const std::size_t k = stock_index(club);
    return k < stock_.size() ? &stock_[k] : nullptr;
  }
  /// The club a player of this skill would hit `distance` m (the shortest that carries it;
  /// the longest when none does); never the putter, the driver only from a tee.
  std::string suggest(double distance, bool teed) const;

 private:
  StrokeInput putt(const GolfRound& round) const;
  /// The club's place in stock_ (the bag's order, longest first); stock_.size() if absent.
  std::size_t stock_index(const std::string& club) const;
  const Assets* assets_;  // a pointer: a bot is assignable (a round restarted)
  GolferSkill skill_;
  Rng rng_;
  std::vector<Stock> stock_;
};

}  // namespace sweetspot
