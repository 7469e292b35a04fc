// Game-mode benchmarks (DESIGN §8): what a player waits for when a bot plays. A
// bot round of the links (every stroke flown and rolled to rest on the holes' worlds) and a
// home-run derby (every pitch flown, struck and flown to the field), in ms of wall time.
#pragma once

#include "game/content/assets.hpp"

namespace sweetspot::bench {

/// ms per round of the default course played by the tour bot (seed 1), worlds loaded before
/// timing; the mean over `rounds` rounds (≥ 1).
double bench_bot_round_ms(const Assets& assets, int rounds);
/// ms per home-run derby (10 outs) of the pro bot batter (seed 2), the mean over `derbies`.
double bench_derby_ms(const Assets& assets, int derbies);
/// Nine-inning bot games (pro lineups against the league's pitcher), seeds 1..games: ms per
/// game, and µs per pitch, which stays comparable when a change to the game's rules or
/// players makes the same seeds play longer or shorter games.
struct GameBench {
  double ms_per_game = 0.0, us_per_pitch = 0.0;
};
GameBench bench_game(const Assets& assets, int games);

}  // namespace sweetspot::bench
