// The window's live game: the player's side ("You", the visitors) bats through a lineup
// against the league's pitcher, and the league's lineup ("League", the home side) bats against
// his team's pitchers and fielders in the bottom half, played out by the game's own plate
// appearances (ball_game.hpp) the moment his side is retired. The cage keeps his count and
// throws his pitches; this keeps what a game adds to them: the outs, the runners (moved on
// each ball in play as a game's half-inning moves them, base_running.hpp: forced, sent for an
// extra base, thrown out, doubled off), the runs, both line scores and the end (Rule 7.01:
// nine innings, the home side not batting in the 9th when ahead, a walk-off, extra innings
// with a runner placed on second).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "game/modes/baseball/ball_game.hpp"
#include "game/modes/baseball/base_running.hpp"

namespace sweetspot {

class LiveInning {
 public:
  LiveInning(const Assets& assets, std::uint64_t seed);

  /// What the scoreboard shows.
  struct Board {
    int inning = 1;
    int outs = 0;
    Bases bases{-1, -1, -1};        ///< the batting order's index of the runner on 1st, 2nd, 3rd; -1 empty
    std::vector<int> runs_by_inning{0};  ///< the line score, this inning last
    int hits = 0, left_on_base = 0;  ///< the game's
    bool side_retired = false;       ///< the last plate appearance made the third out; the next one's first pitch opens the next inning
    /// The last plate appearance's part for the runners in a scorer's words ("2 runs score",
    /// "runner out at 3rd"); with the side retired, the inning's line.
    std::string note;
    /// The last ball in play as the game scored it when its runners changed the fielders'
    /// words ("Grounded into a double play, SS to 2B to 1B" for "Ground out, SS to 1B"), else
    /// empty.
    std::string scored_as;
    /// The home side's line score (a column for each bottom half played), hits and the last
    /// bottom half in words ("Bottom of the 3rd: League 2 runs, 3 hits (Home run to LF, 2
    /// runs)"), told with the side retired and kept through the next plate appearance.
    std::vector<int> their_runs_by_inning;
    int their_hits = 0;
    std::string their_half;
    /// The game is over: its last line ("Final: League 5, You 3"; "... in 10 innings").
    bool final = false;
    std::string final_line;
    int runs() const;
    int their_runs() const;
  };
  static constexpr int kInnings = 9;
  const Board& board() const { return board_; }
  /// The batting side (its hitters' aim along the bat), and what it knows of the pitcher it
  /// faces: the league's, as the cage's.
  const Team& batting() const { return batting_; }
  const ScoutingReport& report() const { return fielding_.report; }

  /// The next plate appearance's first pitch: after a third out the next inning opens (the
  /// bases empty, no outs; from the 10th a runner on second), and the last play's note, read
  /// between batters, is cleared. Nothing once the game is over.
  void next_batter();

  /// The plate appearance that just ended: `result` "strikeout", "walk", "hit_by_pitch" or a
  /// ball in play's BattedOutcome name ("out", "single", ..., "error"), `last` its last pitch
  /// (for a ball in play, with the swing and its fielding play).
  void end_plate_appearance(const std::string& result, const PitchRecord& last);

 private:
  /// The home side's half of this inning, batter by batter until three outs or a walk-off;
  /// then the game's end if it is over.
  void play_their_half();

  const Assets& assets_;
  std::uint64_t seed_;
  Team batting_, fielding_;
  HalfInning half_;
  Rng throws_;
  int batter_ = 0;  ///< the batting order's spot up now
  int inning_hits_ = 0;
  int their_batter_ = 0;        ///< the home lineup's spot up next
  int mound_outs_ = 0;          ///< by the player's side's pitcher now on the mound
  int mound_runs_ = 0;          ///< let in by him this half
  Board board_;
};

/// "runners on 1st and 3rd", "bases loaded", "bases empty".
std::string runners_text(const Bases& b);

}  // namespace sweetspot
