// The batting cage's model driven by timestamped intents: a swing is timed from its key
// press against the pitch's arrival, whatever the frame rate.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <set>
#include <string>

#include "game/modes/baseball/cage.hpp"
#include "game/modes/baseball/fielding.hpp"
#include "game/modes/baseball/figures.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"
#include "support/cage_play.hpp"
#include "support/intent_at.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using test::at;

namespace {

// A pitch called at 1 s and swung at on time, at 50 frames a second, until the swing is
// recorded: the mode's time then.
double pitch_and_swing_on_time(BattingCage& cage) {
  cage.update({at(IntentKind::Pitch, 1.0)}, 1.0);
  const double on_time = 1.0 + (kWindupTime + cage.pitch().flight_time) / BattingCage::kPitchTimeScale;
  double now = 1.0;
  while (now + 0.02 < on_time) cage.update({}, now += 0.02);
  cage.update({at(IntentKind::Swing, on_time)}, now = on_time);
  while (cage.swings().empty() && now < 10.0) cage.update({}, now += 0.02);
  return now;
}

}  // namespace


TEST_CASE("a swing's timing is its key press against the pitch's arrival, at any frame rate", "[modes][baseball]") {
  for (const double dt : {0.016, 0.033, 0.066}) {
    for (const double late_ms : {0.0, 8.0, -20.0, -40.0}) {
      CAPTURE(dt, late_ms);
      BattingCage cage(test::assets());
      cage.update({at(IntentKind::Pitch, 1.0)}, 1.0);
      REQUIRE(cage.stage() == BattingCage::Stage::Pitching);
      // The pitch plays slowed: it leaves the hand after the wind-up and arrives
      // kPitchTimeScale-stretched after release.
      const double arrive = 1.0 + (kWindupTime + cage.pitch().flight_time) / BattingCage::kPitchTimeScale;
      const double key = arrive + late_ms / 1000.0 * (1.0 / BattingCage::kPitchTimeScale);
      double now = 1.0;
      bool sent = false;
      while (cage.stage() == BattingCage::Stage::Pitching) {
        now += dt;
        Intents frame;
        if (!sent && key <= now) {
          frame.push_back(at(IntentKind::Swing, key));
          sent = true;
        }
        cage.update(frame, now);
      }
      REQUIRE(cage.swings().size() == 1);
      CHECK(cage.swings().back().timing_ms == Approx(late_ms).margin(1e-6));
      CHECK_FALSE(cage.swings().back().by_pro);
      // A miss is called when the pitch reaches the plate, at any frame rate.
      if (!cage.swings().back().result.contact) {
        while (!cage.told()) cage.update({}, now += dt);
        CHECK(now < arrive + dt + 1e-9);
      }
      // The call gives the press's error as the player lived it: the pitch plays at half
      // speed, so 20 ms of pitch time early was his key 40 ms early.
      // 20 ms early the bat has turned ~53° past square: the ball crosses its line past the
      // end, and the call says so.
      if (late_ms < -10.0 && late_ms > -30.0) {
        CHECK_FALSE(cage.swings().back().result.contact);
        CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("early by 40 ms, the bat had turned too far: the ball went by past its end"));
      }
      // 40 ms early the bat has turned past a right angle: it was through the zone.
      if (late_ms < -30.0) {
        CHECK_FALSE(cage.swings().back().result.contact);
        CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("early by 80 ms, the bat already through the zone"));
      }
    }
  }
}

TEST_CASE("a pitch left alone is called; the pro swings on request; restart clears the session", "[modes][baseball]") {
  BattingCage cage(test::assets());
  cage.update({at(IntentKind::Pitch, 0.5)}, 0.5);
  cage.update({}, 0.5 + (kWindupTime + cage.pitch().flight_time + BattingCage::kTakenAfter) / BattingCage::kPitchTimeScale + 0.01);
  CHECK(cage.stage() == BattingCage::Stage::Called);
  CHECK((cage.call_text() == "Ball" || cage.call_text() == "Called strike"));
  CHECK(cage.swings().empty());
  CHECK(cage.pitches_done() == 1);  // a pitch taken is a pitch of the session (play --pitches)
  // Space: the next pitch; B during the wind-up asks the pro to swing at it: he does when it
  // reaches him (a second B changes nothing).
  cage.update({at(IntentKind::Swing, 5.0), at(IntentKind::BotSwings, 5.2)}, 5.3);
  CHECK(cage.swings().empty());
  const double arrive = 5.0 + (kWindupTime + cage.pitch().flight_time) / BattingCage::kPitchTimeScale;
  cage.update({at(IntentKind::BotSwings, 5.0 + kWindupTime / BattingCage::kPitchTimeScale + 0.05)}, arrive - 0.1);
  CHECK(cage.swings().empty());
  cage.update({}, arrive + 0.2);
  REQUIRE(cage.swings().size() == 1);
  CHECK(cage.pitches_done() == 2);
  CHECK(cage.swings().back().result.contact);
  CHECK(std::abs(cage.swings().back().timing_ms) < 30.0);
  // While the batted ball flies the call is its launch; its outcome when it comes down.
  REQUIRE(cage.stage() == BattingCage::Stage::Batted);
  CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("mph off the bat"));
  // ... and where on the bat he met it.
  CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("on the barrel") || Catch::Matchers::Contains("off the end of the bat") ||
                                   Catch::Matchers::Contains("in on the hands"));
  cage.update({}, arrive + 30.0);
  CHECK(cage.stage() == BattingCage::Stage::Called);
  CHECK_THAT(cage.call_text(), !Catch::Matchers::Contains("mph off the bat"));
  cage.update({at(IntentKind::Restart, 36.0)}, 36.0);
  CHECK(cage.swings().empty());
  CHECK(cage.pitches_done() == 0);
  CHECK(cage.stage() == BattingCage::Stage::Ready);
}

