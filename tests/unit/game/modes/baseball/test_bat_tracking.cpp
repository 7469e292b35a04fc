// Statcast's bat tracking (bat_tracking.hpp) against its definitions: squared-up as the share
// of the possible exit speed (≥ 80 %), a blast as squared-up and fast (100·share + bat mph
// ≥ 164), swing length as the path of the bat's head, attack angle and direction as the
// sweet spot's path at contact; and a swing at a pitch reports them.
#include <catch2/catch.hpp>

#include "game/modes/baseball/batting.hpp"
#include "game/modes/baseball/pitcher.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {
const BatSpec& maple() { return test::assets().equipment().bat("maple"); }
}  // namespace

TEST_CASE("squared-up: exit speed over the most the bat and pitch speeds allow", "[baseball][bat_tracking]") {
  const double bat = mph_to_mps(72.0), pitch = mph_to_mps(94.0);
  // Statcast's maximum: 0.23 of the pitch plus 1.23 of the bat (mph in, mph out).
  CHECK(mps_to_mph(max_exit_speed(bat, pitch)) == Approx(0.23 * 94.0 + 1.23 * 72.0));
  const SwingPath path{bat, deg_to_rad(10.0), 0.0, 3.2};
  // A swing squared up by construction: the exit speed is the maximum.
  const BatTracking full = track_swing(path, maple(), pitch, max_exit_speed(bat, pitch));
  CHECK(full.squared_up == Approx(1.0));
  CHECK(full.is_squared_up);
  // The boundary: 80 % is squared up, just under is not.
  CHECK(track_swing(path, maple(), pitch, 0.80 * max_exit_speed(bat, pitch)).is_squared_up);
  CHECK_FALSE(track_swing(path, maple(), pitch, 0.799 * max_exit_speed(bat, pitch)).is_squared_up);
  // A whiff squares nothing up.
  CHECK(track_swing(path, maple(), pitch, 0.0).squared_up == 0.0);
}

TEST_CASE("a blast is squared up and fast: 100 x share + bat speed >= 164", "[baseball][bat_tracking]") {
  const double pitch = mph_to_mps(90.0);
  const auto tracked = [&](double bat_mph, double share) {
    const double bat = mph_to_mps(bat_mph);
    return track_swing(SwingPath{bat, 0.17, 0.0, 3.2}, maple(), pitch, share * max_exit_speed(bat, pitch));
  };
  // By construction: 90 % at 75 mph is 165, a blast; 85 % at 75 mph is 160, not; 100 % at
  // 64 mph is exactly 164, a blast; 79 % at 90 mph is fast but not squared up.
  CHECK(tracked(75.0, 0.90).blast);
  CHECK_FALSE(tracked(75.0, 0.85).blast);
  CHECK(tracked(64.0, 1.0).blast);
  CHECK_FALSE(tracked(63.5, 1.0).blast);
  CHECK_FALSE(tracked(90.0, 0.79).blast);
  CHECK(tracked(75.0, 0.90).fast_swing);
  CHECK_FALSE(tracked(74.9, 0.90).fast_swing);
}

TEST_CASE("swing length is the head's path; attack angle and direction are the sweet spot's", "[baseball][bat_tracking]") {
  const BatSpec& b = maple();
  // A half turn about the pivot: the head runs half a circle of the length past the pivot.
  const BatTracking t = track_swing(SwingPath{mph_to_mps(71.5), deg_to_rad(12.0), deg_to_rad(-8.0), kPi}, b,
                                    mph_to_mps(90.0), 0.0);
  CHECK(t.swing_length_m == Approx(kPi * (b.length - b.pivot_from_knob)));
  CHECK(t.attack_angle_deg == Approx(12.0));
  CHECK(t.attack_direction_deg == Approx(-8.0));
  // The league's hitter: Statcast's 2024 averages, 71.5 mph and a 7.3 ft swing (~0.1 ft).
  const BatterSkill& pro = batter_skill("pro");
  const BatTracking avg = track_swing(SwingPath{pro.bat_speed, pro.attack_angle, 0.0, pro.sweep}, b, 40.0, 0.0);
  CHECK(m_to_ft(avg.swing_length_m) == Approx(7.3).margin(0.15));
  CHECK(mps_to_mph(avg.bat_speed_mps) == Approx(71.5));
}

