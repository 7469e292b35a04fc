// The golf game's model driven by scripted, timestamped intents, as the window's keys drive
// it: the meter judged from each key's own time at any frame rate, Esc, a hole to the cup,
// a restarted hole.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <utility>

#include "game/content/course_file.hpp"
#include "game/modes/golf/golf_play.hpp"
#include "game/modes/golf/latency_calibration.hpp"
#include "game/modes/replay.hpp"
#include "game/rules/golf_scoring.hpp"
#include "game/util/rng.hpp"
#include "game/report/report.hpp"
#include "game/report/round_json.hpp"
#include "game/report/round_save.hpp"
#include "physics/units.hpp"
#include "physics/world.hpp"
#include "support/ball_on_green.hpp"
#include "support/intent_at.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using test::at;

namespace {

GolfSetup solo(const std::string& skill) {
  GolfSetup s;
  s.players = {{"You", skill, true, 0, {}}};
  s.flyover = false;
  return s;
}

// The National's hole `index` (0-based) alone, its ball placed on the ground under (x, z).
Course national_hole_from(std::size_t index, double x, double z) {
  Course course = load_course(test::assets(), "national");
  course.holes = {course.holes[index]};
  SurfaceContact hit;
  REQUIRE(ground_under(*course.holes[0].world->world, x, z, 400.0, 420.0, &hit));
  course.holes[0].tee = hit.point;
  return course;
}

Course first_hole(int holes = 1) {
  Course c = load_course(test::assets(), "links");
  c.holes.resize(static_cast<std::size_t>(holes));
  return c;
}

// The first stroke of a `skill` golfer on `course`'s first hole, among `clubs` at powers from
// `from` up to 1.1 in steps of `step`, whose ball comes to rest where `wanted(surface, metres to
// the cup)`; found by playing them without recording them. None when no such stroke.
template <class Wanted>
std::optional<StrokeInput> first_stroke_to(const Course& course, const std::string& skill,
                                           std::initializer_list<const char*> clubs, double from, double step, Wanted wanted) {
  GolfPlay probe(test::assets(), course, solo(skill));
  const GolfRound& r = probe.round();
  const Terrain& world = *course.holes[0].world->world;
  for (const char* club : clubs) {
    for (double p = from; p <= MeterInput::kPower.max + 1e-9; p += step) {
      StrokeInput in;
      in.club = club;
      in.meter.power = p;
      const Vec3 rest = r.simulate(in).trajectory.summary.rest_position;
      const std::optional<SurfaceContact> under = r.ground_at(rest.x(), rest.z());
      const double to_pin = std::hypot(rest.x() - course.holes[0].pin.x(), rest.z() - course.holes[0].pin.z());
      if (under && wanted(world.material(under->material).kind, to_pin)) return in;
    }
  }
  return std::nullopt;
}

// Frames every `dt` s, as the window runs them: each frame hands the model the intents whose
// key went down since the last frame (their own times), then its own time.
struct FrameDriver {
  GolfPlay& play;
  double dt;
  double now = 0.0;
  void until(double t, Intents pending) {
    while (now < t) {
      now += dt;
      Intents frame;
      for (auto it = pending.begin(); it != pending.end();) {
        if (it->time <= now) {
          frame.push_back(*it);
          it = pending.erase(it);
        } else {
          ++it;
        }
      }
      play.update(frame, now);
    }
  }
};

}  // namespace

TEST_CASE("a meter click's error is the key press time minus the mark, at 16, 33 and 66 ms frames", "[modes][golf]") {
  const GolferSkill& skill = golfer_skill("scratch");
  for (const double dt : {0.016, 0.033, 0.066}) {
    for (const double late_ms : {0.0, 7.0, -12.0}) {
      CAPTURE(dt, late_ms);
      GolfPlay play(test::assets(), first_hole(), skill);
      FrameDriver f{play, dt};
      // Start at an odd time, the power click 0.883 s later (98 %): neither on a frame boundary.
      const double start = 0.1003, top = start + 0.883;
      f.until(top + dt, {at(IntentKind::Swing, start), at(IntentKind::Swing, top)});
      REQUIRE(play.stage() == GolfPlay::Stage::Swinging);
      REQUIRE(play.meter()->phase() == MeterClock::Phase::Downswing);
      const double mark = play.meter()->mark_time();
      f.until(mark + 0.3, {at(IntentKind::Swing, mark + late_ms / 1000.0)});
      REQUIRE(play.last_meter());
      REQUIRE(play.last_click());
      // The click's own error, as the player made it, is shown ...
      CHECK(play.last_click()->click_error_ms() == Approx(late_ms).margin(1e-6));
      // ... and plays less the difficulty's perfect window (Standard, 10 ms).
      const double w = perfect_window_ms(MeterDifficulty::Standard);
      CHECK(play.last_meter()->accuracy_ms == Approx(std::copysign(std::max(0.0, std::abs(late_ms) - w), late_ms)).margin(1e-6));
      // The power is the marker's height at the second key press, not at a frame.
      const double tempo = MeterClock::tempo_for(false);
      CHECK(play.last_meter()->power == Approx(0.883 / tempo).margin(1e-9));
      CHECK(play.round().card().back().strokes == 1);
    }
  }
}

TEST_CASE("the meter climbs at one pace with every full-swing club", "[modes][golf]") {
  // A player times his power click to the marker's pace; from the 1st tee (the caddie's
  // 6-iron) the driver and the 8-iron, which cannot reach (a full swing), rise alike (Tour
  // Tempo: one tempo through the bag).
  std::vector<double> heights;
  std::vector<std::string> clubs;
  for (const bool longest : {true, false}) {
    GolfPlay play(test::assets(), first_hole(), solo("scratch"));
    std::vector<IntentKind> keys(longest ? 8 : 2, longest ? IntentKind::ClubUp : IntentKind::ClubDown);
    Intents in;
    for (const IntentKind k : keys) in.push_back(at(k, 0.5));
    play.update(in, 0.5);
    CAPTURE(play.club());
    play.update({at(IntentKind::Swing, 1.0)}, 1.0);
    REQUIRE(play.meter());
    heights.push_back(play.meter()->position(1.45));
    clubs.push_back(play.club());
  }
  CHECK(clubs == std::vector<std::string>{"driver", "8-iron"});
  CHECK(heights[0] == Approx(0.45 / MeterClock::tempo_for(false)).margin(1e-12));
  CHECK(heights[1] == heights[0]);
}

TEST_CASE("at a hot seat each player's meter marks his own last clicks, not his friend's", "[modes][golf]") {
  GolfSetup setup;
  setup.players = {{"You", "scratch", true, 0, {}}, {"Bob", "scratch", true, 0, {}}};
  setup.flyover = false;
  GolfPlay play(test::assets(), first_hole(), setup);
  REQUIRE(play.player() == 0);
  // You: the power click at 0.8 s of the 0.9 s climb.
  play.update({at(IntentKind::Swing, 1.0), at(IntentKind::Swing, 1.8), at(IntentKind::Swing, 2.3)}, 2.4);
  REQUIRE(play.last_click());
  const double yours = play.last_click()->power();
  double t = 3.0;
  while (play.player() != 1 && t < 40.0) {
    t += 0.5;
    play.update({at(IntentKind::Continue, t)}, t);
  }
  REQUIRE(play.player() == 1);
  while (play.stage() != GolfPlay::Stage::Aiming && t < 60.0) play.update({}, t += 0.5);
  // Bob has not swung: no marks of his (You's were the last clicks made).
  CHECK_FALSE(play.last_click());
  CHECK_FALSE(play.last_click_here());
  // Bob's swing, softer; then You's turn again shows You's clicks.
  play.update({at(IntentKind::Swing, t + 1.0), at(IntentKind::Swing, t + 1.6), at(IntentKind::Swing, t + 2.0)}, t + 2.1);
  t += 2.5;
  // Until it is You's turn (Bob may lie farther and play again: his caddie's swings).
  while (!(play.player() == 0 && play.stage() == GolfPlay::Stage::Aiming) && t < 200.0) {
    t += 0.5;
    if (play.player() == 1 && play.stage() == GolfPlay::Stage::Aiming) play.update({at(IntentKind::CaddiePlays, t)}, t);
    else play.update({at(IntentKind::Continue, t)}, t);
  }
  REQUIRE(play.player() == 0);
  REQUIRE(play.last_click());
  CHECK(play.last_click()->power() == yours);
}

TEST_CASE("the last clicks are this hole's guide only on this hole", "[modes][golf]") {
  // The meter marks the last putt's power as a guide to the next putt; one on another green
  // is another length, so it is this player's on this hole or none.
  GolfPlay play(test::assets(), first_hole(2), solo("scratch"));
  play.update({at(IntentKind::Swing, 1.0), at(IntentKind::Swing, 1.8), at(IntentKind::Swing, 2.3)}, 2.4);
  REQUIRE(play.last_click());
  double t = 3.0;
  play.update({at(IntentKind::Continue, t)}, t);
  while (play.stage() != GolfPlay::Stage::Aiming && t < 20.0) play.update({}, t += 0.5);
  REQUIRE(play.round().hole_index() == 0);
  CHECK(play.last_click_here());
  while (play.round().hole_index() == 0 && t < 200.0) {
    t += 1.0;
    play.update({at(IntentKind::CaddiePlays, t), at(IntentKind::Continue, t + 0.1)}, t + 0.2);
    play.update({at(IntentKind::Continue, t + 0.3)}, t + 0.4);
  }
  REQUIRE(play.round().hole_index() == 1);
  REQUIRE(play.last_click());  // the caddie's strokes leave the player's clicks as they were
  CHECK_FALSE(play.last_click_here());
}

