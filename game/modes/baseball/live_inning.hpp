// The window's live game: the player bats through a lineup against the league's pitcher, inning
// after inning. The cage keeps the count and throws the pitches; this keeps what a game adds to
// them: the outs, the runners (moved on each ball in play as a game's half-inning moves them,
// base_running.hpp: forced, sent for an extra base, thrown out, doubled off), the runs, and the
// line score. Three outs retire the side, and the next plate appearance opens the next inning
// with the bases empty.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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
    int runs() const;
  };
  const Board& board() const { return board_; }
  /// The batting side (its hitters' aim along the bat), and what it knows of the pitcher it
  /// faces: the league's, as the cage's.
  const Team& batting() const { return batting_; }
  const ScoutingReport& report() const { return fielding_.report; }

  /// The next plate appearance's first pitch: after a third out the next inning opens (the
  /// bases empty, no outs), and the last play's note, read between batters, is cleared.
  void next_batter();

  /// The plate appearance that just ended: `result` "strikeout", "walk", "hit_by_pitch" or a
  /// ball in play's BattedOutcome name ("out", "single", ..., "error"), `last` its last pitch
  /// (for a ball in play, with the swing and its fielding play).
  void end_plate_appearance(const std::string& result, const PitchRecord& last);

 private:
  Team batting_, fielding_;
  HalfInning half_;
  Rng throws_;
  int batter_ = 0;  ///< the batting order's spot up now
  int inning_hits_ = 0;
  Board board_;
};

/// "runners on 1st and 3rd", "bases loaded", "bases empty".
std::string runners_text(const Bases& b);

}  // namespace sweetspot
