// A game of baseball between two bot teams (DESIGN §9): nine hitters of a skill against a
// pitcher, pitch by pitch with counts, balls in play fielded by nine fielders, runners who
// advance by the hit and their speed (base_running.hpp: sent for an extra base when the throw
// should not beat them, and now and then thrown out), outs, runs, innings to the end the rules
// give, and the box score. Headless and seeded: the same options, the same game.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "game/modes/baseball/hitter.hpp"
#include "game/rules/baseball_game.hpp"

namespace sweetspot {

struct PitchRecord {
  PlannedPitch planned;
  PitchFlight flight;
  Count count;            ///< before the pitch
  PitchRead read;
  bool swung = false;
  SwingInput swing;
  SwingResult result;     ///< with a swing
  PitchResult call = PitchResult::Ball;
};

struct PlateAppearance {
  int inning = 1;
  bool bottom = false;
  int batter = 0;          ///< batting order index
  int outs_before = 0;
  Bases bases_before{-1, -1, -1};
  std::vector<PitchRecord> pitches;
  std::string result;      ///< strikeout, walk, hit_by_pitch, out, single, double, triple, home_run, error
  std::string description; ///< in a scorer's words: "Strikeout swinging", "Fly out to CF", ...
  int runs = 0, rbi = 0, outs_made = 0;
  /// Of `runs`, those earned (Rule 9.16): not a runner who reached on an error or was placed
  /// on second in extra innings, and not after the inning would have ended had each error
  /// been the out it should have been.
  int earned_runs = 0;
  bool sacrifice_fly = false;
  int pitcher = 0;           ///< the fielding team's pitcher (index in TeamBox::pitchers)
  bool pitching_change = false;  ///< he came in to face this batter
};

struct GameOptions {
  int innings = 9;
  static constexpr Range kInnings{1.0, 50.0};
  std::string away = "pro", home = "pro";  ///< each lineup's batter skill
  std::uint64_t seed = 1;
};

/// The batting order's sides: left-handed hitters 2nd, 4th, 6th and 9th (4 of 9: MLB's
/// left-handed batters take ~43 % of plate appearances, 2023; ESTIMATE of a lineup).
bool bats_left(int order);
/// The position each spot of the order plays (DH: the pitcher does not bat, MLB since 2022):
/// a common shape of a lineup, the table setters up the middle and the power in the middle of
/// the order (ESTIMATE; the fielding uses the league's defence whoever bats where).
const char* lineup_position(int order);

class Team {
 public:
  Team(const Assets& assets, std::string name, const BatterSkill& skill, std::uint64_t seed);
  std::string name;
  std::vector<Hitter> lineup;
  Pitcher pitcher;         ///< the one on the mound: the starter, or the last reliever in
  ScoutingReport report;   ///< of the pitcher on the mound, as the other team knows him
  int pitchers_used = 1;
  int entered_inning = 1;  ///< the inning the pitcher on the mound came in
  int entered_lead = 0;    ///< his team's lead when he came in
  /// The manager's look at his pitcher before a plate appearance.
  struct MoundVisit {
    int inning = 1;
    bool inning_start = false;  ///< before the half's first batter
    int runners = 0;            ///< on base now
    int runs_this_inning = 0;   ///< scored while this pitcher was on the mound this half
    int outs_recorded = 0;      ///< by this pitcher, the whole game
    int lead = 0;               ///< the fielding team's lead in runs (behind: negative)
  };
  /// Whether the pitcher gives way to the bullpen now; a fresh one (seeded by `seed`) is then
  /// on the mound. ESTIMATE of today's usage (MLB 2023-24: starters ~88 pitches and ~5⅓
  /// innings, most of them relieved during an inning; relievers about an inning; complete
  /// games under 1 % of starts; ~40 % of starts 6 innings or more, The Athletic 2023; those
  /// of 7 or more halved from 2015 to 2022, Verducci, SI 2024): the starter goes before an
  /// inning once he has thrown kStarterPitches, or has worked kStarterInnings unless he is
  /// cruising (under kStarterCruising pitches), and during one at kStarterLimit, or from
  /// kStarterPitches − 15 when two men are on; a reliever goes after an inning of work or
  /// kRelieverPitches, and during an inning from kRelieverPitches with a man on; anyone who
  /// has let in kBlowUpRuns this inning goes. A reliever who comes in by the kLongReliefBy
  /// inning, or with the game kBlowoutRuns either way (a mop-up man), is a long man: he
  /// covers up to kLongReliefOuts or kLongReliefPitches, as a starter's innings are covered
  /// when he leaves early and a lopsided game's are by one arm (MLB.com, "5 bullpen usage
  /// trends to know", 2017: long relievers are rarer, the average relief outing 1.04 innings
  /// in 2016; the long man's three innings or 50 pitches and the eight-run blowout: ESTIMATE);
  /// without him an early knockout used six to nine pitchers, an inning each. No more than
  /// kMaxPitchers pitch (a roster's 13, MLB Rule since 2022), the last one finishes. Over the tests' 100 games: starters 5.4
  /// innings and 89 pitches, 48 % of starts six innings or more, 12 % seven or more.
  /// Each pitcher throws left-handed as the league's do (kLeftStarterShare,
  /// kLeftRelieverShare), drawn from his seed; the report is then his.
  bool to_the_bullpen(const MoundVisit& visit, std::uint64_t seed);
  static constexpr int kStarterPitches = 90;
  static constexpr int kStarterInnings = 6;
  static constexpr int kStarterCruising = 85;  // ~14 pitches an inning through six (league ~16)
  static constexpr int kStarterLimit = 110;
  static constexpr int kRelieverPitches = 30;
  static constexpr int kLongReliefBy = 4;
  static constexpr int kLongReliefOuts = 9;
  static constexpr int kLongReliefPitches = 50;
  static constexpr int kBlowoutRuns = 8;
  static constexpr int kBlowUpRuns = 4;
  static constexpr int kMaxPitchers = 13;
  Defense defense;
  Rng fielding_rng;

