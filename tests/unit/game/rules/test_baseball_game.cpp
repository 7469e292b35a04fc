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
  CHECK(box_score_mismatch(bat, field).empty());
  bat.runs_by_inning = {1, 0, 1};
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
  bat.runs_by_inning = {1, 0, 2};
  bat.batting[1].pa = 3;  // a plate appearance that is not an at-bat, walk, HBP or sac fly
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
  bat.batting[1].pa = 2;
  field.pitching.so = 2;
  CHECK_FALSE(box_score_mismatch(bat, field).empty());
}
