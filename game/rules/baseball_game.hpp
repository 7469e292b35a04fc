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
/// An inning as it is said: "1st", "2nd", "3rd", "4th", ..., "11th", "21st".
std::string ordinal(int n);

struct BattingLine {
  int pa = 0, ab = 0, r = 0, h = 0, doubles = 0, triples = 0, hr = 0, rbi = 0, bb = 0, so = 0, hbp = 0, sf = 0;
  int total_bases() const { return h + doubles + 2 * triples + 3 * hr; }
  BattingLine& operator+=(const BattingLine& o);
};

/// A pitcher's decision in a game that was won (MLB Rules 9.17 and 9.19).
enum class Decision { None, Win, Loss, Save };
/// "W", "L", "S", or "" for none.
const char* to_string(Decision d);

struct PitchingLine {
  int outs = 0, h = 0, r = 0, bb = 0, so = 0, hr = 0, hbp = 0, pitches = 0, strikes = 0, batters = 0;
  /// Runs charged to him that were earned: not scored by a batter who reached on an error, nor
  /// by extra innings' placed runner (Rule 9.16; the game's errors are rare, and a run that an
  /// error let score otherwise is counted earned).
  int er = 0;
  Decision decision = Decision::None;
  /// His team's runs less the other team's when he came in (a save needs a lead of 1-3).
  int lead_at_entry = 0;
  /// Runners on base when he came in (Rule 9.19(b)(2): the tying run on base, at bat or on
  /// deck), and of those the ones a pitcher before him let on (he came in during an inning)
  /// and how many of his inherited runners scored (Rule 9.16(g): charged to the pitcher who
  /// let them on, not to him).
  int runners_at_entry = 0, inherited = 0, inherited_scored = 0;
  bool left_handed = false;  ///< he throws left-handed (the box's T column)
  PitchingLine& operator+=(const PitchingLine& o);  ///< the counts; not the decision or the lead
};

/// One team's side of the box score.
struct TeamBox {
  std::string name;
  std::vector<int> runs_by_inning;  ///< one entry per half it batted
  int runs = 0, hits = 0, errors = 0, left_on_base = 0;
  int placed_runners = 0;  ///< extra innings' runners placed on second (Rule 7.01(b)): on base without a plate appearance
  std::vector<BattingLine> batting;  ///< by batting order
  PitchingLine pitching;             ///< its pitchers together, against the other team
  std::vector<PitchingLine> pitchers;///< each pitcher in the order they pitched
};

/// Which pitcher each runner is charged to (MLB Rule 9.16(g)): the one who let him on base,
/// not one who relieved him while the runner stood there. A batter who reaches on a fielder's
/// choice that puts out a runner takes over that runner's charge: the rule charges "each
/// pitcher with the number of runners he put on base, rather than with the individual
/// runners". Runners are the batting order's 0..8, pitchers TeamBox::pitchers' indices.
class RunnerCharges {
 public:
  /// `runner` reached base against `pitcher` (a hit, a walk, an error, extra innings' placed runner).
  void reached(int runner, int pitcher);
  /// The batter reached on a fielder's choice that put `out_runner` out.
  void fielders_choice(int batter, int out_runner);
  /// The pitcher charged with `runner`'s run when he scores.
  int charged(int runner) const;

 private:
  std::array<int, 9> pitcher_{};
};

/// One plate appearance as the decisions read it: the fielding team (0 away, 1 home), the
/// index of its pitcher in TeamBox::pitchers, the score after it, and the pitcher charged with
/// each run it brought in, in the order they scored (empty: the one pitching).
struct ScoreAfter {
  int fielding = 0;
  int pitcher = 0;
  int away = 0, home = 0;
  std::vector<int> charged;
};

/// Credits the win, the loss and a save to the pitchers of `away` and `home` from the game's
/// plate appearances in order (`log`), as the official scorer does; none when the game ended
/// tied. Rule 9.17: the loser is the pitcher charged with the run that put the winners ahead
/// for good, the winner their pitcher of record then, but a starter needs five innings (four
/// in a game of five or fewer `scheduled` innings), else the reliever the scorer judges most
/// effective (here: the one with the most outs). Rule 9.19: the winners' finishing pitcher,
/// not the winner, with an out, saves it when he came in leading by at most three and pitched
/// an inning, or with the tying run on base, at bat or on deck (a lead of at most the runners
/// on base and two), or pitched three innings.
void assign_decisions(const std::vector<ScoreAfter>& log, int scheduled, TeamBox& away, TeamBox& home);

/// "" when the decisions agree with the score (a decided game has one win and one loss, on the
/// two teams, and at most one save, the winners', not the winner's; a tied game none) and every
/// pitcher's earned runs are among his runs, otherwise the first that does not.
std::string decisions_mismatch(const TeamBox& away, const TeamBox& home);

/// Every way the lines of a box score must agree (the runs by inning add up to the runs, the
/// batters' runs and hits to the team's, the opponents' pitching to the batting, their
/// pitchers' lines to their staff's, a plate appearance is an at-bat, a walk, a hit-by-pitch
/// or a sacrifice fly; no pitcher's inherited runners scored more than he inherited; the proof,
/// plate appearances and placed runners = runs + left on base + the opponents' putouts); "" when
/// they all do, otherwise the first that does not.
std::string box_score_mismatch(const TeamBox& batting, const TeamBox& fielding);

}  // namespace sweetspot
