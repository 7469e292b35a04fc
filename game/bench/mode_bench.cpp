#include "game/bench/mode_bench.hpp"

#include <algorithm>
#include <chrono>

#include "game/content/course_file.hpp"
#include "game/modes/baseball/ball_game.hpp"
#include "game/modes/baseball/session.hpp"
#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/golfer.hpp"
#include "game/modes/golf/round.hpp"

namespace sweetspot::bench {
namespace {

using Clock = std::chrono::steady_clock;

int play_round(const Assets& assets) {
  GolfRound round(assets, load_course(assets, "links"), golfer_skill("tour"));
  GolfBot bot(assets, golfer_skill("tour"), 1);
  while (!round.finished()) round.play(bot.plan(round));
  return round.total_strokes();
}

}  // namespace

double bench_bot_round_ms(const Assets& assets, int rounds) {
  play_round(assets);  // loads the holes' worlds and the course: not part of a round's time
  const auto t0 = Clock::now();
  int strokes = 0;
  for (int i = 0; i < std::max(rounds, 1); ++i) strokes += play_round(assets);
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return strokes > 0 ? ms / std::max(rounds, 1) : 0.0;
}

double bench_derby_ms(const Assets& assets, int derbies) {
  const SessionOptions derby;  // 10 outs
  const auto run = [&] {
    BotBatter bot(assets, batter_skill("pro"), 2);
    return run_session(assets, derby, bot, 2).size();
  };
  run();  // loads the ballpark
  const auto t0 = Clock::now();
  std::size_t swings = 0;
  for (int i = 0; i < std::max(derbies, 1); ++i) swings += run();
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return swings > 0 ? ms / std::max(derbies, 1) : 0.0;
}

GameBench bench_game(const Assets& assets, int games) {
  GameOptions o;  // nine innings, pro lineups
  o.innings = 1;
  play_game(assets, o);  // loads the ballpark and the pitch types
  o.innings = 9;
  const auto t0 = Clock::now();
  std::size_t pitches = 0;
  for (int i = 0; i < std::max(games, 1); ++i) {
    o.seed = static_cast<std::uint64_t>(i + 1);
    for (const PlateAppearance& pa : play_game(assets, o).plate_appearances) pitches += pa.pitches.size();
  }
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  if (pitches == 0) return {};
  return {ms / std::max(games, 1), 1000.0 * ms / static_cast<double>(pitches)};
}

}  // namespace sweetspot::bench