 private:
  std::vector<PitchType> types_;
  ScoutingReport right_report_, left_report_;  ///< the league's pitcher scouted from each hand
};

/// One plate appearance from the count 0-0: pitches until it ends (the runners are the
/// game's business). `result` and `description` are set for the batter's part.
PlateAppearance plate_appearance(const Assets& assets, Hitter& batter, Team& fielding);

/// A walk-off other than a home run: the game ends when the winning run scores, so only the
/// runs up to it count (MLB Rule 5.08(b)), and a hit is worth only the bases the winning
/// runner took (Rule 9.06(f)). Runners reach home lead runner first. `s` before the play.
void walk_off_limit(PlateAppearance& pa, const GameSituation& s, std::vector<int>& scored);

struct GameRecord {
  GameOptions options;
  std::vector<PlateAppearance> plate_appearances;
  TeamBox away, home;
  int innings_played = 0;
  bool walk_off = false;
  bool stopped_tied = false;  ///< still tied after 40 extra innings (never happened in MLB)
};

/// Plays the game; InputError for innings out of range or an unknown skill.
GameRecord play_game(const Assets& assets, const GameOptions& options);

/// League rates over plate appearances (the note's table; the tests' bands).
struct BattingRates {
  int pa = 0, pitches = 0, swings = 0, whiffs = 0, fouls = 0, balls_in_play = 0;
  double k_rate = 0.0, bb_rate = 0.0, hbp_rate = 0.0, hr_rate = 0.0, avg = 0.0, obp = 0.0, slg = 0.0, babip = 0.0;
  double whiff_per_swing = 0.0, foul_per_pitch = 0.0, swing_rate = 0.0, zone_rate = 0.0, chase_rate = 0.0;
  double squared_up_per_swing = 0.0, blast_per_swing = 0.0, mean_bat_speed_mph = 0.0, mean_swing_length_ft = 0.0;
};
/// Over the plate appearances of the team batting in the bottom (`home`) or top halves.
BattingRates batting_rates(const std::vector<PlateAppearance>& pas, int which /* 0 away, 1 home, 2 both */);

}  // namespace sweetspot
