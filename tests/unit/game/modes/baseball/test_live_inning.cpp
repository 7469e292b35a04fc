// The live game's scoreboard: walks force the runners round (Rule 5.05(b)(1)), three outs
// retire the side and leave the runners on, the next inning opens with the bases empty, and a
// ball in play moves the runners as a game's half-inning does.
#include <catch2/catch.hpp>

#include <string>

#include "game/modes/baseball/cage.hpp"
#include "game/modes/baseball/live_inning.hpp"
#include "support/cage_play.hpp"
#include "support/intent_at.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using test::at;
using test::play_out_pitch;

TEST_CASE("live game: four walks force in a run, three strikeouts retire the side, the next inning starts empty",
          "[modes][baseball]") {
  LiveInning g(test::assets(), 5);
  PitchRecord ball;
  ball.call = PitchResult::Ball;
  PitchRecord strike;
  strike.call = PitchResult::CalledStrike;
  for (int k = 0; k < 3; ++k) g.end_plate_appearance("walk", ball);
  CHECK(runners_text(g.board().bases) == "bases loaded");
  CHECK(g.board().runs() == 0);
  g.end_plate_appearance("walk", ball);
  CHECK(g.board().runs() == 1);
  CHECK(g.board().note == "1 run scores");
  CHECK(runners_text(g.board().bases) == "bases loaded");
  for (int k = 0; k < 2; ++k) g.end_plate_appearance("strikeout", strike);
  CHECK(g.board().outs == 2);
  CHECK_FALSE(g.board().side_retired);
  g.end_plate_appearance("strikeout", strike);
  CHECK(g.board().side_retired);
  CHECK(g.board().left_on_base == 3);
  CHECK(g.board().note == "Side retired: 1 run, 0 hits, 3 left on base");
  // The next plate appearance opens inning 2: the bases empty, the line score a column on.
  g.end_plate_appearance("hit_by_pitch", ball);
  CHECK(g.board().inning == 2);
  CHECK(g.board().outs == 0);
  CHECK(runners_text(g.board().bases) == "runner on 1st");
  CHECK(g.board().runs_by_inning == std::vector<int>{1, 0});
}

TEST_CASE("live game in the cage: the pro's balls in play move the runners, the score adds up", "[modes][baseball]") {
  BattingCage cage(test::assets(), 22);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);
  REQUIRE(cage.live());
  REQUIRE(cage.board() != nullptr);
  double now = 1.0;
  int innings_done = 0, hits = 0, home_runs = 0, rescored = 0, foul_after_rescored = 0;
  while (innings_done < 3 && now < 4000.0) {
    const Count before = cage.count();
    const int pa_before = cage.at_bats().pa;
    const std::size_t swings_before = cage.swings().size();
    cage.update({at(IntentKind::BotSwings, now)}, now);
    // Until the pitch is called and any ball in play has come down.
    for (double until = now + 20.0; now < until && (cage.stage() == BattingCage::Stage::Pitching ||
                                                      cage.stage() == BattingCage::Stage::Batted);) {
      cage.update({}, now += 0.05);
      // While the ball is in the air nothing of its plate appearance is told: the count too.
      if (cage.swings_told() < cage.swings().size()) {
        CHECK(cage.count().balls == before.balls);
        CHECK(cage.count().strikes == before.strikes);
      }
    }
    now += 0.5;
    const LiveInning::Board& b = *cage.board();
    CHECK(b.outs <= 3);
    CHECK(b.hits == cage.at_bats().hits);
    CHECK(b.runs_by_inning.size() == static_cast<std::size_t>(b.inning));
    if (b.side_retired && b.inning > innings_done) {
      innings_done = b.inning;
      CHECK(b.outs == 3);
    }
    hits = b.hits;
    home_runs = cage.at_bats().home_runs;
    // A play the runners changed is called as the game scored it (the banner and the log):
    // the swing that ended the plate appearance (the board keeps its words through the next).
    if (cage.at_bats().pa > pa_before && !b.scored_as.empty() && !cage.swings().empty()) {
      ++rescored;
      CHECK_THAT(cage.swings().back().said, Catch::Matchers::StartsWith("The pro: " + b.scored_as));
    }
    // A swing that did not end the plate appearance (a foul) is called as itself, never with
    // the words of the last play the runners changed ("Foul ball" starts with "Foul").
    if (cage.at_bats().pa == pa_before && swings_before < cage.swings().size() && !b.scored_as.empty()) {
      ++foul_after_rescored;
      CHECK_FALSE(cage.swings().back().said.starts_with("The pro: " + b.scored_as));
    }
  }
  CHECK(innings_done == 3);
  CHECK(rescored >= 1);  // these three innings have a play whose runners changed its words
  CHECK(foul_after_rescored >= 1);  // and a swing after one that did not end its plate appearance
  // Every run is a batter who reached (a hit, a walk, a hit-by-pitch, an error) and came round;
  // the others were left on or put out on the bases.
  const LiveInning::Board& b = *cage.board();
  const int reached = cage.at_bats().pa - cage.at_bats().outs;
  CHECK(b.runs() <= reached);
  CHECK(b.runs() + b.left_on_base <= reached);
  CHECK(b.runs() >= home_runs);
  CHECK(hits > 0);
}