TEST_CASE("a live at-bat: the league's pitcher mixes his pitches, the count decides the plate appearance",
          "[modes][baseball]") {
  BattingCage cage(test::assets(), 3);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);
  REQUIRE(cage.live());
  double now = 1.0;
  std::set<std::string> types;
  // A batter who never swings: every plate appearance ends in a walk, a called strikeout or
  // a hit-by-pitch, and the count follows the calls.
  while (cage.at_bats().pa < 3) {
    const Count before = cage.count();
    cage.update({at(IntentKind::Pitch, now)}, now);
    REQUIRE(cage.stage() == BattingCage::Stage::Pitching);
    types.insert(cage.call().type.type);
    now += (kWindupTime + cage.pitch().flight_time + BattingCage::kTakenAfter) / BattingCage::kPitchTimeScale + 0.01;
    cage.update({}, now);
    REQUIRE(cage.stage() == BattingCage::Stage::Called);
    const std::string& text = cage.call_text();
    const bool ended = text == "Walk" || text == "Strikeout looking" || text == "Hit by pitch";
    if (ended) {
      CHECK((cage.count().balls == 0 && cage.count().strikes == 0));
    } else {
      CHECK(cage.count().balls + cage.count().strikes == before.balls + before.strikes + 1);
    }
    now += 0.5;
  }
  const BattingCage::AtBats& a = cage.at_bats();
  CHECK(a.walks + a.strikeouts + a.hit_by_pitch == 3);
  CHECK(a.hits == 0);
  CHECK(types.size() >= 2);  // not one pitch over and over
}

TEST_CASE("B between pitches calls for one and the pro swings at it, at the same instant at any frame rate",
          "[modes][baseball]") {
  std::vector<double> timings;
  for (const double dt : {0.016, 0.05}) {
    BattingCage cage(test::assets(), 21);
    cage.update({at(IntentKind::BotSwings, 1.0)}, 1.0);
    REQUIRE(cage.stage() == BattingCage::Stage::Pitching);
    double now = 1.0;
    while (cage.swings().empty() && now < 10.0) cage.update({}, now += dt);
    REQUIRE(cage.swings().size() == 1);
    CHECK(cage.swings().back().by_pro);  // his, not the player's: the HUD's figures leave it out
    CHECK_THAT(cage.call_text(), Catch::Matchers::StartsWith("The pro: "));
    timings.push_back(cage.swings().back().timing_ms);
    // His bat met the ball at his timing's instant, not at the frame that saw it.
    const double contact = 1.0 + (kWindupTime + cage.pitch().flight_time + 1e-3 * timings.back()) / BattingCage::kPitchTimeScale;
    CHECK(cage.swung_at() == Approx(contact).margin(1e-9));
  }
  CHECK(timings[0] == timings[1]);
}