TEST_CASE("Esc during a putt says the putt was cancelled", "[modes][golf]") {
  const std::optional<Course> c = test::national_hole_from_green(0, 2.5, 0.3);
  REQUIRE(c);
  GolfPlay play(test::assets(), *c, solo("tour"));
  REQUIRE(play.club() == "putter");
  play.update({at(IntentKind::Swing, 1.0)}, 1.2);
  REQUIRE(play.stage() == GolfPlay::Stage::Swinging);
  play.update({at(IntentKind::Cancel, 1.3)}, 1.4);
  CHECK(play.message() == "Putt cancelled, no stroke counted (Space: putt again)");
  CHECK(play.round().card().back().strokes == 0);
}

TEST_CASE("Esc cancels a swing in progress and no stroke is counted", "[modes][golf]") {
  GolfPlay play(test::assets(), first_hole(), golfer_skill("scratch"));
  play.update({at(IntentKind::Swing, 1.0)}, 1.2);
  REQUIRE(play.stage() == GolfPlay::Stage::Swinging);
  play.update({at(IntentKind::Cancel, 1.3)}, 1.4);
  CHECK(play.stage() == GolfPlay::Stage::Aiming);
  CHECK(play.cancelled() == 1);
  CHECK(play.swing_undone());  // the meter's caption says so until the next swing
  CHECK(play.message() == "Swing cancelled, no stroke counted (Space: swing again)");
  CHECK(play.round().card().back().strokes == 0);
  CHECK(play.round().card().back().shots.empty());
  // Left alone long after, nothing finishes itself: the meter is gone.
  play.update({}, 10.0);
  CHECK(play.round().card().back().strokes == 0);
  // A swing after it counts as the first stroke.
  play.update({at(IntentKind::Swing, 11.0), at(IntentKind::Swing, 11.8), at(IntentKind::Swing, 12.3)}, 12.4);
  CHECK(play.round().card().back().strokes == 1);
}

TEST_CASE("a hole played through intents: the caddie's strokes, putts with two clicks, the card adds up", "[modes][golf]") {
  GolfPlay play(test::assets(), first_hole(), solo("tour"));
  double t = 0.0;
  int played = 0, putted_by_hand = 0;
  while (play.stage() != GolfPlay::Stage::RoundOver && played < 12) {
    t += 1.0;
    if (play.stage() == GolfPlay::Stage::Aiming && play.round().lie() == "green") {
      // A putt by hand: two clicks, power where the second lands.
      REQUIRE(play.club() == "putter");
      play.update({at(IntentKind::Swing, t), at(IntentKind::Swing, t + 0.35)}, t + 0.4);
      ++putted_by_hand;
    } else {
      play.update({at(IntentKind::CaddiePlays, t)}, t);
    }
    ++played;
    REQUIRE(play.stage() != GolfPlay::Stage::Swinging);
    t += 0.5;
    play.update({at(IntentKind::Continue, t)}, t);  // Enter: skip the flight
  }
  REQUIRE(play.stage() == GolfPlay::Stage::RoundOver);
  // Enters (pressed to skip flights and turns) keep the final card, however late; N starts anew.
  play.update({at(IntentKind::Continue, t + 0.1)}, t + 0.1);
  CHECK(play.stage() == GolfPlay::Stage::RoundOver);
  play.update({at(IntentKind::Continue, t + 5.0)}, t + 5.0);
  CHECK(play.stage() == GolfPlay::Stage::RoundOver);
  const HoleCard& card = play.round().card().front();
  CHECK(static_cast<int>(card.shots.size()) == played);
  CHECK(card.strokes == played + card.penalties);
  int on_green = 0;
  for (const StrokeRecord& s : card.shots) on_green += s.lie == "green";
  CHECK(card.putts == on_green);
  CHECK(putted_by_hand == card.putts);
  CHECK((card.holed || card.strokes >= GolfRound::kPickUp));
}

TEST_CASE("restarting a hole puts the round back where the hole began", "[modes][golf]") {
  GolfPlay play(test::assets(), first_hole(2), solo("tour"));
  double t = 0.0;
  // Play hole 1 out with the caddie.
  while (play.round().hole_index() == 0) {
    t += 1.0;
    play.update({at(IntentKind::CaddiePlays, t), at(IntentKind::Continue, t + 0.1)}, t + 0.2);
    play.update({at(IntentKind::Continue, t + 0.3)}, t + 0.4);
  }
  const int hole1 = play.round().card().front().strokes;
  const Vec3 tee = play.round().ball();
  t += 1.0;
  play.update({at(IntentKind::Continue, t)}, t);  // past the scorecard
  REQUIRE(play.stage() == GolfPlay::Stage::Aiming);
  t += 1.0;
  play.update({at(IntentKind::CaddiePlays, t), at(IntentKind::Continue, t + 0.1)}, t + 0.2);
  REQUIRE(play.round().card().back().strokes >= 1);
  // What the pause menu says a restart loses: this hole's strokes, not the last one's.
  CHECK(play.strokes_a_restart_loses() == play.round().card().back().strokes);
  play.update({at(IntentKind::Restart, t + 0.5)}, t + 0.6);
  CHECK(play.strokes_a_restart_loses() == 0);
  CHECK(play.round().hole_index() == 1);
  CHECK(play.round().card().back().strokes == 0);
  CHECK(play.round().card().front().strokes == hole1);
  CHECK((play.round().ball() - tee).norm() == 0.0);
  CHECK(play.stage() == GolfPlay::Stage::Aiming);
  // The stroke thrown away is not there to replay (R would show it on a hole begun again).
  CHECK(play.last_shot().trajectory.samples.empty());
  CHECK_FALSE(play.last_shot_on_hole_shown());
  // The card says so (R): the strokes thrown away are gone, so a mulligan is not hidden.
  CHECK(play.restarts(1) == 1);
  CHECK(play.restarts(0) == 0);
  // Restarted again before any stroke: nothing thrown away, no second mark.
  play.update({at(IntentKind::Restart, t + 0.7)}, t + 0.8);
  CHECK(play.restarts(1) == 1);
  CHECK(play.message() == "Hole 2 restarted");
  // Saved and resumed, the round keeps its R mark (the turns alone do not hold it).
  {
    GolfSetup again = solo("tour");
    const SavedRound saved = parse_round_save(
        json_text(round_save_json(play.group(), play.group().course().source.string(), play.restarts(), play.cancelled())), "save.json");
    again.players = saved.players;
    again.options = saved.options;
    again.resume = saved.events;
    again.resume_restarts = saved.restarts;
    again.resume_cancelled = saved.cancelled;
    const GolfPlay resumed(test::assets(), play.group().course(), again);
    CHECK(resumed.restarts(1) == 1);
    CHECK(resumed.restarts(0) == 0);
    CHECK(resumed.cancelled() == play.cancelled());
  }
  // And the printed card once the hole is played out, with its key (R beside the hole's
  // number, as the window's card has it); a card without restarts has neither.
  while (!play.group().finished()) {
    t += 1.0;
    play.update({at(IntentKind::CaddiePlays, t), at(IntentKind::Continue, t + 0.1)}, t + 0.2);
    play.update({at(IntentKind::Continue, t + 0.3)}, t + 0.4);
  }
  const std::string card = group_table(play.group(), play.restarts());
  INFO(card);
  CHECK_THAT(card, Catch::Matchers::Contains("\n   2 R     " + std::to_string(play.group().course().holes[1].par) + " "));
  CHECK_THAT(card, !Catch::Matchers::Contains("\n   1 R"));
  CHECK_THAT(card, Catch::Matchers::Contains("R the hole was restarted"));
  CHECK_THAT(group_table(play.group()), !Catch::Matchers::Contains("restarted") && !Catch::Matchers::Contains(" R "));
}