TEST_CASE("live game: the pro bats against the league's pitcher as the game's hitters do, not as in batting practice",
          "[modes][baseball]") {
  // B in a live game: his read of each pitch, his take or swing, his errors against live
  // pitching (hitter.hpp), so his line looks like a big-league hitter's (MLB 2024: AVG .243,
  // K 22.6 %, HR 2.9 % of plate appearances), not batting practice's barrel after barrel.
  BattingCage cage(test::assets(), 23);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);
  double now = 1.0;
  while (cage.at_bats().pa < 120 && now < 40000.0) {
    // A game over: P opens the next (B leaves the final standing), and the pro bats on.
    if (cage.board()->final) cage.update({at(IntentKind::Pitch, now)}, now);
    cage.update({at(IntentKind::BotSwings, now + 0.01)}, now + 0.01);
    play_out_pitch(cage, now, 0.05);
    now += 0.5;
  }
  const BattingCage::AtBats& a = cage.at_bats();
  REQUIRE(a.pa >= 120);
  const int ab = a.pa - a.walks - a.hit_by_pitch;
  const double avg = static_cast<double>(a.hits) / ab, k = static_cast<double>(a.strikeouts) / a.pa,
               hr = static_cast<double>(a.home_runs) / a.pa, bb = static_cast<double>(a.walks) / a.pa;
  INFO("PA " << a.pa << ": AVG " << avg << ", K " << k << ", BB " << bb << ", HR/PA " << hr);
  CHECK(avg >= 0.15);
  CHECK(avg <= 0.36);
  CHECK(k >= 0.10);
  CHECK(bb >= 0.02);  // he takes balls: a batting-practice swing never walks
  CHECK(hr <= 0.08);
}

TEST_CASE("live game: the league bats the bottom half; nine innings, no bottom of the 9th for a home side ahead, walk-offs, "
          "a final line that adds up",
          "[modes][baseball]") {
  // The player's halves are scripted (walks force in runs, strikeouts make the outs) so his
  // side scores 0, 1 a inning or 1 every other inning; the league's halves are the game's own
  // plate appearances against his side's pitchers (Rule 7.01: MLB's end of a game).
  PitchRecord ball;
  ball.call = PitchResult::Ball;
  PitchRecord strike;
  strike.call = PitchResult::CalledStrike;
  int home_wins = 0, away_wins = 0, walk_offs = 0, no_bottom_ninth = 0, extra = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    CAPTURE(seed);
    LiveInning g(test::assets(), seed);
    int guard = 0;
    while (!g.board().final && ++guard < 2000) {
      const int inning = g.board().side_retired ? g.board().inning + 1 : g.board().inning;
      const bool score = seed % 3 == 1 || (seed % 3 == 2 && inning % 2 == 1);
      // Four walks then three strikeouts: one run; three strikeouts: none (a placed runner
      // from the 10th is stranded either way).
      const int done = g.board().side_retired ? 0 : g.board().outs;
      const bool walks_left = score && done == 0 && runners_text(g.board().bases) != "bases loaded";
      if (walks_left || (score && done == 0 && g.board().runs_by_inning.back() == 0)) g.end_plate_appearance("walk", ball);
      else g.end_plate_appearance("strikeout", strike);
    }
    const LiveInning::Board& b = g.board();
    REQUIRE(b.final);
    const int ours = b.runs(), theirs = b.their_runs();
    CHECK(ours != theirs);
    CHECK(b.inning >= LiveInning::kInnings);
    CHECK(b.runs_by_inning.size() == static_cast<std::size_t>(b.inning));
    // Extra innings only after a tie through nine.
    if (b.inning > LiveInning::kInnings) {
      ++extra;
      int ours9 = 0, theirs9 = 0;
      for (int i = 0; i < LiveInning::kInnings; ++i) ours9 += b.runs_by_inning[static_cast<std::size_t>(i)], theirs9 += b.their_runs_by_inning[static_cast<std::size_t>(i)];
      CHECK(ours9 == theirs9);
    }
    const std::string winner = ours > theirs ? "You " : "League ";
    CHECK(b.final_line.rfind("Final: " + winner + std::to_string(std::max(ours, theirs)) + ", ", 0) == 0);
    if (theirs > ours) {
      ++home_wins;
      if (b.their_runs_by_inning.size() + 1 == static_cast<std::size_t>(b.inning)) {
        // Ahead after the top of the last inning: the home side did not bat.
        ++no_bottom_ninth;
        CHECK(b.inning == LiveInning::kInnings);
      } else {
        // Won in its last half: a walk-off, which ends the moment the winning run scores, so
        // the home side wins by one unless the last play was a home run.
        REQUIRE(b.their_runs_by_inning.size() == static_cast<std::size_t>(b.inning));
        ++walk_offs;
        CHECK(b.their_half.ends_with(". Walk-off"));
        if (b.their_half.find("Home run") == std::string::npos) CHECK(theirs - ours == 1);
        // Behind or level before it.
        CHECK(theirs - b.their_runs_by_inning.back() <= ours);
      }
    } else {
      ++away_wins;
      CHECK(b.their_runs_by_inning.size() == static_cast<std::size_t>(b.inning));
    }
    // Once over, nothing moves.
    const int before = b.runs();
    g.end_plate_appearance("walk", ball);
    g.next_batter();
    CHECK(g.board().runs() == before);
    CHECK(g.board().final);
  }
  INFO("home wins " << home_wins << " (no bottom of the 9th " << no_bottom_ninth << ", walk-offs " << walk_offs << "), away wins "
                    << away_wins << ", extra innings " << extra);
  CHECK(home_wins > 0);
  CHECK(away_wins > 0);
  CHECK(no_bottom_ninth > 0);
}