TEST_CASE("a miss is called in a hitter's words and inches, never '0 in'", "[modes][baseball]") {
  SwingResult r;
  r.crossing_undercut = 0.066 + 0.004;  // the bat 4 mm under the ball's edge
  CHECK(miss_call(r, 3.0) == "Swinging strike: the bat missed under the ball by 0.2 in");
  r.crossing_undercut = -(0.066 + 0.0002);
  CHECK(miss_call(r, -3.0) == "Swinging strike: the bat missed over the ball by 0.1 in");
  r.crossing_undercut = 0.066 + 0.031;
  CHECK(miss_call(r, 3.0) == "Swinging strike: the bat missed under the ball by 1 in");
  // The bat set 14 cm under the ball, past the 8 cm the swing's physics takes: the call gives
  // the 14 cm (less the reach: 7.4 cm, 3 in), not the 8 cm the physics swung at.
  r.crossing_undercut = 0.08;
  CHECK(miss_call(r, 3.0, 0.06) == "Swinging strike: the bat missed under the ball by 3 in");
  r.crossing_undercut = -0.08;
  CHECK(miss_call(r, 3.0, -0.10) == "Swinging strike: the bat missed over the ball by 4 in");
  // Timing only: the height was the pro's read, so the miss is said by the player's timing.
  CHECK(miss_call(r, 23.4, -0.10, true) == "Swinging strike: late by 23 ms; at the height the pro read, the bat passed 4 in over the ball");
  // Past the end and over the ball as well: both said.
  r.crossing_undercut = -0.12;
  r.past_end = true;
  CHECK(miss_call(r, -20.0) ==
        "Swinging strike: early by 20 ms, the bat had turned too far: the ball went by past its end (wait a touch longer), and 2 in over it");
  CHECK(miss_call(r, -20.0, 0.0, true) == "Swinging strike: early by 20 ms, the bat had turned too far: the ball went by past its end (wait a touch longer)");
  r.crossing_undercut = 0.0;
  CHECK(miss_call(r, -14.2) == "Swinging strike: early by 14 ms, the bat had turned too far: the ball went by past its end (wait a touch longer)");
  CHECK(miss_call(r, 17.0) == "Swinging strike: late by 17 ms, the bat had not come around: the ball went by past its end (start the swing sooner)");
  // The pro's own miss: told, not advised (the advice is the player's).
  CHECK(miss_call(r, 17.0, 0.0, false, false) == "Swinging strike: late by 17 ms, the bat had not come around: the ball went by past its end");
  r.past_end = false;
  r.through = true;
  CHECK(miss_call(r, 48.0) == "Swinging strike: late by 48 ms, the bat not around yet");
}

TEST_CASE("a swing past the end with the bat set on the ball's line is not called over or under it", "[modes][baseball]") {
  // Early, the turned bat's axis crosses the ball's line metres out toward the pitcher, where
  // the ball is still well above the swing plane: a height read there (71 in in play) is not
  // the bat's. Set on the ball's line, the call is timing alone.
  PitchCall c;
  c.type = pitch_type(load_pitch_types(test::assets()), "four-seam");
  c.target_height = 0.5 * (StrikeZone::kLow + StrikeZone::kHigh);
  const PitchFlight pitch = throw_pitch(test::assets(), c);
  int past_end = 0;
  for (double early_ms = 5.0; early_ms <= 40.0; early_ms += 1.0) {
    CAPTURE(early_ms);
    SwingInput s;
    s.timing_ms = -early_ms;
    s.undercut = 0.0;
    const SwingResult r = swing_at(test::assets(), pitch, s, batter_skill("pro").bat_speed);
    if (!r.past_end) continue;
    ++past_end;
    CHECK(r.crossing_undercut == 0.0);
    CHECK_THAT(miss_call(r, -2.0 * early_ms), !Catch::Matchers::Contains("over it") && !Catch::Matchers::Contains("under it"));
  }
  // The case arises: some of these timings send the ball by past the end.
  CHECK(past_end > 0);
  // Set 80 mm over the ball's centre (0.6 in over its edge), the call says so past the end too.
  SwingInput s;
  s.timing_ms = -25.0;
  s.undercut = SwingInput::kUndercut.min;
  const SwingResult r = swing_at(test::assets(), pitch, s, batter_skill("pro").bat_speed);
  REQUIRE(r.past_end);
  CHECK_THAT(miss_call(r, -50.0), Catch::Matchers::EndsWith("and 0.6 in over it"));
}

TEST_CASE("a swing pressed during the windup is refused in words; strike three swinging keeps its miss", "[modes][baseball]") {
  BattingCage cage(test::assets(), 3);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);
  REQUIRE(cage.live());
  double now = 1.0;
  // Space during the windup: no swing, and the batter is told why.
  cage.update({at(IntentKind::Pitch, now)}, now);
  cage.update({at(IntentKind::Swing, now + 0.1)}, now + 0.1);
  CHECK(cage.swings().empty());
  CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("Too soon"));
  now += (kWindupTime + cage.pitch().flight_time + BattingCage::kTakenAfter) / BattingCage::kPitchTimeScale + 0.01;
  cage.update({}, now);
  CHECK_THAT(cage.call_text(), !Catch::Matchers::Contains("Too soon"));  // the pitch's call replaces it
  CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("(your swing came too soon: before the pitch)"));  // and keeps why
  // Swinging 300 ms early at every pitch until the plate appearance ends: strike three
  // swinging says how he missed, as strikes one and two did.
  int guard = 0;
  while (cage.at_bats().pa < 1 && ++guard < 20) {
    now += 0.5;
    cage.update({at(IntentKind::Pitch, now)}, now);
    const double arrive = now + (kWindupTime + cage.pitch().flight_time) / BattingCage::kPitchTimeScale;
    cage.update({at(IntentKind::Swing, arrive - 0.3 / BattingCage::kPitchTimeScale)}, arrive - 0.3 / BattingCage::kPitchTimeScale);
    now = arrive + BattingCage::kTakenAfter / BattingCage::kPitchTimeScale + 0.5;
    cage.update({}, now);
    if (cage.at_bats().pa == 0) {
      CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("early by 600 ms"));  // 300 ms of pitch time
      CHECK_THAT(cage.call_text(), Catch::Matchers::Contains(")"));  // the count follows
    }
  }
  REQUIRE(cage.at_bats().strikeouts == 1);
  CHECK_THAT(cage.call_text(), Catch::Matchers::StartsWith("Strikeout swinging: early by 600 ms"));
}