TEST_CASE("a bot takes its own turn, and a stroke's result is told once the ball stops", "[modes][golf]") {
  GolfSetup setup = default_golf_setup(golfer_skill("scratch"), 7);
  setup.flyover = true;
  GolfPlay play(test::assets(), first_hole(), setup);
  // The hole opens with its flyover; Enter skips it.
  CHECK(play.stage() == GolfPlay::Stage::Flyover);
  play.update({}, 2.0);
  CHECK(play.stage() == GolfPlay::Stage::Flyover);
  CHECK(play.flyover_progress(3.0) == Approx(3.0 / GolfPlay::kFlyover));
  play.update({at(IntentKind::Continue, 2.5)}, 2.6);
  REQUIRE(play.stage() == GolfPlay::Stage::Aiming);
  REQUIRE(play.human_turn());
  REQUIRE(play.player() == 0);
  // You tee off with the caddie's swing; in the air nothing is told yet.
  play.update({at(IntentKind::CaddiePlays, 3.0)}, 3.1);
  REQUIRE(play.stage() == GolfPlay::Stage::Flying);
  CHECK(play.message().empty());
  const double flight = duration(play.last_shot().trajectory);
  play.update({}, 3.0 + flight + 0.01);
  CHECK_FALSE(play.message().empty());
  // The bot has the tee next: it addresses the ball, then swings by itself.
  REQUIRE(play.stage() == GolfPlay::Stage::Aiming);
  CHECK(play.player() == 1);
  CHECK_FALSE(play.human_turn());
  const double turn = 3.0 + flight;
  // Your keys strike nothing on its turn, and are not dropped without a word.
  play.update({at(IntentKind::Swing, turn + 0.1), at(IntentKind::CaddiePlays, turn + 0.15)}, turn + 0.2);
  CHECK(play.stage() == GolfPlay::Stage::Aiming);
  CHECK(play.group().round(0).card().back().strokes == 1);
  CHECK_THAT(play.message(), Catch::Matchers::Contains("is to play, not you"));
  play.update({}, turn + GolfPlay::kBotAddress + 0.01);
  CHECK(play.stage() == GolfPlay::Stage::Flying);
  CHECK(play.group().round(1).card().back().strokes == 1);
  CHECK(play.group().events().back().drawn);
}

TEST_CASE("on your turn your own last stroke is kept for you after the bot has played", "[modes][golf]") {
  // The HUD tells the latest stroke, which is the bot's by the time you play again; your own
  // last one on the hole stays, without your name, until the hole ends.
  GolfSetup setup = default_golf_setup(golfer_skill("scratch"), 7);
  setup.flyover = false;
  GolfPlay play(test::assets(), first_hole(), setup);
  REQUIRE(play.human_turn());
  CHECK(play.own_last(0) == nullptr);
  play.update({at(IntentKind::CaddiePlays, 1.0)}, 1.1);
  const StrokeRecord mine = play.last_record();
  double t = 1.0 + duration(play.last_shot().trajectory) + 0.01;
  play.update({}, t);
  // The bot plays until it is your turn again (the farther ball plays first).
  int bot_strokes = 0;
  while (!play.human_turn() && play.stage() != GolfPlay::Stage::HoleOver && bot_strokes < 10) {
    t += GolfPlay::kBotAddress + 0.01;
    play.update({}, t);
    REQUIRE(play.stage() == GolfPlay::Stage::Flying);
    ++bot_strokes;
    t += duration(play.last_shot().trajectory) + 0.01;
    play.update({}, t);
  }
  REQUIRE(bot_strokes > 0);
  REQUIRE(play.human_turn());
  CHECK(play.shooter() == 1);
  CHECK(play.message().rfind(play.group().players()[1].name + ", stroke", 0) == 0);  // the bot's stroke
  const GolfPlay::OwnLast* own = play.own_last(0);
  REQUIRE(own != nullptr);
  CHECK(own->message.rfind("stroke 1: ", 0) == 0);
  CHECK(own->record.club == mine.club);
  CHECK(own->record.to_pin_m == mine.to_pin_m);
  REQUIRE(play.own_last(1) != nullptr);
  CHECK(play.own_last(1)->message.rfind("stroke " + std::to_string(bot_strokes) + ": ", 0) == 0);
}

TEST_CASE("a stray Space is abandoned at the top of the meter: no stroke, no penalty", "[modes][golf]") {
  GolfPlay play(test::assets(), first_hole(), solo("scratch"));
  play.update({at(IntentKind::Swing, 1.0)}, 1.1);
  REQUIRE(play.stage() == GolfPlay::Stage::Swinging);
  play.update({}, 10.0);
  CHECK(play.stage() == GolfPlay::Stage::Aiming);
  CHECK(play.round().card().back().strokes == 0);
  CHECK(play.cancelled() == 1);
  CHECK(play.swing_undone());
  // The next swing takes the caption back.
  play.update({at(IntentKind::Swing, 11.0)}, 11.1);
  CHECK_FALSE(play.swing_undone());
}

TEST_CASE("putting preview: the flat-green roll grows with power and inverts", "[modes][golf]") {
  GolfPlay play(test::assets(), first_hole(), solo("tour"));
  double t = 0.0;
  while (play.round().lie() != "green" && play.stage() != GolfPlay::Stage::RoundOver) {
    t += 1.0;
    play.update({at(IntentKind::CaddiePlays, t), at(IntentKind::Continue, t + 0.1)}, t + 0.2);
  }
  REQUIRE(play.round().lie() == "green");
  double last = 0.0;
  for (double p = 0.1; p <= 1.0; p += 0.1) {
    const double d = play.flat_roll(p);
    CHECK(d > last);
    CHECK(play.power_for_roll(d) == Approx(p).margin(1e-6));
    last = d;
  }
  // A full putter stroke on this stimp-10.5 green rolls a long lag, and the meter's 110 %
  // reaches past the farthest putt the game reads (a 50 ft uphill putt was beyond it).
  CHECK(play.flat_roll(1.0) > 30.0);
  CHECK(play.flat_roll(MeterInput::kPower.max) > GolfPlay::kPuttGuideReach);
  // The putt's meter runs at the tempo its cup's power asks for (MeterClock::putt_tempo).
  const double cup = play.cup_mark_power();
  play.update({at(IntentKind::Swing, t + 1.0)}, t + 1.0);
  REQUIRE(play.meter());
  CHECK(play.meter()->position(t + 1.6) == Approx(0.6 / MeterClock::putt_tempo(cup)).margin(1e-12));
}

TEST_CASE("putting preview: a putt stopped on the green cup mark gets to the cup", "[modes][golf]") {
  // From 1 to 8 m either side of the cup on every green of the national course, a putt at
  // the mark's power straight at the cup: the mark paces it GolfBot::kPuttPast on, so on these
  // real greens' slopes most reach the hole (holed or past it) where a mark for the cup's
  // own distance leaves half short ("never up, never in").
  int spots = 0, reach = 0, reach_exact = 0, holed = 0;
  for (std::size_t n = 0; n < test::national().holes.size(); ++n) {
    for (double dist : {1.0, 2.5, 8.0}) {
      for (int k = 0; k < 2; ++k) {
        const std::optional<Course> c = test::national_hole_from_green(n, dist, kPi * k + 0.3);
        if (!c) continue;
        GolfPlay play(test::assets(), *c, solo("tour"));
        if (play.round().lie() != "green") continue;
        ++spots;
        const Vec3 from = play.round().ball(), pin = c->holes[0].pin;
        const double to_cup = std::hypot(pin.x() - from.x(), pin.z() - from.z());
        const auto gets_there = [&](double power) {
          StrokeInput putt;
          putt.club = "putter";
          putt.meter.power = power;
          const ShotResult r = play.round().simulate(putt);
          const Vec3 rest = r.trajectory.summary.rest_position;
          const double along = ((rest.x() - from.x()) * (pin.x() - from.x()) + (rest.z() - from.z()) * (pin.z() - from.z())) / to_cup;
          return std::pair{r.end == ShotEnd::Holed, r.end == ShotEnd::Holed || along >= to_cup};
        };
        CHECK(play.flat_roll(play.cup_mark_power()) == Approx(play.putt_plays_as() + GolfBot::kPuttPast).margin(1e-6));
        const auto [in, got] = gets_there(play.cup_mark_power());
        holed += in;
        reach += got;
        reach_exact += gets_there(play.power_for_roll(play.putt_plays_as())).second;
      }
    }
  }
  INFO(spots << " putts: " << reach << " reach the cup at the mark (" << holed << " holed), " << reach_exact
             << " at the cup's own distance");
  REQUIRE(spots > 80);
  CHECK(reach > 0.75 * spots);
  CHECK(reach > reach_exact);
}

TEST_CASE("putting preview from off the green: the slower grass first makes the putt play longer", "[modes][golf]") {
  // An approach that stops just off the green, then the putt from there.
  const Course course = first_hole();
  const std::optional<StrokeInput> off =
      first_stroke_to(course, "tour", {"5-iron", "4-iron", "6-iron", "7-iron"}, 0.6, 0.02,
                      [](SurfaceKind k, double to_pin) { return k == SurfaceKind::Fairway && to_pin > 4.0 && to_pin < 20.0; });
  REQUIRE(off);
  GolfSetup setup = solo("tour");
  GolfEvent e;
  e.stroke = *off;
  setup.resume = {e};
  GolfPlay play(test::assets(), course, setup);
  REQUIRE(play.round().lie() == "fairway");
  const double to_cup = play.round().to_pin();
  // The preview is offered off the green too, and the putt plays longer than its distance:
  // fairway grass slows a roll more than the green.
  CHECK(play.putt_guide());
  CHECK(play.flat_roll(1.0) > 10.0);
  CHECK(play.putt_crosses() == "fairway");
  CHECK(play.putt_plays_as() > to_cup * 1.05);
  // At the power the preview marks, the putt reaches the cup's distance on a line that
  // starts on the fairway (the real hole's slopes aside, it must not stop short by half).
  StrokeInput putt;
  putt.club = "putter";
  putt.meter.power = play.power_for_roll(play.putt_plays_as());
  const Vec3 rest = play.round().simulate(putt).trajectory.summary.rest_position;
  const double rolled = std::hypot(rest.x() - play.round().ball().x(), rest.z() - play.round().ball().z());
  CHECK(rolled > 0.7 * to_cup);
  CHECK(rolled < 1.5 * to_cup);
  // With the fairway counted as green the same putt comes up shorter.
  putt.meter.power = play.power_for_roll(to_cup);
  const Vec3 short_rest = play.round().simulate(putt).trajectory.summary.rest_position;
  CHECK(std::hypot(short_rest.x() - play.round().ball().x(), short_rest.z() - play.round().ball().z()) < rolled);
}

