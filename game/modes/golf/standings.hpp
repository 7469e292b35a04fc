// Where a group's round stands: each player's gross and net scores, putts, fairways and greens
// in regulation, and the format's result over the holes the whole group has finished. The
// scorecard view and the JSON report read this one summary, so the window and `round`
// cannot disagree.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "game/modes/golf/golf_group.hpp"

namespace sweetspot {

struct PlayerStanding {
  std::vector<int> gross, putts, received, net, points;  ///< per finished hole
  /// Per finished hole: it has a score (holed, or picked up at the stroke limit). A match's
  /// hole conceded, or left once the other side conceded it, has none: its strokes are not
  /// a score, and the totals and "to par" leave it out (they would read 2 strokes on a par 4
  /// as two under).
  std::vector<bool> scored;
  std::vector<TeeShot> tee_shot;   ///< per finished hole (None on a par 3)
  std::vector<bool> green_in_regulation;
  /// Over the scored holes only (`scored`): strokes, putts and net; points over all.
  int total_strokes = 0, total_putts = 0, total_net = 0, total_points = 0;
  int total_par = 0;     ///< the par of the scored holes
  int holes_scored = 0;  ///< how many of the finished holes have a score
  /// Fairways hit of the scored par 4s and 5s, and greens in regulation of the scored holes.
  int fairways_hit = 0, fairways = 0, greens_in_regulation = 0;
  int greens = 0;  ///< holes that count toward greens in regulation: the scored ones

  /// The card's total: the strokes, and over how many holes and their par when some have no
  /// score (a match's conceded hole), so "7" does not stand against the par of three holes
  /// ("7 in 2 holes (par 8)" under a par column of 12).
  std::string total_text(std::size_t holes) const {
    std::string out = std::to_string(total_strokes);
    if (static_cast<std::size_t>(holes_scored) < holes)
      out += " in " + std::to_string(holes_scored) + (holes_scored == 1 ? " hole" : " holes") + " (par " + std::to_string(total_par) + ")";
    return out;
  }

  /// Strokes and putts over holes [from, to) that have a score, and the stableford points of
  /// every hole in it (a hole picked up scores 0): a card's nine (Out, In).
  struct Sum {
    int strokes = 0, putts = 0, points = 0;
  };
  Sum sum(std::size_t from, std::size_t to) const {
    Sum out;
    for (std::size_t h = from; h < to && h < scored.size(); ++h) {
      if (h < points.size()) out.points += points[h];
      if (!scored[h]) continue;
      out.strokes += gross[h];
      out.putts += putts[h];
    }
    return out;
  }
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
  /// Those tied for the best standing (one player unless a tie; both in a level match; none
  /// in skins while no skin has been won).
  std::vector<int> leaders;
};

Standings standings(const GolfGroup& group);

/// A player's running score while the group plays `hole`: the standings' scored holes and,
/// once he has finished that hole (holed or picked up) while others play on, that hole too
/// (beside "holed in 2" the total before it would read as a stale sum). `stroke_untold`: his
/// last stroke, on `hole`, is still in the air: a hole it finished is not yet his (the
/// panel tells a stroke once the ball stops).
struct RunningTotal {
  int strokes = 0, par = 0, holes = 0;
};
RunningTotal running_total(const GolfGroup& group, const Standings& standings, int player, std::size_t hole,
                           bool stroke_untold = false);

}  // namespace sweetspot