TEST_CASE("a swing through a pitch early is called a strike when the pitch reaches the plate, not before", "[modes][baseball]") {
  BattingCage cage(test::assets(), 3);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);
  double now = 1.0;
  cage.update({at(IntentKind::Pitch, now)}, now);
  const double arrive = now + (kWindupTime + cage.pitch().flight_time) / BattingCage::kPitchTimeScale;
  const double swung = arrive - 0.3 / BattingCage::kPitchTimeScale;  // 300 ms of pitch time early
  cage.update({at(IntentKind::Swing, swung)}, swung + 0.01);
  REQUIRE(cage.swings().size() == 1);
  REQUIRE_FALSE(cage.swings().back().result.contact);
  // The ball is still on its way: the swing is said, the strike and the count wait for it.
  CHECK_FALSE(cage.told());
  CHECK(cage.call_text() == "Swing and a miss");
  CHECK(cage.count().strikes == 0);
  CHECK(cage.board()->outs == 0);
  // A second press meanwhile is no second swing and no next pitch.
  cage.update({at(IntentKind::Swing, swung + 0.1)}, swung + 0.11);
  CHECK(cage.swings().size() == 1);
  CHECK(cage.stage() == BattingCage::Stage::Called);
  CHECK_THAT(cage.call_text(), Catch::Matchers::EndsWith("(one swing a pitch)"));
  // Nor is B (the pro) or P: answered, the pitch still the one on its way.
  cage.update({at(IntentKind::BotSwings, swung + 0.12)}, swung + 0.13);
  CHECK(cage.swings().size() == 1);
  CHECK(cage.stage() == BattingCage::Stage::Called);
  CHECK_THAT(cage.call_text(), Catch::Matchers::EndsWith("(the next pitch once this one is called)"));
  // At the plate: the call, with how he missed, and the strike counted.
  cage.update({}, arrive - 0.005);
  CHECK_FALSE(cage.told());
  cage.update({}, arrive + 0.005);
  CHECK(cage.told());
  CHECK_THAT(cage.call_text(), Catch::Matchers::StartsWith("Swinging strike: early by 600 ms"));
  CHECK(cage.count().strikes == 1);
  // And Space asks for the next pitch again.
  cage.update({at(IntentKind::Swing, arrive + 0.5)}, arrive + 0.5);
  CHECK(cage.stage() == BattingCage::Stage::Pitching);
}

TEST_CASE("Space pressed a beat after a pitch went by is a late swing, not a call for the next pitch", "[modes][baseball]") {
  BattingCage cage(test::assets(), 3);
  cage.update({at(IntentKind::Pitch, 0.5)}, 0.5);
  const double by = 0.5 + (kWindupTime + cage.pitch().flight_time + BattingCage::kTakenAfter) / BattingCage::kPitchTimeScale;
  // The frame the pitch goes by; the press comes a fifth of a second later.
  cage.update({at(IntentKind::Swing, by + 0.2)}, by + 0.21);
  CHECK(cage.stage() == BattingCage::Stage::Called);
  CHECK(cage.swings().empty());
  // Not lost without a word: the call says the swing came too late.
  CHECK_THAT(cage.call_text(), Catch::Matchers::StartsWith("Called strike") || Catch::Matchers::StartsWith("Ball"));
  CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("too late"));
  // By how much in his own time: the 150 ms of pitch time it took to go by (300 ms slowed)
  // and his 200 ms after that.
  CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("came 500 ms too late"));
  // Once he has had time to see the call, Space asks for the next pitch again.
  cage.update({at(IntentKind::Swing, by + 0.2 + BattingCage::kLateSwing)}, by + 0.3 + BattingCage::kLateSwing);
  CHECK(cage.stage() == BattingCage::Stage::Pitching);
}