TEST_CASE("the meter's pin mark is a flown stroke's power, nearer the pin than the table's straight lines", "[modes][golf]") {
  // The green mark under the swing meter: the power whose stroke stops nearest the pin,
  // bracketed by the table and narrowed by flying the stroke itself. Where a pitch's stop
  // jumps across the pin the table's straight line between two powers promised the pin
  // and sent the ball yards past (a play-test: 65 % "stops at the pin", 64 % ran 7 yd past).
  const Course course = first_hole();
  GolfPlay tee(test::assets(), course, solo("scratch"));
  const double to_pin = tee.round().to_pin();
  CHECK_FALSE(tee.putt_guide());  // a putter chosen on the tee gets no roll scale: nobody putts 300 m
  int found = 0;
  for (const char* club : {"5-iron", "6-iron", "7-iron", "8-iron"}) {
    CAPTURE(club);
    const auto pin = tee.pin_power(club);
    if (!pin) continue;
    ++found;
    StrokeInput in;
    in.club = club;
    in.aim = tee.aim();
    in.meter.power = pin->power;
    CHECK(tee.round().simulate(in).trajectory.summary.total_m == Approx(pin->stops).margin(1e-9));
    // Never farther from the pin than the table's own answer, flown.
    in.meter.power = tee.power_for_stop(club, to_pin);
    const double table_miss = std::abs(tee.round().simulate(in).trajectory.summary.total_m - to_pin);
    CHECK(std::abs(pin->stops - to_pin) <= table_miss + 1e-9);
    // A step of the search either side stops on the other side of the pin or farther from it.
    for (const double step : {-GolfPlay::kPinPowerStep, GolfPlay::kPinPowerStep}) {
      in.meter.power = pin->power + step;
      const double stop = tee.round().simulate(in).trajectory.summary.total_m;
      CHECK((std::abs(stop - to_pin) >= std::abs(pin->stops - to_pin) - 1.0 || (stop - to_pin) * (pin->stops - to_pin) <= 0.0));
    }
  }
  CHECK(found >= 2);
  // A lob wedge from the tee never gets there; the putter has no mark.
  CHECK_FALSE(tee.pin_power("lw"));
  CHECK_FALSE(tee.pin_power("putter"));
}

TEST_CASE("the meter's carry scale is the stroke's own carry at each power, and finds the pin's power", "[modes][golf]") {
  // The scale under a swing's meter reads a table of the club's carry from here: at a power
  // the table holds it is that stroke's carry, between them near it, and back from a carry to
  // a power it lands within a metre of the same carry.
  const Course course = first_hole();
  GolfPlay tee(test::assets(), course, solo("scratch"));
  const std::string club = "7-iron";
  for (const double p : {0.5, 0.8, 1.0}) {
    StrokeInput in;
    in.club = club;
    in.aim = tee.aim();
    in.meter.power = p;
    const double carry = tee.round().simulate(in).trajectory.summary.carry_m;
    INFO("power " << p << ": carry " << carry << " m, the scale " << tee.carry_at_power(club, p) << " m");
    CHECK(tee.carry_at_power(club, p) == Approx(carry).margin(1e-6));
  }
  for (const double p : {0.35, 0.65, 0.95}) {
    StrokeInput in;
    in.club = club;
    in.aim = tee.aim();
    in.meter.power = tee.power_for_carry(club, tee.carry_at_power(club, p));
    CHECK(in.meter.power == Approx(p).margin(1e-6));
    const double carry = tee.round().simulate(in).trajectory.summary.carry_m;
    CHECK(carry == Approx(tee.carry_at_power(club, p)).margin(0.03 * carry));  // linear between the table's powers
  }
  // The pin's mark is by where the stroke stops: the power it gives stops there (to within
  // the table's straight lines between its powers).
  const double stop_p = tee.power_for_stop(club, tee.stop_at_power(club, 0.75));
  CHECK(stop_p == Approx(0.75).margin(1e-6));
  StrokeInput at_stop;
  at_stop.club = club;
  at_stop.aim = tee.aim();
  at_stop.meter.power = stop_p;
  const double total = tee.round().simulate(at_stop).trajectory.summary.total_m;
  CHECK(total == Approx(tee.stop_at_power(club, 0.75)).margin(0.03 * total));
  CHECK(tee.stop_at_power(club, 1.0) >= tee.carry_at_power(club, 1.0));
  // More power never carries less, and the putter has no scale.
  for (double p = 0.2; p < 1.1; p += 0.05) CHECK(tee.carry_at_power(club, p + 0.05) >= tee.carry_at_power(club, p));
  CHECK(tee.carry_at_power("putter", 1.0) == 0.0);
}

TEST_CASE("the caddie names the water on the line of the National's 3rd, where it lies", "[modes][golf]") {
  // The par 3 plays over a pond short of its green: from the tee, along the aim, the hazards
  // on the line hold a stretch of water inside the club's reach whose middle is water and
  // whose ends, a step outside, are not; the putter's line has none.
  Course c = test::national();
  c.holes = {test::national().holes.at(2)};
  GolfPlay tee(test::assets(), c, solo("scratch"));
  const auto& hazards = tee.hazards_on_line(tee.club());
  const auto water = std::find_if(hazards.begin(), hazards.end(), [](const GolfPlay::Hazard& h) { return h.kind == "water"; });
  REQUIRE(water != hazards.end());
  INFO("water " << water->from << "-" << water->to << " m; the pin " << tee.round().to_pin() << " m");
  CHECK(water->from < water->to);
  CHECK(water->to < tee.round().to_pin());
  const Vec3 b = tee.round().ball(), d = tee.aim_direction();
  CHECK(tee.round().surface_at(b + 0.5 * (water->from + water->to) * d) == "water");
  CHECK(tee.round().surface_at(b + (water->from - 2.5) * d) != "water");
  CHECK(tee.round().surface_at(b + (water->to + 2.5) * d) != "water");
  CHECK(tee.hazards_on_line("putter").empty());
}

TEST_CASE("the caddie's plan: a full swing from the tee, a part swing's power for a pitch", "[modes][golf]") {
  const Course course = first_hole();
  GolfPlay tee(test::assets(), course, solo("scratch"));
  REQUIRE(tee.caddie_plan());
  CHECK(tee.caddie_plan()->club == tee.club());
  CHECK(tee.caddie_plan()->meter.power >= 0.97);
  // A tee shot that stops 15-45 m from the cup (short of the pond or over the green): the
  // pitch from there is a part swing.
  const std::optional<StrokeInput> short_one =
      first_stroke_to(course, "scratch", {"hybrid", "4-iron", "5-iron", "9-iron", "pw"}, 0.5, 0.05, [](SurfaceKind k, double to_pin) {
        return (k == SurfaceKind::Fairway || k == SurfaceKind::Rough) && to_pin > 15.0 && to_pin < 45.0;
      });
  REQUIRE(short_one);
  GolfSetup setup = solo("scratch");
  GolfEvent e;
  e.stroke = *short_one;
  setup.resume = {e};
  GolfPlay pitch(test::assets(), course, setup);
  REQUIRE(pitch.caddie_plan());
  INFO(pitch.caddie_plan()->club << " at " << pitch.caddie_plan()->meter.power << " from " << pitch.round().to_pin() << " m");
  CHECK(pitch.caddie_plan()->club == pitch.club());
  CHECK(pitch.caddie_plan()->meter.power < 0.9);
  CHECK(pitch.caddie_plan()->meter.power > 0.1);
  // The panel's figures for that part swing are its own stroke's, and it stops nearer the cup
  // than the full swing the club line gives.
  const double power = pitch.caddie_plan()->meter.power;
  const FlightSummary planned = pitch.round().simulate(*pitch.caddie_plan()).trajectory.summary;
  CHECK(pitch.carry_here(pitch.club(), power) == planned.carry_m);
  CHECK(pitch.stops_here(pitch.club(), power) == planned.total_m);
  CHECK(pitch.carry_here(pitch.club()) > pitch.carry_here(pitch.club(), power) + 5.0);
  CHECK(std::abs(pitch.stops_here(pitch.club(), power) - pitch.round().to_pin()) <
        std::abs(pitch.stops_here(pitch.club()) - pitch.round().to_pin()));
  // Its meter climbs at the part swing's tempo, the mark at least 0.6 s into the swing
  // (MeterClock::part_swing_tempo), not at the club's full-swing pace.
  REQUIRE(MeterClock::part_swing_tempo(power) > MeterClock::tempo_for(false));  // slowed here
  pitch.update({at(IntentKind::Swing, 1.0)}, 1.0);
  REQUIRE(pitch.meter());
  CHECK(pitch.meter()->position(1.3) == Approx(0.3 / MeterClock::part_swing_tempo(power)).margin(1e-12));
  CHECK(pitch.meter()->position(1.0 + MeterClock::kLeastToCup) <= power + 1e-12);
  // Cancelled, the idle bar is the one the next press starts: the part swing's pace and
  // perfect window, not the full swing's (its accuracy mark would be drawn too wide).
  pitch.update({at(IntentKind::Cancel, 1.4)}, 1.4);
  REQUIRE_FALSE(pitch.meter());
  CHECK(pitch.next_meter().tempo() == MeterClock::part_swing_tempo(power));
  CHECK(pitch.next_meter().window_fraction() < MeterClock(MeterClock::tempo_for(false), false, pitch.next_meter().window_ms()).window_fraction());
  pitch.update({at(IntentKind::Swing, 2.0)}, 2.0);
  REQUIRE(pitch.meter());
  CHECK(pitch.meter()->tempo() == pitch.next_meter().tempo());
}

