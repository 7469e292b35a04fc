// What the window prints of the batting cage as it closes (cage_report): the player's figures
// as the panel counts them, a live game's line, and every swing as it was called, a strikeout
// on a foul tip as such (its code "foul_tip", not "foul").
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "game/modes/baseball/figures.hpp"
#include "game/rules/baseball_game.hpp"
#include "game/ui/cage_view.hpp"
#include "support/intent_at.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using test::at;

namespace {

// One pitch swung at on time with the bat set `graze` m under the pitch's height at the
// plate, to the cage's 25 mm steps from where the bat stands; returns the time after it.
double swing_at_next(BattingCage& cage, double now, double graze) {
  cage.update({at(IntentKind::Pitch, now)}, now);
  REQUIRE(cage.stage() == BattingCage::Stage::Pitching);
  const double want = cage.pitch().plate.y() - graze;
  Intents steps;
  for (double h = cage.bat_height(); std::abs(want - h) > 0.5 * BattingCage::kBatStep;
       h += want > h ? BattingCage::kBatStep : -BattingCage::kBatStep)
    steps.push_back(at(want > h ? IntentKind::BatUp : IntentKind::BatDown, now + 0.01));
  cage.update(steps, now + 0.01);
  const double arrive = now + (kWindupTime + cage.pitch().flight_time) / cage.time_scale();
  cage.update({at(IntentKind::Swing, arrive)}, arrive + 0.001);
  // On until the call (a ball in play lands, is fielded or caught).
  double t = arrive;
  while (cage.stage() == BattingCage::Stage::Pitching || cage.stage() == BattingCage::Stage::Batted) {
    t += 0.05;
    cage.update({}, t);
  }
  return t + 0.5;
}

}  // namespace

TEST_CASE("the cage's exit report counts the player's swings and says each call as he was told it", "[ui][baseball]") {
  BattingCage cage(test::assets(), 5);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);
  REQUIRE(cage.live());
  double now = 1.0;
  // The bat set a ball's radius and a bat's (~7 cm) under the pitch or over it grazes it: fouls,
  // foul tips into the mitt, pop-ups and misses. On until a strikeout on a foul tip.
  bool struck_out_on_a_tip = false;
  for (int k = 0; k < 400 && !struck_out_on_a_tip; ++k) {
    now = swing_at_next(cage, now, (k % 2 == 0 ? 1.0 : -1.0) * 0.068);
    const SwingRecord& s = cage.swings().back();
    if (s.result.foul_tip) {
      CHECK(s.call_text == "foul_tip");
      struck_out_on_a_tip = s.said == "Strikeout on a foul tip";
    }
  }
  REQUIRE(struck_out_on_a_tip);
  // And a ball hit square, still in the air as the window closes: counted, listed, not called.
  cage.update({at(IntentKind::Pitch, now)}, now);
  const double arrive = now + (kWindupTime + cage.pitch().flight_time) / cage.time_scale();
  cage.update({at(IntentKind::ToggleTiming, now + 0.01)}, now + 0.01);
  cage.update({at(IntentKind::Swing, arrive)}, arrive + 0.001);
  const bool in_air = cage.stage() == BattingCage::Stage::Batted && cage.swings_told() < cage.swings().size();
  std::ostringstream out;
  cage_report(cage, out);
  const std::string report = out.str();
  const BattingCage::Figures f = cage.figures();
  CHECK(f.swings == static_cast<int>(cage.swings().size()));
  CHECK_THAT(report, Catch::Matchers::StartsWith("baseball: " + std::to_string(f.swings) + " swings, contact " +
                                                  std::to_string(f.contact) + ", fair " + std::to_string(f.fair)));
  CHECK_THAT(report, Catch::Matchers::Contains("live game: PA " + std::to_string(cage.at_bats().pa) + ":"));
  // Where the game stands, in the scoreboard's words: the half inning and its outs, or its end.
  const LiveInning::Board& board = *cage.board();
  CHECK_THAT(report, Catch::Matchers::Contains(board.side_retired ? "; end of the " + ordinal(board.inning) + ", runs "
                                                                  : "; top of the " + ordinal(board.inning) + ", "));
  CHECK_THAT(report, Catch::Matchers::Contains("\nswing: foul_tip  Strikeout on a foul tip\n"));
  // One line a swing, each with its call.
  std::size_t lines = 0;
  for (std::size_t at = report.find("\nswing: "); at != std::string::npos; at = report.find("\nswing: ", at + 1)) ++lines;
  CHECK(lines == cage.swings().size());
  CHECK(in_air);  // timing only, on time: a pro's read of the height, squarely met
  if (in_air) CHECK_THAT(report, Catch::Matchers::EndsWith("  (in the air as the window closed)\n"));
}