TEST_CASE("the cage tells each pitch's movement as Statcast reads it, the seam wake's share in it", "[modes][baseball]") {
  BattingCage cage(test::assets(), 3);
  cage.update({at(IntentKind::ToggleLive, 0.1)}, 0.1);  // the league's pitcher: his mix
  REQUIRE(cage.live());
  std::set<std::string> seen;
  double now = 1.0;
  for (int i = 0; i < 40 && seen.size() < 4; ++i) {
    cage.update({at(IntentKind::Pitch, now)}, now);
    REQUIRE(cage.stage() == BattingCage::Stage::Pitching);
    const PitchMovement expect = statcast_movement(test::assets(), cage.pitch());
    CHECK(cage.movement().induced_vertical_break == expect.induced_vertical_break);
    CHECK(cage.movement().horizontal_break == expect.horizontal_break);
    // A right-hander's sinker and changeup run to his arm side (third base, Statcast's pfx_x < 0)
    // with their wake's share; a four-seamer rises.
    const std::string& type = cage.call().type.type;
    seen.insert(type);
    if (type == "sinker" || type == "changeup") {
      CHECK(cage.movement().horizontal_break < 0.0);
      CHECK(cage.movement().seam_wake_horizontal < 0.0);
    }
    if (type == "four-seam") CHECK(cage.movement().induced_vertical_break > 0.3);
    while (cage.stage() == BattingCage::Stage::Pitching) cage.update({}, now += 0.05);
    now += 2.0;
    cage.update({}, now);
  }
  CHECK(seen.size() >= 4);
}

TEST_CASE("a fielded grounder's call says where he picked it up, a fly's where it came down, a foul grounder's where it was called", "[modes][baseball]") {
  bool grounder = false, fly = false, foul_grounder = false;
  for (std::uint64_t seed = 1; seed <= 60 && !(grounder && fly && foul_grounder); ++seed) {
    BattingCage cage(test::assets(), seed);
    // On time, the bat set 0 to 5 cm above the ball's middle by seed: flies and grounders.
    for (std::uint64_t k = 0; k < seed % 3; ++k) cage.update({at(IntentKind::BatUp, 0.1 + 0.1 * k)}, 0.1 + 0.1 * k);
    double now = pitch_and_swing_on_time(cage);
    REQUIRE(cage.swings().size() == 1);
    // Met on time, and said so (a swing's timing is told on a hit as on a miss).
    if (cage.stage() == BattingCage::Stage::Batted) CHECK_THAT(cage.call_text(), Catch::Matchers::EndsWith(", on time"));
    // The call while it flies is its launch; the outcome's once it is down.
    const double until = now + 15.0;
    while (cage.stage() == BattingCage::Stage::Batted && now < until) cage.update({}, now += 0.05);
    const SwingResult& r = cage.swings().back().result;
    const bool on_ground = batted_ball_type(r.shot.launch.vertical_angle) == BattedBallType::GroundBall;
    const ShotTrajectory played = as_played(r.shot.trajectory, r.play);
    char want[48];
    if (r.contact && r.outcome == BattedOutcome::Foul && on_ground && !r.play.caught) {
      // A foul grounder: where it was called, passing the bag, touched or stopped (the field's
      // label), not its first hop nor its roll on up the line.
      foul_grounder = true;
      std::snprintf(want, sizeof want, ", %.0f ft; ", m_to_ft(played.summary.total_m));
      INFO(cage.call_text());
      CHECK_THAT(cage.call_text(), Catch::Matchers::Contains(want));
      CHECK_THAT(cage.call_text(), Catch::Matchers::EndsWith(", on time"));  // and how he met it
    }
    if (!r.contact || r.outcome == BattedOutcome::Foul || r.outcome == BattedOutcome::HomeRun) continue;
    if (on_ground && !r.play.caught && r.play.fielder >= 0) {
      grounder = true;
      std::snprintf(want, sizeof want, "fielded at %.0f ft; ", m_to_ft(played.summary.total_m));
      INFO(cage.call_text());
      CHECK_THAT(cage.call_text(), Catch::Matchers::Contains(want));
      CHECK(played.summary.total_m > r.shot.trajectory.summary.carry_m);  // past its first hop
    } else if (!on_ground) {
      fly = true;
      std::snprintf(want, sizeof want, ", %.0f ft; ", m_to_ft(played.summary.carry_m));
      INFO(cage.call_text());
      CHECK_THAT(cage.call_text(), Catch::Matchers::Contains(want));
    }
    // Once down, the call still says how he met it: where on the bat, and when.
    INFO(cage.call_text());
    CHECK_THAT(cage.call_text(), Catch::Matchers::EndsWith(", on time"));
  }
  CHECK(grounder);
  CHECK(fly);
  CHECK(foul_grounder);
}

