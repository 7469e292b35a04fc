// Where a hitter aims along his bat (aim.hpp): inside the sweet spot by what his own scatter
// makes worth it, checked against the game's own swings.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "game/modes/baseball/aim.hpp"
#include "game/modes/baseball/hitter.hpp"
#include "game/util/rng.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

const PitchFlight& fastball() {
  static const PitchFlight f = [] {
    PitchCall c;
    c.type = pitch_type(load_pitch_types(test::assets()), "four-seam");
    c.target_height = 0.5 * (StrikeZone::kLow + StrikeZone::kHigh);
    return throw_pitch(test::assets(), c);
  }();
  return f;
}

SwingInput swing_of(const BatterSkill& skill) {
  SwingInput s;
  s.attack_angle = skill.attack_angle;
  s.swing_tilt = skill.swing_tilt;
  s.sweep = skill.sweep;
  s.undercut = 0.005;
  return s;
}

// His mean exit speed (m/s; a miss counts 0) over `n` swings at the league's fastball through
// swing_at, aiming `aim` m inside the sweet spot, with his reach and timing reads' scatter.
// The same draws for every aim, so aims are compared on the same swings.
double mean_exit_speed(const BatterSkill& skill, double aim, int n) {
  Rng rng(20261129);
  FieldingSetup flight_only;
  flight_only.field = false;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    SwingInput s = swing_of(skill);
    s.aim_inside = aim;
    s.timing_ms = rng.normal(skill.read_timing_sd_ms);
    s.reach_error = rng.normal(reach_scatter(skill));
    const SwingResult r = swing_at(test::assets(), fastball(), s, skill.bat_speed, kGameBat, flight_only);
    if (r.contact) sum += r.shot.launch.ball_speed;
  }
  return sum / n;
}

double aim_of(const BatterSkill& skill) { return aim_inside(test::assets(), skill, kGameBat); }

}  // namespace

TEST_CASE("a hitter aims inside the sweet spot, the farther the more he scatters", "[baseball][aim]") {
  const BatterSkill& pro = batter_skill("pro");
  const double aim = aim_of(pro);
  INFO("the pro aims " << aim << " m inside the sweet spot");
  // On the barrel: inside the sweet spot, short of where it narrows to the handle and the exit
  // speed falls away (bats.toml's cor_profile, 30 cm from the tip).
  CHECK(aim > 0.02);
  CHECK(aim < 0.15);
  // Each scatter alone moves it: more timing spread carries his contacts farther out along
  // the turned bat, more reach spread sends more of them past the end.
  BatterSkill later = pro, wider = pro, steady = pro;
  later.read_timing_sd_ms *= 1.5;
  wider.read_reach_sd *= 1.5;
  steady.read_timing_sd_ms = 0.0;
  steady.read_reach_sd = steady.eye_sd = 0.0;
  CHECK(aim_of(later) > aim);
  CHECK(aim_of(wider) > aim);
  // Without scatter there is nothing to allow for: he aims where the ball leaves fastest, the
  // barrel's node about the 6 in sweet spot (its exit speed is flat within 2 cm of it).
  CHECK(aim_of(steady) < 0.02);
}

// The aim is found on a flat model of the swing (the ball's line square to the bat's arc); the
// game swings in a tilted plane at a descending pitch (meet_ball). Its mean exit speed must
// still be highest at that aim: 5 cm either way costs more than the draws' noise.
TEST_CASE("the aim gives the game's own swings their best mean exit speed", "[baseball][aim][statistics]") {
  const BatterSkill& pro = batter_skill("pro");
  const double aim = aim_of(pro);
  REQUIRE(aim >= 0.05);
  const int n = 600;
  const double at = mean_exit_speed(pro, aim, n);
  const double outer = mean_exit_speed(pro, aim - 0.05, n), inner = mean_exit_speed(pro, aim + 0.05, n);
  const double sweet = mean_exit_speed(pro, 0.0, n);
  INFO("mean exit speed " << at << " m/s at the aim (" << aim << " m inside), " << outer << " 5 cm out, " << inner
                          << " 5 cm in, " << sweet << " at the sweet spot");
  CHECK(at > outer);
  CHECK(at > inner);
  CHECK(at > sweet);
}

// Met on time the ball lands `aim` inside where it lands aiming at the sweet spot, out front
// (a lead toward the pull side for an inside pitch) as square: the lead turns the bat, not the
// aim. (Aiming the pitch's line `aim` nearer on a turned bat would put it aim/cos(lead) in.)
TEST_CASE("on time the ball meets the bat where he aimed, however far out front", "[baseball][aim]") {
  const BatterSkill& pro = batter_skill("pro");
  const BatSpec& bat = test::assets().equipment().bat(kGameBat);
  const auto met = [&](double lead, double aim) {
    SwingInput s = swing_of(pro);
    s.contact_lead = lead;
    s.aim_inside = aim;
    FieldingSetup flight_only;
    flight_only.field = false;
    const SwingResult r = swing_at(test::assets(), fastball(), s, pro.bat_speed, kGameBat, flight_only);
    REQUIRE(r.contact);
    return r.impact_from_tip;
  };
  for (const double lead : {0.0, 0.5, -0.5}) {
    const double at_sweet = met(lead, 0.0), inside = met(lead, 0.06);
    INFO("lead " << lead << " rad: met " << at_sweet << " m from the tip aiming at the sweet spot, " << inside
                 << " aiming 6 cm inside");
    // The pitch's descent through the tilted plane moves the crossing a few mm along the bat.
    CHECK(at_sweet == Approx(bat.sweet_spot_from_tip).margin(0.015));
    CHECK(inside - at_sweet == Approx(0.06).margin(0.0015));
  }
}

TEST_CASE("the game's hitter swings with his aim", "[baseball][aim]") {
  Hitter h(batter_skill("pro"), false, 7, 0.0625);
  PitchRead r;
  r.seen = fastball().plate;
  CHECK(h.swing(r, Count{}).aim_inside == 0.0625);
}

// A hitter's words for where he met it, from the bat's own restitution (bats.toml: whole from
// 4 to 9 in from the maple's tip, falling to 0.4 at the tip and 18 in): the barrel is where it
// keeps 90 % of it, 3.3 to 10.6 in. A ball squared up an inch inside the plateau is on the
// barrel, not "in on the hands" (a play-tester's 95 mph liner, 88 % squared up).
TEST_CASE("where on the bat: off the end, on the barrel, in on the hands", "[baseball][aim]") {
  const BatSpec& maple = test::assets().equipment().bat(kGameBat);
  CHECK(std::string(contact_spot(maple, -0.02)) == "off the end of the bat");
  CHECK(std::string(contact_spot(maple, 0.05)) == "off the end of the bat");
  CHECK(std::string(contact_spot(maple, 0.09)) == "on the barrel");
  CHECK(std::string(contact_spot(maple, maple.sweet_spot_from_tip)) == "on the barrel");
  CHECK(std::string(contact_spot(maple, 0.22)) == "on the barrel");
  CHECK(std::string(contact_spot(maple, 0.25)) == "on the barrel");
  CHECK(std::string(contact_spot(maple, 0.30)) == "in on the hands");
  CHECK(std::string(contact_spot(maple, 0.35)) == "in on the hands");
}