TEST_CASE("a swing at a pitch carries its bat tracking; on time at the sweet spot squares it up", "[baseball][bat_tracking]") {
  PitchCall c;
  c.type = pitch_type(load_pitch_types(test::assets()), "four-seam");
  const PitchFlight p = throw_pitch(test::assets(), c);
  SwingInput s;
  s.timing_ms = 0.0;
  s.undercut = 0.0;
  s.attack_angle = deg_to_rad(8.0);
  const SwingResult r = swing_at(test::assets(), p, s, mph_to_mps(72.0));
  REQUIRE(r.contact);
  CHECK(r.tracking.bat_speed_mps == Approx(mph_to_mps(72.0)));
  CHECK(r.tracking.attack_angle_deg == Approx(8.0));
  CHECK(r.tracking.squared_up > 0.9);
  CHECK(r.tracking.is_squared_up);
  // 4 cm under the ball's centre: a pop-up, well short of squared up.
  s.undercut = 0.045;
  const SwingResult under = swing_at(test::assets(), p, s, mph_to_mps(72.0));
  REQUIRE(under.contact);
  CHECK(under.tracking.squared_up < 0.8);
  // Late by a bat's quarter turn past square: the ball goes foul or is missed; early likewise.
  s.undercut = 0.0;
  s.timing_ms = 40.0;
  const SwingResult late = swing_at(test::assets(), p, s, mph_to_mps(72.0));
  CHECK((!late.contact || late.outcome == BattedOutcome::Foul));
  CHECK(late.tracking.attack_direction_deg > 45.0);
}

TEST_CASE("the attack angle follows the bat's arc: early contact climbs, late contact flattens, in the swing's plane",
          "[baseball][bat_tracking]") {
  const double tilt = kLeagueSwingTilt, on_time = deg_to_rad(12.5);
  CHECK(attack_angle_at(on_time, tilt, 0.0) == Approx(on_time));
  // Early (turned < 0): farther round the arc, steeper; late: flatter, and down past the low point.
  CHECK(attack_angle_at(on_time, tilt, deg_to_rad(-20.0)) > on_time);
  CHECK(attack_angle_at(on_time, tilt, deg_to_rad(20.0)) < on_time);
  CHECK(attack_angle_at(on_time, tilt, deg_to_rad(60.0)) < 0.0);
  // The closed form: sin α = sin τ · sin β, β measured from the arc's low point.
  const double beta0 = std::asin(std::sin(on_time) / std::sin(tilt));
  CHECK(std::sin(attack_angle_at(on_time, tilt, deg_to_rad(-15.0))) ==
        Approx(std::sin(tilt) * std::sin(beta0 + deg_to_rad(15.0))));
  // No path climbs more steeply than its plane, however early.
  for (double turned = -1.5; turned <= 1.5; turned += 0.1)
    CHECK(std::abs(attack_angle_at(on_time, tilt, turned)) <= tilt + 1e-12);
  CHECK(attack_angle_at(on_time, tilt, -(kPi / 2.0 - beta0)) == Approx(tilt));
  // A level plane keeps a level path, whatever the timing.
  CHECK(attack_angle_at(0.0, 0.0, 0.7) == 0.0);
  // The bat's axis at the same point runs down the plane's slope by sin τ · cos β: ~30° head
  // down for a 10° path in the 32° plane, flatter out front, steeper deep; a level plane keeps
  // a level bat.
  const double ten = deg_to_rad(10.0);
  CHECK(rad_to_deg(vertical_bat_angle_at(ten, tilt, 0.0)) == Approx(-30.0).margin(0.5));
  CHECK(vertical_bat_angle_at(ten, tilt, deg_to_rad(-20.0)) > vertical_bat_angle_at(ten, tilt, 0.0));
  CHECK(vertical_bat_angle_at(ten, tilt, deg_to_rad(15.0)) < vertical_bat_angle_at(ten, tilt, 0.0));
  CHECK(vertical_bat_angle_at(0.0, 0.0, 0.7) == 0.0);
  // Near the on-time point a ms of timing moves the path by sin τ · cos β per radian of turn.
  const double per_rad = (attack_angle_at(on_time, tilt, -1e-4) - attack_angle_at(on_time, tilt, 1e-4)) / 2e-4;
  CHECK(per_rad == Approx(std::sin(tilt) * std::cos(beta0) / std::cos(on_time)).epsilon(1e-6));
}