TEST_CASE("live game in the cage: the final stays until P; B and Space say so", "[modes][baseball]") {
  // The pro bats the whole game (B between pitches); once it is over, B and Space, the keys
  // of the game, answer that P starts a new one, and only P does.
  BattingCage cage(test::assets(), 5);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);
  REQUIRE(cage.live());
  double now = 1.0;
  while (!cage.board()->final && now < 40000.0) {
    cage.update({at(IntentKind::BotSwings, now)}, now);
    play_out_pitch(cage, now, 0.1);
    now += 0.5;
  }
  REQUIRE(cage.board()->final);
  const std::string final_line = cage.board()->final_line;
  for (const IntentKind k : {IntentKind::BotSwings, IntentKind::Swing}) {
    cage.update({at(k, now)}, now);
    now += 0.5;
    CHECK(cage.board()->final);
    CHECK(cage.board()->final_line == final_line);
    CHECK(cage.stage() != BattingCage::Stage::Pitching);
  }
  CHECK(cage.finished_games().empty());
  const int game_pa = cage.game_pa();
  CHECK(game_pa == cage.at_bats().pa);  // the first game: every plate appearance is its own
  CHECK(game_pa >= 27);                  // at least three up in each of nine innings
  cage.update({at(IntentKind::Pitch, now)}, now);
  CHECK_FALSE(cage.board()->final);
  CHECK(cage.stage() == BattingCage::Stage::Pitching);
  // The finished game's final is kept for the exit report; the session's plate appearances
  // go on, the new game's start from none (what a restart would lose).
  CHECK(cage.finished_games() == std::vector<std::string>{final_line});
  CHECK(cage.at_bats().pa == game_pa);
  CHECK(cage.game_pa() == 0);
}

TEST_CASE("the live game A keeps for the way back is counted while practising (what a restart would also lose)",
          "[modes][baseball]") {
  BattingCage cage(test::assets(), 7);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);
  REQUIRE(cage.live());
  double now = 1.0;
  while (cage.game_pa() < 4 && now < 4000.0) {
    cage.update({at(IntentKind::BotSwings, now)}, now);
    play_out_pitch(cage, now, 0.1);
    now += 0.5;
  }
  const int pa = cage.game_pa();
  REQUIRE(pa >= 4);
  cage.update({at(IntentKind::ToggleLive, now)}, now);
  REQUIRE_FALSE(cage.live());
  CHECK(cage.other_game_pa() == pa);
  cage.update({at(IntentKind::ToggleLive, now + 1.0)}, now + 1.0);
  REQUIRE(cage.live());
  CHECK(cage.game_pa() == pa);
}
