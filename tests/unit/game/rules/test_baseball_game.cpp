// Baseball's game rules (baseball_game.hpp): the count (MLB Rules 5.05, 5.09), forced
// runners, the end of a game (Rule 7.01) and a box score whose lines must add up.
#include <catch2/catch.hpp>

#include "game/rules/baseball_game.hpp"

using namespace sweetspot;

TEST_CASE("the count: four balls walk, three strikes retire, fouls stop at two strikes, a foul tip does not",
          "[baseball][rules]") {
  Count c;
  CHECK(apply_pitch(c, PitchResult::Ball) == PlateEnd::None);
  CHECK(apply_pitch(c, PitchResult::Foul) == PlateEnd::None);
  CHECK(apply_pitch(c, PitchResult::CalledStrike) == PlateEnd::None);
  CHECK((c.balls == 1 && c.strikes == 2));
  for (int i = 0; i < 5; ++i) CHECK(apply_pitch(c, PitchResult::Foul) == PlateEnd::None);
  CHECK(c.strikes == 2);
  CHECK(apply_pitch(c, PitchResult::FoulTip) == PlateEnd::Strikeout);
  Count w;
  for (int i = 0; i < 3; ++i) CHECK(apply_pitch(w, PitchResult::Ball) == PlateEnd::None);
  CHECK(apply_pitch(w, PitchResult::Ball) == PlateEnd::Walk);
  Count s;
  apply_pitch(s, PitchResult::SwingingStrike);
  apply_pitch(s, PitchResult::FoulTip);
  CHECK(apply_pitch(s, PitchResult::SwingingStrike) == PlateEnd::Strikeout);
  Count h;
  CHECK(apply_pitch(h, PitchResult::HitByPitch) == PlateEnd::HitByPitch);
  CHECK(apply_pitch(h, PitchResult::InPlay) == PlateEnd::InPlay);
}

TEST_CASE("a walk forces only the runners behind whom there is no open base", "[baseball][rules]") {
  Bases b{-1, 4, -1};  // a runner on second only
  CHECK(force_advance(b, 7) == 0);
  CHECK((b == Bases{7, 4, -1}));
  CHECK(force_advance(b, 8) == 0);
  CHECK((b == Bases{8, 7, 4}));
  CHECK(force_advance(b, 0) == 1);  // bases loaded: one run forced in
  CHECK((b == Bases{0, 8, 7}));
  Bases third{-1, -1, 2};
  CHECK(force_advance(third, 5) == 0);
  CHECK((third == Bases{5, -1, 2}));
}

TEST_CASE("the game ends when the rules say so", "[baseball][rules]") {
  GameSituation s;
  s.scheduled = 9;
  s.inning = 9;
  s.outs = 3;
  s.home_runs = 3;
  s.away_runs = 2;
  CHECK(game_over(s));  // home ahead after the top of the 9th: no bottom half
  s.home_runs = 2;
  CHECK_FALSE(game_over(s));  // tied: the home team bats
  s.bottom = true;
  s.outs = 1;
  s.home_runs = 3;
  CHECK(game_over(s));  // a walk-off
  s.home_runs = 1;
  s.outs = 3;
  CHECK(game_over(s));  // the home team lost in its last half
  s.home_runs = 2;
  CHECK_FALSE(game_over(s));  // tied after nine: extra innings
  s.inning = 8;
  s.home_runs = 5;
  CHECK_FALSE(game_over(s));  // the home team leads in the 8th: play on
}

TEST_CASE("a box score whose lines disagree is caught", "[baseball][rules]") {
  TeamBox bat, field;
  bat.name = "away";
  bat.runs_by_inning = {1, 0, 2};
  bat.runs = 3;
  bat.hits = 2;
  bat.batting.resize(2);
  bat.batting[0] = {3, 3, 2, 1, 0, 0, 1, 2, 0, 1, 0, 0};
  bat.batting[1] = {2, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0};
  field.pitching.r = 3;
  field.pitching.h = 2;
  field.pitching.bb = 1;
  field.pitching.so = 1;
  field.pitching.hr = 1;
  field.pitching.batters = 5;
  field.pitching.outs = 1;
  bat.left_on_base = 1;  // the proof: 5 PA = 3 R + 1 LOB + 1 putout
  CHECK(box_score_mismatch(bat, field).empty());
  bat.left_on_base = 2;  // a runner counted twice
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
  bat.placed_runners = 1;  // unless an extra inning's placed runner was left on too
  CHECK(box_score_mismatch(bat, field).empty());
  bat.left_on_base = 1;
  bat.placed_runners = 0;
  bat.runs_by_inning = {1, 0, 1};
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
  bat.runs_by_inning = {1, 0, 2};
  bat.batting[1].pa = 3;  // a plate appearance that is not an at-bat, walk, HBP or sac fly
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
  bat.batting[1].pa = 2;
  field.pitching.so = 2;
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
}

