// Baseball's rules for a game (DESIGN §9), apart from any batted ball's physics: the count
// (MLB Rules 5.05, 5.09: four balls walk, three strikes retire the batter, a foul is a strike
// except with two strikes, a caught foul tip is a strike with any count), forced runners, the
// end of a game (Rule 7.01: the home team does not bat in the last inning when it leads; a
// game tied after the last scheduled inning goes on; the home team winning in its last half
// ends the game at once) and the box score's lines, which must add up.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace sweetspot {

struct Count {
  int balls = 0, strikes = 0;
};

enum class PitchResult { Ball, CalledStrike, SwingingStrike, Foul, FoulTip, InPlay, HitByPitch };
const char* to_string(PitchResult r);

enum class PlateEnd { None, Strikeout, Walk, HitByPitch, InPlay };

/// The count after a pitch, and whether the plate appearance ends with it.
PlateEnd apply_pitch(Count& count, PitchResult result);

/// Runners on first, second, third: the batting order's index of each, −1 for none.
using Bases = std::array<int, 3>;
/// A walk or hit-by-pitch: the batter to first, each runner forced along; returns the runs
/// forced in.
int force_advance(Bases& bases, int batter);

/// Where a game stands between plate appearances.
struct GameSituation {
  int scheduled = 9;       ///< innings scheduled
  int inning = 1;          ///< 1-based
  bool bottom = false;     ///< the home team bats
  int outs = 0;
  int away_runs = 0, home_runs = 0;
};
/// Whether the game is over: after a half-inning ends (outs = 3) or at once when the home
/// team takes the lead in the bottom of the last scheduled inning or later.
bool game_over(const GameSituation& s);

struct BattingLine {
  int pa = 0, ab = 0, r = 0, h = 0, doubles = 0, triples = 0, hr = 0, rbi = 0, bb = 0, so = 0, hbp = 0, sf = 0;
  int total_bases() const { return h + doubles + 2 * triples + 3 * hr; }
  BattingLine& operator+=(const BattingLine& o);
};

struct PitchingLine {
  int outs = 0, h = 0, r = 0, bb = 0, so = 0, hr = 0, hbp = 0, pitches = 0, strikes = 0, batters = 0;
  PitchingLine& operator+=(const PitchingLine& o);
};

/// One team's side of the box score.
struct TeamBox {
  std::string name;
  std::vector<int> runs_by_inning;  ///< one entry per half it batted
  int runs = 0, hits = 0, errors = 0, left_on_base = 0;
  std::vector<BattingLine> batting;  ///< by batting order
  PitchingLine pitching;             ///< its pitchers together, against the other team
  std::vector<PitchingLine> pitchers;///< each pitcher in the order they pitched
};

/// Every way the lines of a box score must agree (the runs by inning add up to the runs, the
/// batters' runs and hits to the team's, the opponents' pitching to the batting, their
/// pitchers' lines to their staff's, a plate appearance is an at-bat, a walk, a hit-by-pitch
/// or a sacrifice fly); "" when they all do, otherwise the first that does not.
std::string box_score_mismatch(const TeamBox& batting, const TeamBox& fielding);

}  // namespace sweetspot