TEST_CASE("timing only: the bat finds the pitch's height as a pro reads it, the key times the swing", "[modes][baseball]") {
  // The bat set 15 cm high: swung on time by hand it passes over nearly every pitch; with T
  // the same keys meet nearly every one.
  int met[2] = {0, 0};
  for (const bool timing_only : {false, true}) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      BattingCage cage(test::assets(), seed);
      for (int k = 0; k < 6; ++k) cage.update({at(IntentKind::BatUp, 0.1 + 0.01 * k)}, 0.1 + 0.01 * k);
      if (timing_only) cage.update({at(IntentKind::ToggleTiming, 0.2)}, 0.2);
      REQUIRE(cage.timing_only() == timing_only);
      cage.update({at(IntentKind::Pitch, 1.0)}, 1.0);
      const double on_time = 1.0 + (kWindupTime + cage.pitch().flight_time) / BattingCage::kPitchTimeScale;
      double now = 1.0;
      while (now + 0.02 < on_time) cage.update({}, now += 0.02);
      cage.update({at(IntentKind::Swing, on_time)}, on_time);
      REQUIRE(cage.swings().size() == 1);
      met[timing_only] += cage.swings().back().result.contact;
    }
  }
  CHECK(met[0] <= 2);
  CHECK(met[1] >= 8);
}

TEST_CASE("A while a ball in play is in the air waits for its call: the session is not wiped unseen", "[modes][baseball]") {
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 12 && checked < 2; ++seed) {
    BattingCage cage(test::assets(), seed);
    double now = 1.0;
    cage.update({at(IntentKind::BotSwings, now)}, now);
    while (cage.stage() == BattingCage::Stage::Pitching && now < 20.0) cage.update({}, now += 0.01);
    if (cage.stage() != BattingCage::Stage::Batted || cage.swings_told() == cage.swings().size()) continue;  // no ball in the air
    ++checked;
    cage.update({at(IntentKind::ToggleLive, now + 0.01)}, now + 0.02);
    now += 0.02;
    CHECK_FALSE(cage.live());
    CHECK(cage.swings().size() == 1);
    CHECK_THAT(cage.call_text(), Catch::Matchers::EndsWith("(A: once this ball is called)"));
    while (cage.stage() == BattingCage::Stage::Batted && now < 60.0) cage.update({}, now += 0.02);
    CHECK_THAT(cage.call_text(), !Catch::Matchers::Contains("(A: once"));  // the play's own call
    cage.update({at(IntentKind::ToggleLive, now + 0.01)}, now + 0.02);
    CHECK(cage.live());
  }
  CHECK(checked == 2);
}

TEST_CASE("the cage's difficulty is the pitch's pace: a key 40 ms early hits at easy, misses at standard", "[modes][baseball]") {
  // Timing only (the pro's read sets the bat's height): 40 ms of the player's time early is
  // 12 ms of pitch time at easy's 0.3 (inside the bat's ~14 ms window) and 20 ms at 0.5 (the
  // ball goes by past the end of the bat).
  int met[2] = {0, 0};
  const double scales[2] = {BattingCage::kEasyPitchTimeScale, BattingCage::kPitchTimeScale};
  for (int k = 0; k < 2; ++k) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      BattingCage cage(test::assets(), seed, scales[k]);
      cage.update({at(IntentKind::ToggleTiming, 0.1)}, 0.1);
      double now = 1.0;
      cage.update({at(IntentKind::Pitch, now)}, now);
      const double arrive = now + (kWindupTime + cage.pitch().flight_time) / scales[k];
      CHECK(cage.pitch_clock(arrive) == Approx(cage.pitch().flight_time));
      const double key = arrive - 0.040;
      bool sent = false;
      while (cage.stage() == BattingCage::Stage::Pitching) {
        now += 0.01;
        Intents f;
        if (!sent && key <= now) f.push_back(at(IntentKind::Swing, key)), sent = true;
        cage.update(f, now);
      }
      REQUIRE(cage.swings().size() == 1);
      CHECK(cage.swings().back().timing_ms == Approx(-40.0 * scales[k]).margin(1e-6));  // pitch time
      met[k] += cage.swings().back().result.contact;
      // A hit says its timing in the player's time, as a miss does.
      if (cage.swings().back().result.contact) CHECK_THAT(cage.call_text(), Catch::Matchers::EndsWith(", 40 ms early"));
    }
  }
  CHECK(met[0] >= 8);
  CHECK(met[1] <= 1);
  CHECK_THROWS_AS(BattingCage(test::assets(), 1, 0.05), InputError);
  CHECK_THROWS_AS(BattingCage(test::assets(), 1, 1.5), InputError);
}