namespace {

TeamBox staff(const char* name, std::initializer_list<std::pair<int, int>> outs_and_lead) {
  TeamBox t;
  t.name = name;
  for (const auto& [outs, lead] : outs_and_lead) {
    PitchingLine p;
    p.outs = outs;
    p.lead_at_entry = lead;
    t.pitchers.push_back(p);
  }
  return t;
}

}  // namespace

TEST_CASE("the win, the loss and the save go where Rules 9.17 and 9.19 put them", "[baseball][rules][decisions]") {
  // Away leads 2-0 from the 1st; home goes ahead 3-2 off the away starter in the 6th and its
  // closer comes in for the 9th leading by one.
  std::vector<ScoreAfter> log = {{1, 0, 2, 0, {}}, {0, 0, 2, 0, {}}, {0, 0, 2, 3, {}},
                                 {1, 0, 2, 3, {}}, {1, 1, 2, 3, {}}, {1, 1, 2, 3, {}}};
  TeamBox away = staff("away", {{18, 0}, {6, -1}}), home = staff("home", {{24, 0}, {3, 1}});
  away.runs = 2, home.runs = 3;
  assign_decisions(log, 9, away, home);
  CHECK(away.pitchers[0].decision == Decision::Loss);  // charged with the go-ahead run
  CHECK(away.pitchers[1].decision == Decision::None);
  CHECK(home.pitchers[0].decision == Decision::Win);   // pitcher of record, eight innings
  CHECK(home.pitchers[1].decision == Decision::Save);  // a one-run lead, an inning
  CHECK(decisions_mismatch(away, home) == "");

  // A starter out after four innings cannot win: the reliever with the most outs does.
  home = staff("home", {{12, 0}, {9, 2}, {3, 1}});
  assign_decisions(log, 9, away, home);
  CHECK(home.pitchers[0].decision == Decision::None);
  CHECK(home.pitchers[1].decision == Decision::Win);
  CHECK(home.pitchers[2].decision == Decision::Save);

  // A closer who comes in four runs up and gets three outs has no save; three innings do.
  home = staff("home", {{18, 0}, {3, 4}});
  assign_decisions(log, 9, away, home);
  CHECK(home.pitchers[1].decision == Decision::None);
  home = staff("home", {{18, 0}, {9, 5}});
  assign_decisions(log, 9, away, home);
  CHECK(home.pitchers[1].decision == Decision::Save);
  // Two runs up, the tying run on deck: one out saves it.
  home = staff("home", {{24, 0}, {1, 2}});
  assign_decisions(log, 9, away, home);
  CHECK(home.pitchers[1].decision == Decision::Save);

  // The lead changes hands: the last go-ahead decides. Home leads 1-0, away goes ahead 2-1 off
  // home's reliever in the 7th, home ties it, away goes ahead for good off the next reliever.
  log = {{0, 0, 0, 1, {}}, {1, 1, 2, 1, {}}, {0, 1, 2, 2, {}}, {1, 2, 3, 2, {}}, {0, 2, 3, 2, {}}};
  away = staff("away", {{18, 0}, {6, -1}, {3, 1}});
  home = staff("home", {{18, 0}, {3, 1}, {3, 0}});
  away.runs = 3, home.runs = 2;
  assign_decisions(log, 9, away, home);
  CHECK(home.pitchers[1].decision == Decision::None);  // his run against was not the one that stood
  CHECK(home.pitchers[2].decision == Decision::Loss);
  CHECK(away.pitchers[1].decision == Decision::Win);   // pitching when his team went ahead for good
  CHECK(away.pitchers[2].decision == Decision::Save);
  CHECK(decisions_mismatch(away, home) == "");

  // A tie has no decisions; a second winner, or a save on the losing side, is caught.
  log.push_back({1, 2, 3, 3, {}});
  home.runs = 3;
  assign_decisions(log, 9, away, home);
  for (const TeamBox* t : {&away, &home})
    for (const PitchingLine& p : t->pitchers) CHECK(p.decision == Decision::None);
  CHECK(decisions_mismatch(away, home) == "");
  home.runs = 2;
  away.pitchers[0].decision = Decision::Win;
  away.pitchers[1].decision = Decision::Win;
  home.pitchers[0].decision = Decision::Loss;
  CHECK(decisions_mismatch(away, home) != "");
  away.pitchers[1].decision = Decision::None;
  home.pitchers[1].decision = Decision::Save;
  CHECK(decisions_mismatch(away, home) != "");
  home.pitchers[1].decision = Decision::None;
  CHECK(decisions_mismatch(away, home) == "");
  away.pitchers[2].er = 1;  // earned runs beyond his runs
  CHECK(decisions_mismatch(away, home) != "");
}

