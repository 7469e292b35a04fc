// Golf's formats of play scored from the players' cards (Rules of Golf, Rules 3 and 21; the
// World Handicap System for strokes received): stroke play adds the strokes; match play wins
// holes; stableford turns net strokes into points; skins gives each hole to its one best net
// score, ties carrying the skin over. Pure functions of numbers: the game (game/modes) and
// `round` feed them the cards.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sweetspot {

enum class GolfFormat { Stroke, Match, Stableford, Skins };
const char* to_string(GolfFormat f);
/// "stroke", "match", "stableford", "skins"; InputError listing them otherwise.
GolfFormat golf_format(std::string_view name);

/// A hole's score in golfers' words: "hole in one", "albatross", "eagle", "birdie", "" for
/// par, "bogey", "double bogey", "triple bogey", then "+4" and on.
std::string score_name(int strokes, int par);

/// Course handicaps: WHS Rule 6 allows up to 54; a plus handicap is not modelled.
inline constexpr int kMaxHandicap = 54;

/// The strokes a course handicap (set for 18 holes) receives over a round of `holes` holes:
/// in proportion, rounded half up (WHS Rule 6.1: a 9-hole round plays off half).
int strokes_for_round(int handicap, int holes);

/// Strokes received on each hole: the round's strokes given one per hole in the order of the
/// holes' stroke index (1 = the hardest first), again from index 1 when there are more
/// strokes than holes (Rules of Golf, Definitions "Stroke index"; WHS Appendix E).
/// `stroke_index` holds each hole's index, a permutation of 1..n.
std::vector<int> strokes_received(int handicap, const std::vector<int>& stroke_index);

/// Rule 21.1b: points from the net score against par: 0 for net double bogey or worse (or no
/// score), 1 bogey, 2 par, 3 birdie, 4 eagle, 5 albatross, 6 for four under.
int stableford_points(int par, int net_strokes);

/// One hole of a singles match. `winner` 0 or 1, -1 halved.
struct MatchHole {
  int winner = -1;
  int lead = 0;          ///< player 0's holes up after this hole (negative: player 1 up)
  std::string status;    ///< "1 up", "all square", "dormie 2", "won 3&2" (from player 0's side: "A 1 up")
};

struct MatchResult {
  std::vector<MatchHole> holes;
  int lead = 0;            ///< after the last hole played
  int decided_after = -1;  ///< hole index after which one side led by more than remained; -1 if not
  std::string result;      ///< "NAME wins 3&2", "NAME wins 1 up", "halved", "NAME 1 up after 2"
};

/// Scores a singles match (Rule 3.2) from each hole's net scores. `conceded_by[h]` is the
/// player (0/1) who conceded hole h (Rule 3.2b: a conceded hole is lost whatever the
/// strokes), -1 when neither did. The match is decided once a side leads by more holes than
/// remain (Rule 3.2a(3)); the card goes on being kept after that. `round_holes`: the holes
/// the match is over (the holes given may be fewer: a match in progress).
MatchResult score_match(const std::vector<int>& net0, const std::vector<int>& net1, const std::vector<int>& conceded_by,
                        int round_holes, const std::string& name0, const std::string& name1);

struct SkinsResult {
  std::vector<int> winner;   ///< per hole: the player who won the skins, -1 tied (carried)
  std::vector<int> value;    ///< per hole: skins won there (1 + the carried ones), 0 on a tie
  std::vector<int> skins;    ///< per player: skins won
  int unwon = 0;             ///< skins still carried after the last hole
};

/// Skins: each hole is worth one skin; the lowest net score alone takes it and every skin
/// carried to it; a tie for lowest carries it to the next hole. `net[p][h]`.
SkinsResult score_skins(const std::vector<std::vector<int>>& net);

}  // namespace sweetspot
