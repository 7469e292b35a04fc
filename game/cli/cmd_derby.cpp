// `sweetspot derby`: a bot batter in a home-run derby (until N outs), an at-bat or batting
// practice, headless (DESIGN §9 JSON); `--plot FILE.png` draws the session's spray chart.
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/render/image.hpp"
#include "game/report/report.hpp"
#include "game/modes/baseball/batting.hpp"
#include "game/modes/baseball/session.hpp"
#include "game/report/session_json.hpp"
#include "game/report/box_score.hpp"
#include "game/render/spray_chart.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"
#include "physics/range.hpp"

namespace sweetspot::cli {
namespace {

struct DerbyOptions {
  std::string bot = "pro";
  std::uint64_t seed = 1;
  SessionOptions session;
  bool json = false;
  std::string plot;
  int innings = 9;
  int games = 1;
  static constexpr Range kGames{1.0, 1000.0};
};

// `session_flag`: a session's --outs or --swings as given, which a game does not take.
int run_game(const Assets& assets, const DerbyOptions& o, const std::string& session_flag) {
  if (!session_flag.empty()) throw InputError(session_flag + ": a game counts innings (--innings)");
  if (o.session.left_handed) throw InputError("--left: a game's lineups mix left- and right-handed batters");
  check_range("--innings", o.innings, GameOptions::kInnings, "");
  check_range("--games", o.games, DerbyOptions::kGames, "");
  if (o.json && o.games != 1) throw InputError("--json: one game at a time (--games 1)");
  if (!o.plot.empty()) throw InputError("--plot: the spray chart is for derby, at-bat and practice sessions");
  GameOptions g;
  g.innings = o.innings;
  g.away = g.home = o.bot;
  batter_skill(o.bot);  // an unknown skill is refused before any pitch
  std::vector<PlateAppearance> all;
  for (int i = 0; i < o.games; ++i) {
    g.seed = o.seed + static_cast<std::uint64_t>(i);
    GameRecord game = play_game(assets, g);
    if (o.json) {
      std::cout << json_text(game_json(game)) << "\n";
      return 0;
    }
    if (o.games == 1) {
      int half_shown = -1;  // inning * 2 + bottom of the last line printed
      for (const PlateAppearance& pa : game.plate_appearances) {
        const int half = 2 * pa.inning + (pa.bottom ? 1 : 0);
        // An extra inning's half opens with its runner on second (MLB Rule 7.01(b)): say so,
        // or a run he scores comes from nowhere in the play-by-play.
        if (half != half_shown && pa.inning > o.innings && pa.bases_before[1] >= 0)
          std::printf("%-6s %-2d %-6s #%d  %s\n", pa.bottom ? "bottom" : "top", pa.inning, pa.bottom ? "home" : "away",
                      pa.bases_before[1] + 1, "starts on 2nd (extra innings)");
        half_shown = half;
        if (pa.pitching_change) std::printf("%-6s %-2d %s\n", pa.bottom ? "bottom" : "top", pa.inning, pitching_change_text(pa).c_str());
        const std::string runs = pa.runs == 1 ? "1 run scores" : pa.runs > 1 ? std::to_string(pa.runs) + " runs score" : "";
        // The runs in their column; a description too long for it takes them after a comma
        // ("Grounded into a double play, 3B to 2B to 1B, 1 run scores").
        constexpr std::size_t kColumn = 32;
        const std::string play = pa.description.size() >= kColumn && !runs.empty() ? pa.description + "," : pa.description;
        char line[512];
        std::snprintf(line, sizeof line, "%-6s %-2d %-6s #%d  %-*s %s", pa.bottom ? "bottom" : "top", pa.inning,
                      pa.bottom ? "home" : "away", pa.batter + 1, static_cast<int>(kColumn), play.c_str(), runs.c_str());
        std::string text = line;
        text.erase(text.find_last_not_of(' ') + 1);  // the padding is for the runs column only
        std::printf("%s\n", text.c_str());
      }
      std::printf("\n%s", box_score_text(game).c_str());
    } else {
      std::printf("game %d (seed %llu): away %d, home %d in %d innings\n", i + 1, static_cast<unsigned long long>(g.seed),
                  game.away.runs, game.home.runs, game.innings_played);
    }
    all.insert(all.end(), std::make_move_iterator(game.plate_appearances.begin()),
               std::make_move_iterator(game.plate_appearances.end()));
  }
  std::printf("\n%s", rates_text(batting_rates(all, 2), "two " + o.bot + "-bot lineups against league-average pitching").c_str());
  return 0;
}

/// A count flag refused in int_range's words ("1e20 is not a whole number", "2000000 is out
/// of range") against the model's own range, before any of the modes' checks.
CLI::Validator whole_in(const Range& r) { return int_range<int>(static_cast<int>(r.min), static_cast<int>(r.max)); }

RunFn setup_derby(CLI::App& sub) {
  auto o = std::make_shared<DerbyOptions>();
  sub.add_option("--bot", o->bot, "batter skill: pro or amateur (default pro)")
      ->check(checked_by([](const std::string& t) { batter_skill(t); }, "SKILL"));
  sub.add_option("--seed", o->seed, "seed of the pitcher's and the batter's errors, 0..18446744073709551615 (default 1)")->check(kSeedText);
  auto* outs = sub.add_option("--outs", o->session.outs, "derby: outs before it ends, 1..50 (default 10)")
                   ->check(whole_in(SessionOptions::kOuts));
  sub.add_option("--mode", o->session.mode, "derby (default), at-bat, practice or game (two bot lineups against bot pitchers)");
  auto* innings = sub.add_option("--innings", o->innings, "game: innings scheduled, 1..50 (default 9)")
                      ->check(whole_in(GameOptions::kInnings));
  auto* games = sub.add_option("--games", o->games, "game: games in a row (seeds S, S+1, ...) with their league rates, 1..1000 (default 1)")
                    ->check(whole_in(DerbyOptions::kGames));
  auto* swings = sub.add_option("--swings", o->session.swings, "practice: pitches, 1..500 (default 20)")
                     ->check(whole_in(SessionOptions::kSwings));
  sub.add_flag("--left", o->session.left_handed, "a left-handed batter");
  sub.add_flag("--json", o->json, "print the DESIGN §9 JSON");
  sub.add_option("--plot", o->plot, "write the session's spray chart (PNG)");
  return [o, outs, swings, innings, games](const Assets& assets) -> int {
    // A flag of another mode would be ignored without a word: refuse it.
    const std::string& mode = o->session.mode;
    if (mode != "derby" && mode != "at-bat" && mode != "practice" && mode != "game")
      throw InputError("--mode " + mode + ": unknown mode (allowed: derby, at-bat, practice, game)");
    if (mode != "game" && (innings->count() > 0 || games->count() > 0))
      throw InputError(std::string(innings->count() > 0 ? "--innings" : "--games") + ": only a game has innings and games (--mode game)");
    if (mode == "game") return run_game(assets, *o, outs->count() > 0 ? "--outs" : swings->count() > 0 ? "--swings" : "");
    const bool known = mode == "derby" || mode == "at-bat" || mode == "practice";
    if (known && outs->count() > 0 && mode != "derby")
      throw InputError("--outs: only the derby counts outs (--mode " + o->session.mode + ")");
    if (known && swings->count() > 0 && mode != "practice")
      throw InputError("--swings: only practice has a set number of pitches (--mode " + o->session.mode + ")");
    check_range("--outs", o->session.outs, SessionOptions::kOuts, "");
    check_range("--swings", o->session.swings, SessionOptions::kSwings, "");
    if (!o->plot.empty()) check_png_output(o->plot, "--plot");
    BotBatter bot(assets, batter_skill(o->bot), o->seed);
    const std::vector<SwingRecord> swings = run_session(assets, o->session, bot, o->seed);
    const nlohmann::json j = session_json(swings, o->session, o->seed);
    if (!o->plot.empty()) write_spray_chart(assets, swings, o->plot);
    if (o->json) {
      std::cout << json_text(j) << "\n";
      return 0;
    }
    Count count;  // an at-bat's count before each pitch
    for (const SwingRecord& s : swings) {
      if (o->session.mode == "at-bat") {
        std::printf("%d-%d  ", count.balls, count.strikes);
        // The session names a pitch's call by to_string(PitchResult), a ball in play by its outcome.
        PitchResult call = PitchResult::InPlay;
        for (PitchResult r : {PitchResult::Ball, PitchResult::CalledStrike, PitchResult::SwingingStrike, PitchResult::Foul,
                              PitchResult::FoulTip, PitchResult::HitByPitch})
          if (s.call_text == to_string(r)) call = r;
        apply_pitch(count, call);
      }
      // A take has no swing to time: its column says so instead of a timing of 0.
      if (s.swung)
        std::printf("%-10s %5.1f mph  timing %+5.1f ms  ", s.call.type.type.c_str(), mps_to_mph(s.call.type.speed), s.timing_ms);
      else
        std::printf("%-10s %5.1f mph  %-15s  ", s.call.type.type.c_str(), mps_to_mph(s.call.type.speed), "taken");
      // A fair ball's play in a scorer's words says where it went ("Double to RF").
      const bool fair = s.result.contact && s.result.outcome != BattedOutcome::Foul;
      // In a derby every fair ball short of a home run is an out: called so, with what it
      // would have been in a game beside it.
      const BattedOutcome oc = s.result.outcome;
      const bool derby_out = o->session.mode == "derby" && fair &&
                             (oc == BattedOutcome::Single || oc == BattedOutcome::Double || oc == BattedOutcome::Triple || oc == BattedOutcome::Error);
      const std::string play = !fair ? std::string() : derby_out ? "(in a game: " + s.result.play.description + ")" : s.result.play.description;
      if (s.result.contact)
        std::printf("EV %5.1f mph LA %+5.1f deg  %5.0f ft  %s%s%s%s\n", mps_to_mph(s.result.shot.launch.ball_speed),
                    rad_to_deg(s.result.shot.launch.vertical_angle), m_to_ft(s.result.shot.trajectory.summary.carry_m),
                    derby_out ? "out" : s.call_text.c_str(), s.result.barrel ? " (barrel)" : "", fair ? "  " : "", play.c_str());
      else
        std::printf("%s\n", s.call_text.c_str());
    }
    if (o->session.mode == "derby")
      std::printf("home runs: %d in %d swings\n", j["home_runs"].get<int>(), static_cast<int>(swings.size()));
    // Statcast's bat tracking over the session's swings.
    int n = 0, squared = 0, blasts = 0;
    double speed = 0.0, length = 0.0, attack = 0.0;
    for (const SwingRecord& s : swings) {
      if (!s.swung) continue;
      ++n;
      squared += s.result.tracking.is_squared_up;
      blasts += s.result.tracking.blast;
      speed += mps_to_mph(s.result.tracking.bat_speed_mps);
      length += m_to_ft(s.result.tracking.swing_length_m);
      attack += s.result.tracking.attack_angle_deg;
    }
    if (n > 0)
      std::printf("bat tracking: %.1f mph, %.1f ft swing, attack angle %.0f deg, squared up %d of %d, blasts %d\n",
                  speed / n, length / n, attack / n, squared, n, blasts);
    if (o->session.mode == "at-bat") std::printf("result: %s\n", j["result"].get<std::string>().c_str());
    if (!o->plot.empty()) std::printf("spray chart: %s\n", o->plot.c_str());
    return 0;
  };
}

const CommandRegistrar derby_command{45, "derby", "a bot batter: home-run derby, at-bat or batting practice (§9 JSON, --plot)", setup_derby};

}  // namespace
}  // namespace sweetspot::cli
