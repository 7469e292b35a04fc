// Where a hitter aims along his bat (aim.hpp): inside the sweet spot by what his own scatter
// makes worth it, checked against the game's own swings.
#include <catch2/catch.hpp>

#include <cmath>
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

// His mean exit speed (m/s; a miss counts 0) over `n` swings at the league's fastball through
// swing_at, aiming `aim` m inside the sweet spot, with his reach and timing reads' scatter.
// The same draws for every aim, so aims are compared on the same swings.
double mean_exit_speed(const BatterSkill& skill, double aim, int n) {
  Rng rng(20261129);
  FieldingSetup flight_only;
  flight_only.field = false;
  const double reach_sd = std::hypot(skill.read_reach_sd, skill.eye_sd);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    SwingInput s;
    s.attack_angle = skill.attack_angle;
    s.swing_tilt = skill.swing_tilt;
    s.sweep = skill.sweep;
    s.undercut = 0.005;
    s.aim_inside = aim;
    s.timing_ms = rng.normal(skill.read_timing_sd_ms);
    s.reach_error = rng.normal(reach_sd);
    const SwingResult r = swing_at(test::assets(), fastball(), s, skill.bat_speed, kGameBat, flight_only);
    if (r.contact) sum += r.shot.launch.ball_speed;
  }
  return sum / n;
}

}  // namespace

TEST_CASE("a hitter aims inside the sweet spot, the farther the more he scatters", "[baseball][aim]") {
  const double pro = aim_inside(test::assets(), batter_skill("pro"), kGameBat);
  const double amateur = aim_inside(test::assets(), batter_skill("amateur"), kGameBat);
  INFO("pro " << pro << " m, amateur " << amateur << " m inside the sweet spot");
  // On the barrel: inside the sweet spot, short of the 30 cm where the barrel narrows to the
  // handle and the exit speed falls away (bats.toml's cor_profile).
  CHECK(pro > 0.02);
  CHECK(pro < 0.15);
  CHECK(amateur > pro);
  // Without scatter there is nothing to allow for: he aims where the ball leaves fastest, at
  // the sweet spot (within the 6 in definition's neighbourhood where the exit speed peaks).
  BatterSkill perfect = batter_skill("pro");
  perfect.read_reach_sd = perfect.eye_sd = 0.0;
  perfect.read_timing_sd_ms = 0.0;
  CHECK(aim_inside(test::assets(), perfect, kGameBat) < 0.02);
}

// The aim is found on a flat model of the swing (the ball's line square to the bat's arc); the
// game swings in a tilted plane at a descending pitch (meet_ball). Its mean exit speed must
// still be highest at that aim: 5 cm either way costs more than the draws' noise.
TEST_CASE("the aim gives the game's own swings their best mean exit speed", "[baseball][aim][statistics]") {
  const BatterSkill& pro = batter_skill("pro");
  const double aim = aim_inside(test::assets(), pro, kGameBat);
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

TEST_CASE("the game's hitter swings with his aim", "[baseball][aim]") {
  Hitter h(batter_skill("pro"), false, 7, 0.0625);
  PitchRead r;
  r.seen = fastball().plate;
  CHECK(h.swing(r, Count{}).aim_inside == 0.0625);
}
