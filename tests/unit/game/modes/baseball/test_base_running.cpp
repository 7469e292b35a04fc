// Base running on one play (base_running.hpp): a runner sent home on a single is out now and
// then, as the throw comes, but never once the winning run has scored (Rule 5.08(b)); a
// fielder's choice at third needs the man covering it there.
#include <catch2/catch.hpp>

#include "game/content/resolve.hpp"
#include "game/modes/baseball/base_running.hpp"
#include "game/modes/baseball/batting.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

// A single to right field that the fielder has ready to throw `ready` s after contact.
PlateAppearance single_to_right(double ready) {
  PlateAppearance pa;
  pa.batter = 0;
  PitchRecord rec;
  rec.call = PitchResult::InPlay;
  rec.result.contact = true;
  rec.result.outcome = BattedOutcome::Single;
  FieldingPlay& p = rec.result.play;
  p.outcome = BattedOutcome::Single;
  p.type = BattedBallType::GroundBall;
  p.fielder = 8;  // RF
  p.fielded_at = Vec3(55.0, 0.0, 25.0);
  p.fielded_time = ready;
  p.ready_time = ready;
  p.start = fielder_spots(false);
  pa.pitches.push_back(rec);
  return pa;
}

HalfInning half(const Bases& bases) {
  ShotSpec spec;
  spec.sport = "baseball";
  spec.strike = LaunchStrike{};
  const ResolvedShot r = resolve(spec, test::assets());
  HalfInning h;
  h.aero = r.aero;
  h.environment = r.spec.environment;
  h.bases = bases;
  return h;
}

}  // namespace

TEST_CASE("a runner sent home on a single is thrown out now and then, never after the winning run scores",
          "[baseball][game][running]") {
  const Team batting(test::assets(), "home", batter_skill("pro"), 3);
  const Team fielding(test::assets(), "away", batter_skill("pro"), 4);
  // The fielder is slow to the ball: the runner from second is sent with a little to spare.
  const PlateAppearance pa = single_to_right(4.6);
  int thrown_out = 0, scored_second = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    for (int to_win : {0, 1}) {
      HalfInning h = half({-1, 5, 6});  // men on second and third
      h.runs_to_win = to_win;
      Rng throws(seed);
      std::vector<int> scored;
      int outs_made = 0;
      std::string words = "Single to RF";
      h.advance(pa, batting, fielding, throws, scored, outs_made, words);
      REQUIRE(!scored.empty());
      CHECK(scored.front() == 6);  // the man on third scores first
      CHECK(h.outs == outs_made);
      if (to_win == 1) {
        // The game was over when he crossed the plate: no one is put out after it.
        CHECK(outs_made == 0);
        CHECK(words == "Single to RF");
      } else {
        thrown_out += outs_made;
        scored_second += static_cast<int>(scored.size()) - 1;
        if (outs_made == 1) CHECK(words == "Single to RF, runner from 2nd out at home (RF to C)");
      }
    }
  }
  INFO(thrown_out << " thrown out at home and " << scored_second << " scored from second in 200 plays");
  CHECK(thrown_out > 5);  // sent with ~0.3 s to spare: about one in fifteen (kThrowSpread 0.2 s)
  CHECK(thrown_out < 80);
  CHECK(scored_second + thrown_out == 200);  // he was sent every time
}

TEST_CASE("a runner reaches his top speed as a sprinter does: MLB's steal time from a stand", "[baseball][game][running]") {
  const double league = batter_skill("pro").sprint_speed;  // 27 ft/s: Statcast's league average
  // Baseball Factory's scouting standard: an average MLB steal of second takes 3.30 s from the
  // runner's first move off a 12 ft lead (the slide included).
  CHECK(sprint_time(league, ft_to_m(78.0), 0.0) == Approx(3.30).margin(0.05));
  // Already at top speed he gains nothing more; from a stand he is slower, never faster.
  CHECK(sprint_time(league, 20.0, league) == Approx(20.0 / league).epsilon(1e-12));
  for (double d : {0.5, 3.0, 10.0, 27.432, 60.0}) {
    CHECK(sprint_time(league, d, 0.0) > d / league);
    CHECK(sprint_time(league, d, 0.0) > sprint_time(league, d, 1.0));
    CHECK(sprint_time(league, d, 1.0) > sprint_time(league, d, 3.0));
  }
  // Once up to speed he trails a runner at top speed all the way by a fixed time (under a
  // second: 90 ft from a stand at 27 ft/s is no slower than Statcast's 4.47 s home to first,
  // which has the swing's finish in it as well).
  const double lag = sprint_time(league, 100.0, 0.0) - 100.0 / league;
  CHECK(sprint_time(league, 200.0, 0.0) - 200.0 / league == Approx(lag).margin(1e-9));
  CHECK(lag > 0.2);
  CHECK(sprint_time(league, ft_to_m(90.0), 0.0) < 4.47);
  CHECK(sprint_time(league, 0.0, 0.0) == 0.0);
}