TEST_CASE("taps that run on past the calibration's last beat are taps, not a swing", "[modes][golf]") {
  TapQuiet quiet;
  CHECK_FALSE(quiet.swallow(1.0));  // before any calibration, Space is a swing
  quiet.start(10.0);
  // A player who started three beats late taps on at the beat's period: every one swallowed,
  // far past the quiet's first end.
  for (int k = 0; k < 4; ++k) CHECK(quiet.swallow(10.2 + k * LatencyCalibration::kPeriod));
  const double last = 10.2 + 3 * LatencyCalibration::kPeriod;
  CHECK(last > 10.0 + TapQuiet::kQuiet);
  // Once he stops, a press after the quiet is his swing.
  CHECK_FALSE(quiet.swallow(last + TapQuiet::kQuiet + 0.01));
}

TEST_CASE("latency calibration: the median tap offset, and the meter judges aimed clicks that much earlier", "[modes][golf]") {
  LatencyCalibration cal(10.0);
  // Taps 45 ms after each beat with a few ms of scatter; the lead-in beats are not counted;
  // one wild tap does not move the median.
  const double jitter[] = {0.004, -0.003, 0.002, -0.001, 0.0, 0.003, -0.002, 0.001, 0.2, -0.004};
  for (int k = 0; k < LatencyCalibration::kBeats; ++k) cal.tap(cal.beat(k) + 0.045 + jitter[k]);
  CHECK(cal.counted() == LatencyCalibration::kBeats - LatencyCalibration::kLeadIn);
  REQUIRE(cal.latency());
  CHECK(*cal.latency() == Approx(0.045).margin(0.004));
  CHECK(cal.done(cal.beat(LatencyCalibration::kBeats - 1) + 0.5));
  LatencyCalibration few(0.0);
  few.tap(few.beat(3));
  CHECK_FALSE(few.latency());

  // A player 45 ms late on every aimed click plays a perfect swing once the latency is set.
  GolfSetup setup = solo("scratch");
  setup.input_latency = 0.045;
  setup.difficulty = MeterDifficulty::Pro;
  GolfPlay play(test::assets(), first_hole(), setup);
  play.update({at(IntentKind::Swing, 1.0), at(IntentKind::Swing, 1.0 + 0.8 + 0.045)}, 1.9);
  REQUIRE(play.meter());
  const double mark = play.meter()->mark_time();
  play.update({at(IntentKind::Swing, mark + 0.045)}, mark + 0.1);
  REQUIRE(play.last_meter());
  CHECK(play.last_meter()->accuracy_ms == Approx(0.0).margin(1e-6));
  const double tempo = MeterClock::tempo_for(false);
  CHECK(play.last_meter()->power == Approx(0.8 / tempo).margin(1e-9));
}

TEST_CASE("the window's round resumes from a save's turns, a finished one on its final card", "[modes][golf][save]") {
  GolfSetup setup = default_golf_setup(golfer_skill("amateur"), 5);
  setup.flyover = false;
  GolfGroup played(test::assets(), first_hole(2), setup.players, setup.options);
  for (int k = 0; k < 5; ++k) played.play_bot();
  setup.resume = played.events();
  GolfPlay resumed(test::assets(), first_hole(2), setup);
  CHECK(resumed.group().events().size() == played.events().size());
  CHECK(resumed.group().to_play() == played.to_play());
  CHECK(resumed.player() == played.to_play());
  for (int p = 0; p < 2; ++p) CHECK((resumed.group().round(p).ball() - played.round(p).ball()).norm() == 0.0);
  // Resumed in the middle of a hole, play goes on from the ball: no flyover of a hole begun.
  setup.flyover = true;
  REQUIRE(played.hole_index() == 0);
  CHECK(GolfPlay(test::assets(), first_hole(2), setup).stage() == GolfPlay::Stage::Aiming);
  // Resumed at a hole's first stroke (here the round's start), its flyover is shown.
  setup.resume.clear();
  CHECK(GolfPlay(test::assets(), first_hole(2), setup).stage() == GolfPlay::Stage::Flyover);
  setup.flyover = false;
  while (!played.finished()) played.play_bot();
  setup.resume = played.events();
  setup.flyover = true;
  GolfPlay over(test::assets(), first_hole(2), setup);
  CHECK(over.stage() == GolfPlay::Stage::RoundOver);
  CHECK(over.hole_shown() == 1);  // the card stands over the last green, not the first tee
}

TEST_CASE("restart during the round's last flight restarts the last hole, not past the end", "[modes][golf]") {
  GolfPlay play(test::assets(), first_hole(), solo("tour"));
  double t = 0.0;
  // Play until a stroke ends the round, and restart while that ball is still in the air.
  for (int k = 0; k < 12 && !play.group().finished(); ++k) {
    t += 1.0;
    play.update({at(IntentKind::CaddiePlays, t)}, t);
    if (!play.group().finished()) play.update({at(IntentKind::Continue, t + 0.1)}, t + 0.1);
  }
  REQUIRE(play.group().finished());
  REQUIRE(play.stage() == GolfPlay::Stage::Flying);
  CHECK(play.strokes_a_restart_loses() == play.round().card().back().strokes);
  play.update({at(IntentKind::Restart, t + 0.2)}, t + 0.2);
  CHECK(play.stage() == GolfPlay::Stage::Aiming);
  CHECK_FALSE(play.group().finished());
  CHECK(play.group().hole_index() == 0);
  CHECK(play.round().card().back().strokes == 0);
  CHECK(play.ball_centre().allFinite());
}

TEST_CASE("the club's carry from here is the stroke's own physics: the hole's wind and the lie", "[modes][golf]") {
  // The HUD shows each club's bag carry (calm, flat fairway) beside its carry from where the
  // ball lies in this hole's wind, and where that swing stops (the caddie picks by it).
  GolfSetup calm = solo("amateur"), windy = solo("amateur");
  calm.options.seed = windy.options.seed = 5;
  Course still = first_hole(), blowing = first_hole();
  still.holes[0].wind_speed = 0.0;
  blowing.holes[0].wind_speed = 6.0;  // m/s, into the player: pin to tee
  const Vec3 into = blowing.holes[0].tee - blowing.holes[0].pin;
  blowing.holes[0].wind_toward = std::atan2(into.z(), into.x());
  GolfPlay a(test::assets(), still, calm), b(test::assets(), blowing, windy);
  // Along the aim the player is handed (the caddie's, off the pin where the ground asks).
  StrokeInput in;
  in.club = "5-iron";
  in.aim = a.aim();
  const double calm_carry = a.carry_here("5-iron");
  CHECK(calm_carry == a.round().simulate(in).trajectory.summary.carry_m);
  CHECK(calm_carry > 100.0);
  CHECK(b.carry_here("5-iron") < calm_carry - 5.0);  // held up by the wind
  in.aim = b.aim();
  CHECK(b.carry_here("5-iron") == b.round().simulate(in).trajectory.summary.carry_m);
  // The wind's share, which the HUD names: the same swing from the same ball in still air.
  CHECK(b.calm_carry_here("5-iron") == b.round().simulate_calm(in).trajectory.summary.carry_m);
  CHECK(b.calm_carry_here("5-iron") > b.carry_here("5-iron") + 5.0);
  CHECK(a.calm_carry_here("5-iron") == calm_carry);  // no wind, no share
  CHECK(a.carry_here("putter") == 0.0);
  // Where the same swing stops, the distance the caddie picks by: past the carry on this
  // fairway (the 5-iron runs ~15 m), and the stroke's own.
  in.aim = a.aim();
  CHECK(a.stops_here("5-iron") == a.round().simulate(in).trajectory.summary.total_m);
  CHECK(a.stops_here("5-iron") > calm_carry + 5.0);
  CHECK(a.stops_here("putter") == 0.0);
}