TEST_CASE("E steps the next pitch's pace: standard, easy, pro, standard; a pitch thrown keeps its own", "[modes][baseball]") {
  BattingCage cage(test::assets());
  REQUIRE(cage.next_time_scale() == BattingCage::kPitchTimeScale);
  cage.update({at(IntentKind::TogglePace, 0.5)}, 0.5);
  CHECK(cage.next_time_scale() == BattingCage::kEasyPitchTimeScale);
  CHECK(cage.call_text() == "Pitch pace: easy, 30 % of real speed (hit within about 47 ms)");
  cage.update({at(IntentKind::TogglePace, 0.6)}, 0.6);
  CHECK(cage.next_time_scale() == BattingCage::kProPitchTimeScale);
  CHECK(cage.call_text() == "Pitch pace: pro, real speed (hit within about 14 ms)");
  cage.update({at(IntentKind::TogglePace, 0.7), at(IntentKind::TogglePace, 0.8)}, 0.8);
  REQUIRE(cage.next_time_scale() == BattingCage::kEasyPitchTimeScale);
  // Thrown at the easy pace, it arrives when that pace says, whatever E does on its way or
  // just after a swing through it (the pitch is still drawn flying on its clock).
  cage.update({at(IntentKind::Pitch, 1.0)}, 1.0);
  REQUIRE(cage.time_scale() == BattingCage::kEasyPitchTimeScale);
  const double released = 1.0 + kWindupTime / BattingCage::kEasyPitchTimeScale;
  cage.update({at(IntentKind::TogglePace, released + 0.05)}, released + 0.05);
  CHECK(cage.time_scale() == BattingCage::kEasyPitchTimeScale);
  CHECK(cage.next_time_scale() == BattingCage::kProPitchTimeScale);
  const double early_swing = released + 0.1;  // far too early: a miss, called at once
  cage.update({at(IntentKind::Swing, early_swing)}, early_swing);
  REQUIRE(cage.stage() == BattingCage::Stage::Called);
  cage.update({at(IntentKind::TogglePace, early_swing + 0.05)}, early_swing + 0.05);
  CHECK(cage.next_time_scale() == BattingCage::kPitchTimeScale);
  const double arrives = released + cage.pitch().flight_time / BattingCage::kEasyPitchTimeScale;
  CHECK(cage.pitch_clock(arrives) == Approx(cage.pitch().flight_time).margin(1e-9));
  // The next pitch comes at the pace chosen last.
  cage.update({at(IntentKind::Pitch, arrives + 5.0)}, arrives + 5.0);
  CHECK(cage.time_scale() == BattingCage::kPitchTimeScale);
}

TEST_CASE("A keeps the record it leaves: batting practice's swings and the live game come back on the way back",
          "[modes][baseball]") {
  BattingCage cage(test::assets(), 9);
  double now = 0.5;
  // B pitches and lets the pro swing; on until the call.
  const auto pro_swings = [&] {
    cage.update({at(IntentKind::BotSwings, now)}, now);
    test::play_out_pitch(cage, now, 0.05);
    now += 0.5;
  };
  for (int k = 0; k < 3; ++k) pro_swings();
  const std::size_t practice = cage.swings().size();
  REQUIRE(practice >= 1);
  const std::string first_said = cage.swings().front().said;
  cage.update({at(IntentKind::ToggleLive, now)}, now);
  REQUIRE(cage.live());
  CHECK(cage.swings().empty());  // the game's own record
  REQUIRE(cage.other_figures());
  CHECK(cage.other_figures()->by_pro == static_cast<int>(practice));
  while (cage.at_bats().pa < 4) pro_swings();
  const int pa = cage.at_bats().pa;
  const int inning = cage.board()->inning, runs = cage.board()->runs();
  const std::size_t game_swings = cage.swings().size();
  cage.update({at(IntentKind::ToggleLive, now)}, now);
  REQUIRE_FALSE(cage.live());
  CHECK(cage.call_text() == "Back to batting practice");
  REQUIRE(cage.swings().size() == practice);
  CHECK(cage.swings().front().said == first_said);
  CHECK(cage.board() == nullptr);
  cage.update({at(IntentKind::ToggleLive, now + 0.1)}, now + 0.1);
  REQUIRE(cage.live());
  CHECK(cage.call_text() == "Back to the live game");
  CHECK(cage.at_bats().pa == pa);
  CHECK(cage.swings().size() == game_swings);
  CHECK(cage.board()->inning == inning);
  CHECK(cage.board()->runs() == runs);
  // Restart clears both.
  cage.update({at(IntentKind::Restart, now + 0.2)}, now + 0.2);
  CHECK(cage.swings().empty());
  CHECK_FALSE(cage.other_figures());
}