TEST_CASE("runs are charged to the pitcher who let the runner on, and a fielder's choice keeps his count (Rule 9.16(g))",
          "[baseball][rules][decisions]") {
  // The rule's own example: A walks the batter (1) and leaves; B gets a fielder's choice that
  // forces 1 at second with the batter (2) safe, then a home run scores 2 and the hitter (3).
  RunnerCharges charges;
  charges.reached(1, 0);  // pitcher 0 (A) walks him
  charges.reached(2, 1);  // the batter reaches against B ...
  charges.fielders_choice(2, 1);  // ... on a fielder's choice that puts A's runner out
  charges.reached(3, 1);
  CHECK(charges.charged(2) == 0);  // A answers for the runner B's fielder's choice left on
  CHECK(charges.charged(3) == 1);
  // A fielder's choice on B's own runner changes nothing.
  charges.reached(4, 1);
  charges.fielders_choice(5, 4);
  CHECK(charges.charged(5) == 1);
  CHECK_THROWS(charges.reached(9, 0));  // the batting order is 0..8
}

TEST_CASE("the loss goes to the pitcher charged with the go-ahead run, though he had left; a save with the tying run on base",
          "[baseball][rules][decisions]") {
  // Tied 2-2 in the 8th, home's starter leaves two on; his reliever gives up a double that
  // scores both: the go-ahead run (the first in) is the starter's, the second the reliever's.
  std::vector<ScoreAfter> log = {{1, 0, 2, 2, {}}, {1, 1, 4, 2, {0, 0}}, {0, 0, 4, 2, {}}, {0, 1, 4, 2, {}}};
  TeamBox away = staff("away", {{24, 0}, {3, 3}}), home = staff("home", {{22, 0}, {5, 0}});
  away.runs = 4, home.runs = 2;
  assign_decisions(log, 9, away, home);
  CHECK(home.pitchers[0].decision == Decision::Loss);
  CHECK(home.pitchers[1].decision == Decision::None);
  // The first run in is the reliever's own (he walked that runner) when the order says so.
  log[1].charged = {1, 0};
  assign_decisions(log, 9, away, home);
  CHECK(home.pitchers[1].decision == Decision::Loss);
  // Behind 2-3 the same double's second run puts away ahead: its pitcher takes the loss.
  log = {{1, 0, 2, 3, {}}, {1, 1, 4, 3, {1, 0}}, {0, 0, 4, 3, {}}, {0, 1, 4, 3, {}}};
  away.runs = 4, home.runs = 3;
  assign_decisions(log, 9, away, home);
  CHECK(home.pitchers[0].decision == Decision::Loss);
  CHECK(home.pitchers[1].decision == Decision::None);

  // Rule 9.19(b)(2): four runs up with two on, the tying run is on deck: one out saves it.
  // With the bases empty the same lead and out do not.
  away = staff("away", {{26, 0}, {1, 4}});
  away.pitchers[1].runners_at_entry = 2;
  assign_decisions(log, 9, away, home);
  CHECK(away.pitchers[1].decision == Decision::Save);
  away.pitchers[1].runners_at_entry = 0;
  assign_decisions(log, 9, away, home);
  CHECK(away.pitchers[1].decision == Decision::None);
}

TEST_CASE("a reliever's inherited runners who scored are among those he inherited", "[baseball][rules]") {
  TeamBox bat, field;
  bat.name = "away", field.name = "home";
  bat.batting.assign(9, BattingLine{});
  field.pitchers.assign(2, PitchingLine{});
  field.pitchers[1].runners_at_entry = field.pitchers[1].inherited = 2;
  field.pitchers[1].inherited_scored = 2;
  CHECK(box_score_mismatch(bat, field) == "");
  field.pitchers[1].inherited_scored = 3;
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
  field.pitchers[1].inherited_scored = 1;
  field.pitchers[1].inherited = 3;  // more than were on base when he came in
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
}