TEST_CASE("in a crosswind the caddie aims upwind of the pin, the same way on every tee, and says why", "[modes][golf]") {
  // The links' first hole in a 7 m/s (16 mph) wind across the line, from either side: the
  // player is handed the caddie's aim, upwind of the pin, and his stroke aimed there finishes
  // nearer the pin's line than the same club aimed at the flag. Calm, the aim is the pin's.
  for (const double side : {-1.0, 1.0}) {
    Course c = first_hole();
    const Vec3 line = c.holes[0].pin - c.holes[0].tee;
    c.holes[0].wind_speed = 7.0;
    c.holes[0].wind_toward = std::atan2(line.z(), line.x()) + side * kPi / 2.0;  // + side: toward the right
    const GolfPlay play(test::assets(), c, solo("scratch"));
    REQUIRE(play.caddie_plan());
    INFO("wind toward the " << (side > 0 ? "right" : "left") << ": " << play.club() << " aimed " << play.aim() << " rad");
    CHECK(play.aim() == play.caddie_plan()->aim);
    CHECK(play.aim() * side < -0.01);  // upwind: left of the pin in a wind toward the right
    CHECK(play.aim_why() == GolfPlay::AimWhy::Wind);
    StrokeInput at_flag = *play.caddie_plan();
    at_flag.aim = 0.0;
    const GolfRound& r = play.round();
    const auto off_line = [&](const StrokeInput& in) {
      const Vec3 rest = r.simulate(in).trajectory.summary.rest_position - r.ball();
      return std::abs(std::sin(std::atan2(rest.z(), rest.x()) - r.line_to_pin()) * std::hypot(rest.x(), rest.z()));
    };
    CHECK(off_line(*play.caddie_plan()) < 0.5 * off_line(at_flag));
    // Where the map centres his spread: the flight's own landing, drifted back toward the
    // pin's line from the aim upwind (not on the aim line).
    const Vec3 land = play.landing_here(play.club()) - r.ball();
    const double land_off_aim = std::sin(std::atan2(land.z(), land.x()) - (r.line_to_pin() + play.aim())) * std::hypot(land.x(), land.z());
    INFO("lands " << land_off_aim << " m to the side of the aim line");
    CHECK(land_off_aim * side > 5.0);  // blown downwind of the aim
    // His reason is his club's: another club on the same line says none; C brings his back.
    GolfPlay changed(test::assets(), c, solo("scratch"));
    changed.update({at(IntentKind::ClubDown, 1.0)}, 1.1);
    REQUIRE(changed.club() != play.club());
    CHECK(changed.aim() == play.aim());
    CHECK(changed.aim_why() == GolfPlay::AimWhy::Pin);
    changed.update({at(IntentKind::CaddieClub, 1.2)}, 1.3);
    CHECK(changed.club() == play.club());
    CHECK(changed.aim_why() == GolfPlay::AimWhy::Wind);
  }
  Course calm = first_hole();
  calm.holes[0].wind_speed = 0.0;
  const GolfPlay still(test::assets(), calm, solo("scratch"));
  CHECK(std::abs(still.aim()) < deg_to_rad(0.5));
  CHECK(still.aim_why() == GolfPlay::AimWhy::Pin);
  // A bend 1 m off the straight line (a hole that looks straight) leaves the crosswind's aim
  // the wind's.
  Course bent = first_hole();
  CourseHole& h = bent.holes[0];
  const Vec3 line = h.pin - h.tee;
  const double along = std::atan2(line.z(), line.x());
  Vec3 bend = h.tee + 0.55 * line;
  bend.x() += std::cos(along + kPi / 2.0);
  bend.z() += std::sin(along + kPi / 2.0);
  h.bends = {bend};
  h.wind_speed = 7.0;
  h.wind_toward = along - kPi / 2.0;  // toward the left: the aim goes right, to the bend's side
  const GolfPlay crossed(test::assets(), bent, solo("scratch"));
  REQUIRE(crossed.round().next_bend());
  CHECK(crossed.aim() > 0.01);
  CHECK(crossed.aim_why() == GolfPlay::AimWhy::Wind);
  // The National's 2nd from its tee, out of a scratch player's reach in calm air: the caddie
  // plays to the bend, whose line turns 5 deg there (the hole looks straight: a bend, not a
  // dogleg); turned 30 deg there (the pin swung round the bend), the dogleg's corner.
  for (const double swing : {0.0, 25.0}) {
    Course par5 = test::national();
    par5.holes = {test::national().holes.at(1)};
    CourseHole& p5 = par5.holes[0];
    p5.number = 1;
    p5.wind_speed = 0.0;
    REQUIRE(p5.bends.size() == 1);
    const Vec3 c = p5.bends[0];
    const Vec3 leg = p5.pin - c;
    const double turn = std::remainder(std::atan2(leg.z(), leg.x()) - std::atan2(c.z() - p5.tee.z(), c.x() - p5.tee.x()), 2.0 * kPi);
    const double a = deg_to_rad(swing) * (turn > 0.0 ? 1.0 : -1.0);  // the way the line already turns
    p5.pin.x() = c.x() + leg.x() * std::cos(a) - leg.z() * std::sin(a);
    p5.pin.z() = c.z() + leg.x() * std::sin(a) + leg.z() * std::cos(a);
    const GolfPlay play(test::assets(), par5, solo("scratch"));
    INFO("pin swung " << swing << " deg round the bend: aim " << rad_to_deg(play.aim()) << " deg");
    REQUIRE(play.round().next_bend());
    CHECK(std::abs(play.aim()) > deg_to_rad(0.5));
    CHECK(play.aim_why() == (swing > 0.0 ? GolfPlay::AimWhy::Corner : GolfPlay::AimWhy::Bend));
  }
}

TEST_CASE("a chip's aim off the pin in a crosswind is not the wind's: the air moves it centimetres", "[modes][golf]") {
  // The National's 10th from the rough 15 m from the cup in a 5 m/s (11 mph) wind across the
  // line, from either side. The caddie's chip hangs ~1.5 s at ~10 m/s; the wind moves its
  // landing by tens of centimetres, so any aim he takes off the pin is the green's or his
  // line's, never "the wind drifts it".
  for (const double side : {-1.0, 1.0}) {
    Course course = national_hole_from(9, 93.5, -407.7);
    CourseHole& h = course.holes[0];
    const Vec3 line = h.pin - h.tee;
    h.wind_speed = 5.0;
    h.wind_toward = std::atan2(line.z(), line.x()) + side * kPi / 2.0;
    const GolfPlay play(test::assets(), course, solo("amateur"));
    REQUIRE(play.caddie_plan());
    INFO("wind toward the " << (side > 0 ? "right" : "left") << ": " << play.club() << " at " << play.caddie_plan()->meter.power
                            << " power aimed " << rad_to_deg(play.aim()) << " deg");
    // The physics behind the claim: the same chip in calm air lands within 0.5 m of it.
    Course calm = course;
    calm.holes[0].wind_speed = 0.0;
    const GolfPlay still(test::assets(), calm, solo("amateur"));
    const Vec3 windy_landing = play.round().simulate(*play.caddie_plan()).trajectory.summary.landing_position;
    const Vec3 calm_landing = still.round().simulate(*play.caddie_plan()).trajectory.summary.landing_position;
    CHECK((windy_landing - calm_landing).norm() < 0.5);
    CHECK(play.aim_why() != GolfPlay::AimWhy::Wind);
  }
}

TEST_CASE("behind a tree the caddie's aim points the way out, not at the flag", "[modes][golf]") {
  // The National's 9th from the left rough ~225 m out: a tree ~15 m ahead on the line to the
  // flag (the bot's test, test_golf_round.cpp). The player is handed the caddie's club and
  // line: a club aimed at the flag would strike the tree.
  const Course course = national_hole_from(8, -307.4, -473.5);
  const GolfPlay play(test::assets(), course, solo("amateur"));
  REQUIRE(play.caddie_plan());
  INFO(play.club() << " aimed " << play.aim() << " rad");
  StrokeInput straight;
  straight.club = play.club();
  CHECK(play.round().first_touch_in_a_tree(play.round().simulate(straight).trajectory.summary));  // at the flag: the tree
  CHECK(play.aim() == play.caddie_plan()->aim);
  CHECK(std::abs(play.aim()) > 0.05);
  StrokeInput in = *play.caddie_plan();
  CHECK_FALSE(play.round().first_touch_in_a_tree(play.round().simulate(in).trajectory.summary));
  // The HUD's carry from here is along that aim: clear of the tree, the stroke's own carry.
  CHECK_FALSE(play.tree_in_the_way(play.club()));
  CHECK(play.carry_here(play.club()) == play.round().simulate(in).trajectory.summary.carry_m);
}

TEST_CASE("the caddie's part swing at the pin stops where the pin mark does, not a few tries short of it", "[modes][golf]") {
  // The National's 2nd, a scratch player a little past half way: his 3-wood swung soft. Tuned
  // in three tries from a guess it stopped 14 m short in the rough, where the pin mark's
  // power stopped at the pin on the green.
  const Course national = load_course(test::assets(), "national");
  const CourseHole& second = national.holes[1];
  const Vec3 p = second.tee + 0.55 * (second.pin - second.tee);
  const Course course = national_hole_from(1, p.x(), p.z());
  const GolfPlay play(test::assets(), course, solo("scratch"));
  const std::optional<double> part = play.caddie_part_swing(play.club());
  REQUIRE(part);
  CHECK(std::abs(play.stops_here(play.club(), *part) - play.round().to_pin()) < 4.0);
  StrokeInput in = *play.caddie_plan();
  CHECK(play.round().surface_at(play.round().simulate(in).trajectory.summary.rest_position) == "green");
}