TEST_CASE("a foul back to the screen is called so, not by the backstop's 60 ft", "[modes][baseball]") {
  // A bat set under the ball's middle sends fouls back over the catcher, dead at the backstop
  // (stop_at_backstop): each would read the same 60 ft.
  int back = 0;
  for (std::uint64_t seed = 1; seed <= 80 && back < 2; ++seed) {
    BattingCage cage(test::assets(), seed);
    const int down = 3 + static_cast<int>(seed % 3);
    for (int k = 0; k < down; ++k) cage.update({at(IntentKind::BatDown, 0.1 + 0.1 * k)}, 0.1 + 0.1 * k);
    double now = pitch_and_swing_on_time(cage);
    const double until = now + 15.0;
    while (cage.stage() == BattingCage::Stage::Batted && now < until) cage.update({}, now += 0.05);
    REQUIRE(cage.swings().size() == 1);
    const SwingResult& r = cage.swings().back().result;
    if (!r.contact || r.outcome != BattedOutcome::Foul || r.play.caught) continue;
    const ShotTrajectory played = as_played(r.shot.trajectory, r.play);
    const Vec3& end = played.samples.back().position;
    INFO(cage.call_text());
    if (end.x() < 0.0 && std::hypot(end.x(), end.z()) >= kFoulGround - 0.01) {
      ++back;
      CHECK_THAT(cage.call_text(), Catch::Matchers::Contains(", back to the screen; "));
      CHECK_THAT(cage.call_text(), !Catch::Matchers::Contains("60 ft"));
    } else {
      CHECK_THAT(cage.call_text(), !Catch::Matchers::Contains("back to the screen"));
    }
  }
  CHECK(back >= 1);
}

TEST_CASE("a swing pressed after the pitch reached the plate, before it is called, is a late swing", "[modes][baseball]") {
  for (const double late_ms : {40.0, 70.0, 140.0}) {  // of pitch time: 80, 140, 280 ms of the player's
    CAPTURE(late_ms);
    BattingCage cage(test::assets(), 3);
    cage.update({at(IntentKind::Pitch, 1.0)}, 1.0);
    const double arrive = 1.0 + (kWindupTime + cage.pitch().flight_time) / BattingCage::kPitchTimeScale;
    const double key = arrive + late_ms / 1000.0 / BattingCage::kPitchTimeScale;
    double now = 1.0;
    while (now + 0.05 < key) cage.update({}, now += 0.05);
    cage.update({at(IntentKind::Swing, key)}, now += 0.05);
    if (late_ms < 1000.0 * BattingCage::kTakenAfter) {
      // Inside the pitch's last kTakenAfter: a swing, called late by the player's own ms.
      REQUIRE(cage.swings().size() == 1);
      while (!cage.told()) cage.update({}, now += 0.05);
      char late[32];
      std::snprintf(late, sizeof late, "late by %.0f ms", 2.0 * late_ms);
      CHECK_THAT(cage.call_text(), Catch::Matchers::Contains(late) || Catch::Matchers::Contains("ms late"));
    } else {
      // Past it: the pitch was taken, and the call says the swing came too late.
      CHECK(cage.swings().empty());
      CHECK_THAT(cage.call_text(), Catch::Matchers::Contains("too late"));
    }
  }
}

TEST_CASE("the player's misses in a row count his own swings since his last contact", "[modes][baseball]") {
  BattingCage cage(test::assets(), 3);
  double now = 1.0;
  const auto swing_early = [&](double early_s) {
    cage.update({at(IntentKind::Pitch, now)}, now);
    const double arrive = now + (kWindupTime + cage.pitch().flight_time) / BattingCage::kPitchTimeScale;
    cage.update({at(IntentKind::Swing, arrive - early_s)}, arrive - early_s);
    now = arrive + 1.0;
    cage.update({}, now);
    while (!cage.told()) cage.update({}, now += 0.5);
    now += 0.5;
  };
  for (int k = 0; k < 3; ++k) swing_early(0.6);
  CHECK(cage.misses_in_a_row() == 3);
  // The pro's swing (B) is his, not the player's: the run goes on.
  cage.update({at(IntentKind::BotSwings, now)}, now);
  now += 12.0;
  cage.update({}, now);
  while (!cage.told()) cage.update({}, now += 0.5);
  REQUIRE(cage.swings().back().by_pro);
  CHECK(cage.misses_in_a_row() == 3);
  // A ball met ends it: on time at the middle of the zone with timing only.
  cage.update({at(IntentKind::ToggleTiming, now)}, now);
  now += 0.5;
  for (int k = 0; k < 6 && cage.misses_in_a_row() > 0; ++k) swing_early(0.0);
  CHECK(cage.misses_in_a_row() == 0);
}
