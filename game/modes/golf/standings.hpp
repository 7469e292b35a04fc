// Where a group's round stands: each player's gross and net scores, putts and the format's
// result over the holes the whole group has finished. The scorecard view and the JSON
// report read this one summary, so the window and `round` cannot disagree.
#pragma once

#include <optional>
#include <vector>

#include "game/modes/golf/golf_group.hpp"

namespace sweetspot {

struct PlayerStanding {
  std::vector<int> gross, putts, received, net, points;  ///< per finished hole
  int total_strokes = 0, total_putts = 0, total_net = 0, total_points = 0, total_par = 0;
};

struct Standings {
  GolfFormat format = GolfFormat::Stroke;
  std::size_t holes = 0;                 ///< holes every player has finished
  std::vector<PlayerStanding> players;
  std::optional<MatchResult> match;      ///< match play
  std::optional<SkinsResult> skins;      ///< skins
  /// Players by standing, best first: fewest net strokes (stroke), most points (stableford),
  /// most skins (skins), the match's winner (match). Ties keep the order of play.
  std::vector<int> ranking;
  /// Those tied for the best standing (one player unless a tie; both in a level match).
  std::vector<int> leaders;
};

Standings standings(const GolfGroup& group);

}  // namespace sweetspot