TEST_CASE("the meter's carry scale is the aim's: turned back at the tree, it reads the tree", "[modes][golf]") {
  const Course course = national_hole_from(8, -307.4, -473.5);
  GolfPlay play(test::assets(), course, solo("amateur"));
  const std::string club = play.club();
  // Along the caddie's line, clear of the tree: the scale's full swing is the stroke's carry.
  const double clear = play.carry_at_power(club, 1.0);
  CHECK(clear == Approx(play.carry_here(club)));
  // Aimed back at the flag, the same club strikes the tree ~15 m out: the scale says so.
  const double a = play.aim();
  const int steps = static_cast<int>(std::lround(std::abs(a) / GolfPlay::kAimStep));
  Intent turn = at(a > 0.0 ? IntentKind::AimLeft : IntentKind::AimRight, 1.0);
  turn.param = steps;
  play.update({turn}, 1.0);
  REQUIRE(std::abs(play.aim()) < GolfPlay::kAimStep);
  StrokeInput at_flag;
  at_flag.club = club;
  at_flag.aim = play.aim();
  REQUIRE(play.round().first_touch_in_a_tree(play.round().simulate(at_flag).trajectory.summary));
  CHECK(play.carry_at_power(club, 1.0) < 0.5 * clear);
  // And back along the caddie's line, the clear carry again.
  Intent back = at(a > 0.0 ? IntentKind::AimRight : IntentKind::AimLeft, 2.0);
  back.param = steps;
  play.update({back}, 2.0);
  CHECK(play.carry_at_power(club, 1.0) == Approx(play.carry_here(club)));
}

TEST_CASE("beside a row of trees in a crosswind the caddie's line clears them when the swing is a little off", "[modes][golf]") {
  // The window's `play --mode golf --bot none --seed 3`: the caddie's drive on the National's
  // 1st stops in the right rough ~178 yd out, trees along the right and the wind (22 mph)
  // blowing right to left. A line held out over the trees for the wind to bring back flies
  // into them when the swing is a standard deviation of the meter's timing late or early.
  GolfSetup setup = solo("scratch");
  setup.options.seed = 3;
  GolfPlay play(test::assets(), load_course(test::assets(), "national"), setup);
  play.update({at(IntentKind::CaddiePlays, 1.0)}, 1.1);
  REQUIRE(play.stage() == GolfPlay::Stage::Flying);
  play.update({at(IntentKind::Continue, 1.2)}, 1.3);
  REQUIRE(play.stage() == GolfPlay::Stage::Aiming);
  REQUIRE(play.round().lie() == "rough");
  REQUIRE(play.round().wind().speed > 5.0);
  const std::optional<StrokeInput>& plan = play.caddie_plan();
  REQUIRE(plan);
  INFO(plan->club << " at " << plan->meter.power << " power, aimed " << plan->aim << " rad");
  const double sd = golfer_skill("scratch").accuracy_sd_ms;
  for (const double f : {0.0, -1.0, 1.0}) {
    StrokeInput in = *plan;
    in.meter.accuracy_ms = f * sd;
    INFO("timing " << in.meter.accuracy_ms << " ms");
    CHECK_FALSE(play.round().first_touch_in_a_tree(play.round().simulate(in).trajectory.summary));
  }
  // He hands a shorter club than the distance asks for, and says which he passed over: the
  // stock club for the distance, whose plan or misses found the trees.
  if (!play.caddie_passed_over().empty()) {
    const auto& bag = golf_bag();
    const auto at = [&](const std::string& c) { return std::find(bag.begin(), bag.end(), c) - bag.begin(); };
    CHECK(at(play.caddie_passed_over()) < at(plan->club));
  }
}

TEST_CASE("a pitch's tree warning is the pitch's: a full wedge into the trees says nothing of it", "[modes][golf]") {
  // The National's 10th, calm, in the rough 15 m from the cup: a full lob wedge at the flag
  // flies into the trees behind the green (carry ~43 m); the caddie's part swing lands short
  // of them, and the panel warns of no tree.
  Course course = load_course(test::assets(), "national");
  course.holes = {course.holes[9]};
  course.holes[0].wind_speed = 0.0;
  SurfaceContact hit;
  REQUIRE(ground_under(*course.holes[0].world->world, 93.5, -407.7, 400.0, 420.0, &hit));
  course.holes[0].tee = hit.point;
  const GolfPlay play(test::assets(), course, solo("amateur"));
  REQUIRE(play.caddie_plan());
  INFO(play.club() << " at " << play.caddie_plan()->meter.power << " power, aimed " << play.aim());
  REQUIRE(play.caddie_plan()->meter.power < 0.9);
  StrokeInput full;
  full.club = play.club();
  full.aim = play.aim();
  REQUIRE(play.round().first_touch_in_a_tree(play.round().simulate(full).trajectory.summary));
  CHECK_FALSE(play.tree_in_the_way(play.club()));
}

namespace {
/// A tour match between you and `other` (a human at the same keys, or a bot), no flyover.
GolfSetup tour_match(const std::string& other, bool human) {
  GolfSetup s;
  s.players = {{"You", "tour", true, 0, {}}, {other, "tour", human, 0, {}}};
  s.options.format = GolfFormat::Match;
  s.flyover = false;
  return s;
}
}  // namespace

TEST_CASE("match play: H asks before it gives up the hole, another key answers no", "[modes][golf][formats]") {
  GolfPlay play(test::assets(), first_hole(2), tour_match("tour bot", false));
  REQUIRE(play.stage() == GolfPlay::Stage::Aiming);
  REQUIRE(play.human_turn());
  // One H asks; nothing is given up.
  play.update({at(IntentKind::Concede, 1.0)}, 1.0);
  CHECK(play.group().hole_index() == 0);
  CHECK_FALSE(play.round().card().front().conceded);
  CHECK(play.message().find("H again") != std::string::npos);
  // Any other key answers no, and does nothing else (the aim stays); the next H asks again.
  const double aim = play.aim();
  play.update({at(IntentKind::AimLeft, 1.5)}, 1.5);
  CHECK(play.message() == "Hole not conceded: play on");
  CHECK(play.aim() == aim);
  play.update({at(IntentKind::Concede, 2.0)}, 2.0);
  CHECK(play.group().hole_index() == 0);
  // H twice: the hole is given up and the match moves to the next one.
  play.update({at(IntentKind::Concede, 2.5)}, 2.5);
  CHECK(play.group().hole_index() == 1);
  CHECK(play.group().round(0).card().front().conceded);
}

TEST_CASE("in stroke play H says what it is for and gives up nothing", "[modes][golf][formats]") {
  GolfPlay play(test::assets(), first_hole(2), solo("tour"));
  REQUIRE(play.human_turn());
  play.update({at(IntentKind::Concede, 1.0), at(IntentKind::Concede, 1.5)}, 1.5);
  CHECK(play.group().hole_index() == 0);
  CHECK_FALSE(play.round().card().front().conceded);
  CHECK(play.message() == "H concedes a hole, in match play only");
}

TEST_CASE("match play: a hole given up before a ball is struck on it is the hole the header shows", "[modes][golf][formats]") {
  // Two friends at one keyboard: each hole given up at once, hole 1 and then hole 2 (the
  // header showed hole 1 under "Bob concedes hole 2").
  GolfPlay play(test::assets(), first_hole(3), tour_match("Bob", true));
  REQUIRE(play.human_turn());
  play.update({at(IntentKind::Concede, 1.0), at(IntentKind::Concede, 1.5)}, 1.5);
  REQUIRE(play.group().hole_index() == 1);
  CHECK(play.hole_shown() == 0);
  play.update({at(IntentKind::Continue, 6.0)}, 6.0);
  REQUIRE(play.stage() == GolfPlay::Stage::Aiming);
  REQUIRE(play.human_turn());
  CHECK(play.hole_shown() == 1);
  play.update({at(IntentKind::Concede, 6.5), at(IntentKind::Concede, 7.0)}, 7.0);
  REQUIRE(play.group().hole_index() == 2);
  CHECK(play.stage() == GolfPlay::Stage::HoleOver);
  CHECK(play.hole_shown() == 1);
  CHECK_FALSE(play.last_shot_on_hole_shown());  // nothing struck in this round to show
}

TEST_CASE("a hole given up unplayed does not show the previous hole's last stroke as its own", "[modes][golf][formats]") {
  // Both play hole 1 out with the caddie's strokes, then Bob gives up hole 2 before a ball is
  // struck on it: the card of hole 2 has no stroke of its own to show.
  GolfPlay play(test::assets(), first_hole(3), tour_match("Bob", true));
  double t = 1.0;
  // One intent half a second on: Enter, or the caddie's stroke when it is a human's turn.
  const auto step = [&](IntentKind kind) {
    t += 0.5;
    play.update({at(kind, t)}, t);
  };
  REQUIRE(play.human_turn());
  play.update({at(IntentKind::CaddiePlays, t)}, t);
  while (play.stage() != GolfPlay::Stage::Aiming && t < 60.0) step(IntentKind::Continue);
  REQUIRE(play.last_shot_on_hole_shown());  // the stroke just struck, on hole 1
  while (play.group().hole_index() == 0 && t < 200.0)
    step(play.stage() == GolfPlay::Stage::Aiming && play.human_turn() ? IntentKind::CaddiePlays : IntentKind::Continue);
  REQUIRE(play.group().hole_index() == 1);
  while (play.stage() != GolfPlay::Stage::Aiming && t < 300.0) step(IntentKind::Continue);
  REQUIRE(play.human_turn());
  play.update({at(IntentKind::Concede, t + 0.5), at(IntentKind::Concede, t + 1.0)}, t + 1.0);
  REQUIRE(play.stage() == GolfPlay::Stage::HoleOver);
  CHECK(play.hole_shown() == 1);
  CHECK_FALSE(play.last_shot_on_hole_shown());
}


TEST_CASE("G: the caddie reads a putt: his line holes it, breaks the way the green falls, paced for the slope",
          "[modes][golf][putting]") {
  int read = 0, breaking = 0, uphill = 0, downhill = 0;
  for (std::size_t n = 0; n < 18; ++n) {
    for (int k = 0; k < 4; ++k) {
      const std::optional<Course> course = test::national_hole_from_green(n, 4.0, kPi / 2.0 * k + 0.3);
      if (!course) continue;
      GolfPlay play(test::assets(), *course, solo("tour"));
      REQUIRE(play.round().lie() == "green");
      CHECK_FALSE(play.putt_read());
      play.update({at(IntentKind::AimRight, 0.5), at(IntentKind::ReadGreen, 1.0)}, 1.0);
      REQUIRE(play.putt_read());
      const GolfPlay::PuttRead& r = *play.putt_read();
      ++read;
      // It lines the player up along his line and leaves the stroke to him: nothing struck.
      CHECK(play.aim() == r.aim);
      CHECK(play.club() == "putter");
      CHECK(play.round().card().back().strokes == 0);
      // His putt, struck at his pace along his line, drops; the drawn line runs from the ball
      // into the cup.
      StrokeInput putt;
      putt.club = "putter";
      putt.aim = play.aim();
      putt.meter.power = r.power;
      CHECK(play.round().simulate(putt).end == ShotEnd::Holed);
      CHECK(r.holes);
      REQUIRE(r.line.size() >= 2);
      const Vec3 ball = play.round().ball(), pin = course->holes[0].pin;
      CHECK(std::hypot(r.line.front().x() - ball.x(), r.line.front().z() - ball.z()) < 0.05);
      CHECK(std::hypot(r.line.back().x() - pin.x(), r.line.back().z() - pin.z()) < 0.108);
      // It breaks the way the green falls across the line, halfway to the cup: falling to the
      // right, the ball curls right, so he aims left of the cup.
      const Vec3 mid = 0.5 * (ball + pin);
      SurfaceContact hit;
      REQUIRE(ground_under(*course->holes[0].world->world, mid.x(), mid.z(), 400.0, 420.0, &hit));
      const double line = play.round().line_to_pin();
      const double fall_right = (hit.normal.x() * -std::sin(line) + hit.normal.z() * std::cos(line)) / hit.normal.y();
      if (std::abs(fall_right) > 0.01 && std::abs(r.aim_off) > 0.05) {
        ++breaking;
        INFO("hole " << n + 1 << ": falls " << fall_right << " to the right, aim " << r.aim_off << " m right of the cup");
        CHECK((fall_right > 0.0) == (r.aim_off < 0.0));
      }
      // Uphill he strikes it as a longer putt on flat, downhill as a shorter one.
      const double rise = pin.y() - ball.y();
      if (rise > 0.04) {
        ++uphill;
        CHECK(r.plays_as > r.to_cup);
      } else if (rise < -0.04) {
        ++downhill;
        CHECK(r.plays_as < r.to_cup);
      }
      // G again hides it; a stroke played clears it.
      play.update({at(IntentKind::ReadGreen, 1.5)}, 1.5);
      CHECK_FALSE(play.putt_read());
    }
  }
  INFO(read << " putts read: " << breaking << " breaking, " << uphill << " uphill, " << downhill << " downhill");
  CHECK(read >= 60);
  CHECK(breaking >= 20);
  CHECK(uphill >= 8);
  CHECK(downhill >= 8);
}

TEST_CASE("G off the green says where it reads; a putt abandoned says so; a stroke clears the read", "[modes][golf][putting]") {
  GolfPlay play(test::assets(), first_hole(), solo("tour"));
  REQUIRE(play.round().lie() != "green");
  play.update({at(IntentKind::ReadGreen, 1.0)}, 1.0);
  CHECK_FALSE(play.putt_read());
  CHECK(play.message() == "G reads a putt once the ball is on the green");
  double t = 1.0;
  while (play.round().lie() != "green" && play.stage() != GolfPlay::Stage::RoundOver) {
    t += 1.0;
    play.update({at(IntentKind::CaddiePlays, t), at(IntentKind::Continue, t + 0.1)}, t + 0.2);
  }
  REQUIRE(play.round().lie() == "green");
  play.update({at(IntentKind::ReadGreen, t + 1.0)}, t + 1.0);
  REQUIRE(play.putt_read());
  // A putt left at the top of its meter is abandoned in a putt's words (two clicks, not three).
  play.update({at(IntentKind::Swing, t + 1.5)}, t + 30.0);
  CHECK(play.stage() == GolfPlay::Stage::Aiming);
  CHECK(play.message() == "Putt abandoned, no stroke counted (Space: start, Space: power)");
  play.update({at(IntentKind::CaddiePlays, t + 31.0)}, t + 31.0);
  CHECK_FALSE(play.putt_read());
}

TEST_CASE("the map's prior spread is what a golfer of the player's skill spreads the club by", "[modes][golf]") {
  // Before the player's own swings give one, the map draws the dispersion of his skill's
  // meter errors (GolferSkill: the power click's and the third click's spreads), flown from
  // here. Against the same errors drawn: 48 drives with the skill's errors, the carry's and
  // the landing side's standard deviations sit near the prior's (its straight lines through
  // ±2 sd; a sample's sd of 48 is within ~±20 % at 2 sd).
  const Course course = first_hole();
  for (const char* skill : {"tour", "amateur"}) {
    CAPTURE(skill);
    GolfPlay tee(test::assets(), course, solo(skill));
    const auto prior = tee.skill_spread("driver");
    REQUIRE(prior);
    CHECK(prior->carry_sd > 0.5);
    CHECK(prior->side_sd > 1.0);
    CHECK_FALSE(tee.skill_spread("putter"));
    const GolferSkill& sk = golfer_skill(skill);
    Rng rng(11);
    double n = 0.0, c = 0.0, c2 = 0.0, s = 0.0, s2 = 0.0;
    for (int k = 0; k < 48; ++k) {
      StrokeInput in;
      in.club = "driver";
      in.aim = tee.aim();
      in.meter.power = std::clamp(1.0 + rng.normal(sk.power_sd), 0.02, 1.1);
      in.meter.accuracy_ms = std::clamp(rng.normal(sk.accuracy_sd_ms), -200.0, 200.0);
      const ShotResult r = tee.round().simulate(in);
      const double carry = r.trajectory.summary.carry_m, side = side_of_aim(r, r.trajectory.summary.landing_position);
      n += 1.0;
      c += carry;
      c2 += carry * carry;
      s += side;
      s2 += side * side;
    }
    const double carry_sd = std::sqrt((c2 - c * c / n) / (n - 1.0)), side_sd = std::sqrt((s2 - s * s / n) / (n - 1.0));
    INFO("drawn: carry sd " << carry_sd << " m, side sd " << side_sd << " m; prior " << prior->carry_sd << ", " << prior->side_sd);
    CHECK(prior->carry_sd == Approx(carry_sd).epsilon(0.25));
    CHECK(prior->side_sd == Approx(side_sd).epsilon(0.25));
  }
  // The better golfer's is the smaller.
  GolfPlay tour(test::assets(), course, solo("tour")), amateur(test::assets(), course, solo("amateur"));
  CHECK(tour.skill_spread("7-iron")->side_sd < amateur.skill_spread("7-iron")->side_sd);
}

TEST_CASE("a holed stroke is told with what it scored, and from where it went in", "[modes][golf]") {
  GolfPlay play(test::assets(), first_hole(), solo("tour"));
  double t = 0.0;
  std::string told;
  for (int k = 0; k < 40 && told.empty(); ++k) {
    t += 1.0;
    play.update({at(IntentKind::CaddiePlays, t)}, t);
    for (int i = 0; i < 30 && told.empty(); ++i) {
      t += 0.5;
      play.update({}, t);
      if (play.message().find("In the hole") != std::string::npos) told = play.message();
    }
    if (told.empty()) play.update({at(IntentKind::Continue, t + 0.1)}, t + 0.2);
  }
  INFO(told);
  REQUIRE_FALSE(told.empty());
  const HoleCard& card = play.group().round(0).card().front();
  std::string score = card.strokes == 1 ? std::string("a hole in one") : score_name(card.strokes, card.par);
  if (score.empty()) score = "par";
  score[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(score[0])));
  CHECK_THAT(told, Catch::Matchers::EndsWith("! " + score));
  const std::string& lie = card.shots.back().lie;
  CHECK_THAT(told, Catch::Matchers::Contains(lie == "green" ? std::string(": In the hole! ") : ": In the hole from the " + lie + "! "));
}
