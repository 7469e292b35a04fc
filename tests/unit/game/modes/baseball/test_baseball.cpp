// The baseball game (DESIGN §9): pitches whose break comes out of the flight, the swing,
// Statcast's classes, fair and foul, home runs over the fence, seeded determinism.
#include <catch2/catch.hpp>

#include <cmath>

#include "game/modes/baseball/pitcher.hpp"
#include "game/modes/baseball/session.hpp"
#include "game/report/session_json.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {
const std::vector<PitchType>& types() {
  static const std::vector<PitchType> t = load_pitch_types(test::assets());
  return t;
}
PitchFlight pitch(const char* type, double speed_mph = 0.0) {
  PitchCall c;
  c.type = pitch_type(types(), type);
  if (speed_mph > 0.0) c.type.speed = mph_to_mps(speed_mph);
  return throw_pitch(test::assets(), c);
}
double inches(double m) { return m / 0.0254; }
}  // namespace

TEST_CASE("a four-seamer and a curveball move as Statcast measures them", "[baseball][pitch][reference]") {
  // 2023 league averages (Statcast pitch-level data, TJStats): four-seam IVB 15.7 in with a
  // between-pitcher spread of ~2.9 in, 7.7 in of arm-side run (Savant 2024 movement
  // leaderboard); curveball IVB -9.4 in, 9.0 in glove side, drop spread 7.1 in.
  const PitchFlight ff = pitch("four-seam");
  const PitchMovement ffm = statcast_movement(test::assets(), ff);
  INFO("four-seam IVB " << inches(ffm.induced_vertical_break) << " in, HB " << inches(ffm.horizontal_break) << " in");
  CHECK(std::abs(inches(ffm.induced_vertical_break) - 15.7) <= 2.9);
  CHECK(inches(ffm.horizontal_break) < 0.0);  // a right-hander's fastball runs to the third-base side
  CHECK(std::abs(-inches(ffm.horizontal_break) - 7.7) <= 3.0);
  const PitchFlight cu = pitch("curveball");
  const PitchMovement cum = statcast_movement(test::assets(), cu);
  INFO("curveball IVB " << inches(cum.induced_vertical_break) << " in, HB " << inches(cum.horizontal_break) << " in");
  CHECK(std::abs(inches(cum.induced_vertical_break) - (-9.4)) <= 7.1);
  CHECK(inches(cum.horizontal_break) > 0.0);  // glove side
  // Flight time: "a typical pitch is airborne for about 400 ms" (Healey & Wang 2021); the
  // 94 mph four-seamer from 6.5 ft of extension takes 0.39-0.42 s.
  CHECK(ff.flight_time > 0.39);
  CHECK(ff.flight_time < 0.42);
  CHECK(pitch("four-seam", 100.0).flight_time < ff.flight_time);
  CHECK(cu.flight_time > ff.flight_time);
  // It crosses where it was aimed (the middle of the zone).
  CHECK(std::abs(ff.plate.y() - 0.76) < 1e-3);
  CHECK(std::abs(ff.plate.z()) < 1e-3);
}

TEST_CASE("sliders, cutters and curveballs move as Savant measures them at their active spin",
          "[baseball][pitch][reference]") {
  // League averages: 2023 induced vertical break (Statcast pitch-level data, TJStats) and the
  // 2024 Savant movement leaderboard's horizontal break, glove side for a right-hander; each
  // type thrown at its Savant 2024 active spin (pitches.toml). 3 in: breaking balls spread
  // between pitchers (curveball drop sd 7.1 in). Read at the transverse spin alone, the lift
  // moved these 1.3-1.9 times as far (slider 9.6 in glove side).
  const struct {
    const char* type;
    double ivb, hb;  // in; hb + toward first base (glove side)
  } rows[] = {{"slider", 1.6, 5.6}, {"cutter", 7.7, 2.9}, {"curveball", -9.4, 9.0}};
  for (const auto& row : rows) {
    const PitchMovement mv = statcast_movement(test::assets(), pitch(row.type));
    INFO(row.type << ": IVB " << inches(mv.induced_vertical_break) << " in, HB " << inches(mv.horizontal_break) << " in");
    CHECK(std::abs(inches(mv.induced_vertical_break) - row.ivb) <= 3.0);
    CHECK(std::abs(inches(mv.horizontal_break) - row.hb) <= 3.0);
  }
}

TEST_CASE("the sinker's seam-shifted wake turns its movement off its spin toward the arm side, as Hawk-Eye measures",
          "[baseball][pitch][reference]") {
  // Savant: the league sinker runs 15.0 in arm side (2024 movement leaderboard); Hawk-Eye's
  // measured spin axes put the movement its spin alone gives 22.1° above where it goes
  // (the spin-direction leaderboard, pitches.toml). 2 in: the validation band.
  const PitchType& si = pitch_type(types(), "sinker");
  const PitchFlight f = pitch("sinker");
  const PitchMovement m = statcast_movement(test::assets(), f);
  const Vec3 magnus = f.spin.cross(f.release_velocity);  // seen from the catcher: y up, z toward first base
  const double spin_based = std::atan2(magnus.z(), magnus.y());
  const double moved = std::atan2(m.horizontal_break, m.induced_vertical_break);
  INFO("spin-based " << rad_to_deg(spin_based) << " deg, moved " << rad_to_deg(moved) << " deg, HB "
                     << inches(m.horizontal_break) << " in");
  CHECK(rad_to_deg(spin_based - moved) == Approx(rad_to_deg(si.seam_wake_deviation)).margin(2.0));
  CHECK(std::abs(-inches(m.horizontal_break) - 15.0) <= 2.0);
  // The wake's share is across the Magnus force's, tan δ of it (the two forces keep their
  // angle as the pitch slows; their sizes drift apart by a few per cent over its flight).
  const double wv = m.seam_wake_vertical, wh = m.seam_wake_horizontal;
  const double mv = m.induced_vertical_break - wv, mh = m.horizontal_break - wh;
  INFO("wake " << inches(wv) << " in up, " << inches(wh) << " in; Magnus " << inches(mv) << " up, " << inches(mh));
  CHECK(rad_to_deg(std::acos((wv * mv + wh * mh) / (std::hypot(wv, wh) * std::hypot(mv, mh)))) == Approx(90.0).margin(3.0));
  CHECK(std::hypot(wv, wh) / std::hypot(mv, mh) == Approx(std::tan(si.seam_wake_deviation)).epsilon(0.05));
  CHECK(wh < 0.0);  // arm side
  CHECK(wv < 0.0);  // and down
  // The same spin along the movement's direction and no wake (the Magnus force alone) runs
  // it less far: the wake adds to the Magnus force, across it.
  PitchCall plain;
  plain.type = si;
  plain.type.seam_wake_deviation = 0.0;
  const PitchFlight pf = throw_pitch(test::assets(), plain);
  CHECK(pf.seam_side_force == 0.0);
  CHECK(-inches(m.horizontal_break) > -inches(statcast_movement(test::assets(), pf).horizontal_break) + 0.5);
  // A left-hander's sinker is the mirror image.
  PitchCall left;
  left.type = si;
  left.left_handed = true;
  const PitchMovement lm = statcast_movement(test::assets(), throw_pitch(test::assets(), left));
  CHECK(lm.horizontal_break == Approx(-m.horizontal_break).margin(1e-6));
  CHECK(lm.induced_vertical_break == Approx(m.induced_vertical_break).margin(1e-6));
}

TEST_CASE("Statcast's movement is the spin's share (Magnus and seam wake) from 50 ft to the plate's front", "[baseball][pitch]") {
  // A pitch without spin has no lift: the ball under the liftless law is the same ball.
  PitchCall still;
  still.type = pitch_type(types(), "four-seam");
  still.type.spin = 0.0;
  const PitchMovement s = statcast_movement(test::assets(), throw_pitch(test::assets(), still));
  CHECK(s.induced_vertical_break == 0.0);
  CHECK(s.horizontal_break == 0.0);
  // A nearly constant Magnus push moves the ball as the square of the time it acts: the
  // 48.6 ft window is ~0.92 of the flight's time from the hand (6.5 ft of extension), so the
  // movement is ~0.85 of the whole flight's break, in the same direction, for every type.
  for (const PitchType& t : types()) {
    PitchCall c;
    c.type = t;
    const PitchFlight f = throw_pitch(test::assets(), c);
    const PitchMovement m = statcast_movement(test::assets(), f);
    INFO(t.type);
    const double whole = std::hypot(f.flight_break_vertical, f.flight_break_horizontal);
    const double window = std::hypot(m.induced_vertical_break, m.horizontal_break);
    CHECK(window / whole > 0.78);
    CHECK(window / whole < 0.92);
    CHECK(m.induced_vertical_break * f.flight_break_vertical + m.horizontal_break * f.flight_break_horizontal > 0.0);
  }
}

TEST_CASE("the pitch types order their rise as Statcast's leaderboard does", "[baseball][pitch]") {
  // Savant 2024 pitch movement: the four-seamer rises most, then the sinker, the slider,
  // and the curveball drops (vertical drop with gravity FF < SI < SL < CU).
  const auto ivb = [](const char* t) { return statcast_movement(test::assets(), pitch(t)).induced_vertical_break; };
  CHECK(ivb("four-seam") > ivb("sinker"));
  CHECK(ivb("sinker") > ivb("slider"));
  CHECK(ivb("slider") > ivb("curveball"));
  // Sinkers and changeups run arm side about twice as far as four-seamers.
  const auto hb = [](const char* t) { return statcast_movement(test::assets(), pitch(t)).horizontal_break; };
  const double ff = -hb("four-seam");
  CHECK(-hb("sinker") > 1.5 * ff);
  CHECK(-hb("changeup") > 1.5 * ff);
}

TEST_CASE("Statcast's barrel, hard-hit and sweet-spot classes", "[baseball]") {
  // The closed form (baseballr): LA <= 50, EV >= 98, 1.5 EV - LA >= 117, EV + LA >= 124.
  CHECK(is_barrel(98.0, 28.0));
  CHECK_FALSE(is_barrel(97.9, 28.0));
  CHECK_FALSE(is_barrel(98.0, 31.0));
  CHECK(is_barrel(116.0, 8.0));
  CHECK_FALSE(is_barrel(116.0, 51.0));
}

// The closed form of meet_ball for a ball flying in the vertical plane square to the bat
// (descending at θ, the bat's path climbing at α on time), turned φ: the bat's axis crosses
// its line reach/cos φ from the pivot, reach·tan φ·cos θ/cos(α−θ) ahead of the on-time point,
// where the ball sits reach·tan φ·tan(α−θ) lower against the bat's axis.
TEST_CASE("the turned bat meets the ball farther out along it, and out front lower against it", "[baseball][swing]") {
  const double reach = 0.54, u0 = 0.01;
  for (const double alpha : {0.0, deg_to_rad(12.5)}) {
    for (const double theta : {0.0, deg_to_rad(5.0), deg_to_rad(12.5)}) {
      const Vec3 dir(-std::cos(theta), -std::sin(theta), 0.0);
      for (const double phi : {deg_to_rad(-30.0), 0.0, deg_to_rad(20.0), deg_to_rad(38.0)}) {
        const BallCrossing c = meet_ball(dir, alpha, 0.0, reach, u0, phi);
        INFO("alpha " << rad_to_deg(alpha) << " theta " << rad_to_deg(theta) << " phi " << rad_to_deg(phi));
        REQUIRE(c.crosses);
        CHECK(c.from_pivot == Approx(reach / std::cos(phi)).margin(1e-12));
        CHECK(c.ahead == Approx(reach * std::tan(phi) * std::cos(theta) / std::cos(alpha - theta)).margin(1e-12));
        CHECK(c.undercut == Approx(u0 - reach * std::tan(phi) * std::tan(alpha - theta)).margin(1e-12));
      }
    }
  }
  // A bat turned square to the ball's line has nothing to cross.
  CHECK_FALSE(meet_ball(Vec3(0.0, 0.0, -1.0), 0.0, 0.0, reach, u0, 0.0).crosses);
}

TEST_CASE("timing sends the ball: early pulls, late goes the other way; far off time the bat misses", "[baseball][swing]") {
  const PitchFlight p = pitch("four-seam");
  SwingInput s;
  s.undercut = 0.010;
  s.timing_ms = -8.0;
  const SwingResult early = swing_at(test::assets(), p, s, mph_to_mps(71.5));
  s.timing_ms = 8.0;
  const SwingResult late = swing_at(test::assets(), p, s, mph_to_mps(71.5));
  REQUIRE(early.contact);
  REQUIRE(late.contact);
  CHECK(early.shot.launch.horizontal_angle < -deg_to_rad(10.0));  // pulled to left field (right-handed batter)
  CHECK(late.shot.launch.horizontal_angle > deg_to_rad(10.0));
  // Out front the bat is farther round its arc and climbing (attack_angle_at); late its path is
  // flatter. Its plane climbs more steeply than the fastball descends, so out front the ball
  // sits lower against the bat (rolled over) and deep it sits higher (under it): the same aim
  // launches the late ball higher. The tracking reports the swing's plane.
  CHECK(early.tracking.attack_angle_deg > rad_to_deg(s.attack_angle) + 10.0);
  CHECK(late.tracking.attack_angle_deg < rad_to_deg(s.attack_angle) - 10.0);
  CHECK(late.shot.launch.vertical_angle > early.shot.launch.vertical_angle + deg_to_rad(15.0));
  CHECK(early.tracking.swing_path_tilt_deg == Approx(32.0).margin(0.01));
  s.left_handed = true;
  s.timing_ms = -8.0;
  CHECK(swing_at(test::assets(), p, s, mph_to_mps(71.5)).shot.launch.horizontal_angle > deg_to_rad(10.0));
  // 20 ms off the bat has turned ~53° from square: its axis crosses the ball's line past the
  // end of the bat, farther than the ball's edge can reach its end cap, either way.
  for (const double t : {-20.0, 20.0}) {
    s.timing_ms = t;
    const SwingResult miss = swing_at(test::assets(), p, s, mph_to_mps(71.5));
    CHECK_FALSE(miss.contact);
    CHECK(miss.outcome == BattedOutcome::Strike);
  }
  // Farther off the bat is round (early) or not yet started (late): a miss at every timing to
  // the input's ±150 ms, whatever the pitch, where the turned bat's geometry repeats every
  // 140 ms at this speed (a swing 150 ms early had met the ball as one 10 ms early).
  for (const PitchType& t : types()) {
    for (double ms = -150.0; ms <= 150.0; ms += 2.5) {
      if (std::abs(ms) < 40.0) continue;
      s.timing_ms = ms;
      s.left_handed = false;
      const SwingResult miss = swing_at(test::assets(), pitch(t.type.c_str()), s, mph_to_mps(71.5));
      INFO(t.type << " at " << ms << " ms");
      CHECK_FALSE(miss.contact);
      CHECK(miss.through);
    }
  }
}

TEST_CASE("hit it where it's pitched: an inside pitch met out front is pulled off the sweet spot, an outside one goes the other way",
          "[baseball][swing]") {
  // 20 cm inside and outside the middle (a corner's edge), met on time by the batter's body.
  CHECK(contact_lead_for(0.2) == Approx(kLeadPerInside * 0.2));
  CHECK(contact_lead_for(-0.2) == Approx(-kLeadPerInside * 0.2));
  CHECK(contact_lead_for(5.0) == Approx(SwingInput::kContactLead.max));
  const PitchFlight p = pitch("four-seam");
  SwingInput s;
  s.undercut = 0.010;
  const SwingResult middle = swing_at(test::assets(), p, s, mph_to_mps(71.5));
  s.contact_lead = contact_lead_for(0.2);
  const SwingResult inside = swing_at(test::assets(), p, s, mph_to_mps(71.5));
  s.contact_lead = contact_lead_for(-0.2);
  const SwingResult outside = swing_at(test::assets(), p, s, mph_to_mps(71.5));
  REQUIRE(middle.contact);
  REQUIRE(inside.contact);
  REQUIRE(outside.contact);
  // Pulled (toward third base for a right-handed batter) and the other way, by about the lead.
  CHECK(inside.shot.launch.horizontal_angle < middle.shot.launch.horizontal_angle - 0.5 * contact_lead_for(0.2));
  CHECK(outside.shot.launch.horizontal_angle > middle.shot.launch.horizontal_angle + 0.5 * contact_lead_for(0.2));
  // Met on the sweet spot as the square hit is (not the handle, not the tip).
  CHECK(inside.shot.bat.impact_from_tip == Approx(middle.shot.bat.impact_from_tip).margin(0.01));
  CHECK(outside.shot.bat.impact_from_tip == Approx(middle.shot.bat.impact_from_tip).margin(0.01));
}

TEST_CASE("derby swings: home runs cross the fence in flight, fouls land outside the lines, same seed same swings",
          "[baseball][derby]") {
  SessionOptions o;
  o.outs = 6;
  const auto run = [&](std::uint64_t seed) {
    BotBatter bot(test::assets(), batter_skill("pro"), seed);
    return run_session(test::assets(), o, bot, seed);
  };
  const std::vector<SwingRecord> a = run(2), b = run(2);
  REQUIRE(a.size() == b.size());
  CHECK(session_json(a, o, 2) == session_json(b, o, 2));
  const WorldAsset& park = *test::assets().world("ballpark");
  int home_runs = 0;
  for (const SwingRecord& s : a) {
    if (s.result.outcome == BattedOutcome::HomeRun) {
      ++home_runs;
      // Where its path crosses the fence's line (between two samples, interpolated) it is
      // above the fence's top.
      bool over = false;
      const auto& path = s.result.shot.trajectory.samples;
      for (std::size_t i = 1; i < path.size(); ++i) {
        const Vec3 &p0 = path[i - 1].position, &p1 = path[i].position;
        const double r0 = std::hypot(p0.x(), p0.z()), r1 = std::hypot(p1.x(), p1.z());
        const double fence = fence_distance(park, std::atan2(p1.z(), p1.x()));
        if (r0 <= fence && r1 > fence && p0.y() + (fence - r0) / (r1 - r0) * (p1.y() - p0.y()) > park.fence_height)
          over = true;
      }
      CHECK(over);
    }
    if (s.result.outcome == BattedOutcome::Foul) {
      const Vec3& land = s.result.shot.trajectory.summary.landing_position;
      const Vec3& rest = s.result.shot.trajectory.summary.rest_position;
      const bool outside = [](const Vec3& p) { return p.x() < 0.0 || std::abs(std::atan2(p.z(), p.x())) > 0.25 * kPi; }(
          std::hypot(land.x(), land.z()) > 27.432 ? land : rest);
      CHECK(outside);
    }
  }
  CHECK(home_runs > 0);
}

TEST_CASE("batting practice swings run at a speed of their own, spread as Statcast's hitters' are", "[baseball][derby]") {
  // BatterSkill::bat_speed_sd: 4.3 % of the hitter's average (Statcast's fast-swing shares,
  // docs/baseball.md), as the live game's hitter draws it.
  const BatterSkill& pro = batter_skill("pro");
  BotBatter bot(test::assets(), pro, 11);
  Rng pitcher(3);
  const PitchFlight pitch = throw_pitch(test::assets(), derby_pitch(load_pitch_types(test::assets()), pitcher));
  double sum = 0.0, sum2 = 0.0;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double e = bot.plan(pitch, false, false).speed_error;
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  INFO("speed error " << mean << " +- " << sd << " m/s against " << pro.bat_speed_sd * pro.bat_speed);
  CHECK(std::abs(mean) < 0.2 * pro.bat_speed_sd * pro.bat_speed);
  CHECK(sd == Approx(pro.bat_speed_sd * pro.bat_speed).epsilon(0.15));
}

TEST_CASE("bad baseball input names the value and its range", "[baseball][input]") {
  // A path cannot climb more steeply than the plane the bat turns in.
  SwingInput steep;
  steep.swing_tilt = deg_to_rad(10.0);
  steep.attack_angle = deg_to_rad(12.5);
  CHECK_THROWS_WITH(swing_at(test::assets(), pitch("four-seam"), steep, mph_to_mps(72.0)),
                    Catch::Contains("swing.attack_angle") && Catch::Contains("swing_tilt") && Catch::Contains("allowed"));
  PitchCall c;
  c.type = pitch_type(types(), "four-seam");
  c.type.speed = mph_to_mps(130.0);
  CHECK_THROWS_WITH(throw_pitch(test::assets(), c), Catch::Contains("pitch.speed") && Catch::Contains("allowed"));
  CHECK_THROWS_WITH(pitch_type(types(), "knuckler"), Catch::Contains("four-seam"));
  SessionOptions o;
  o.outs = 0;
  BotBatter bot(test::assets(), batter_skill("pro"), 1);
  CHECK_THROWS_WITH(run_session(test::assets(), o, bot, 1), Catch::Contains("outs = 0") && Catch::Contains("[1, 50]"));
}

// The count's intent by type: odds scaled by the type's zone odds against the mix's.
TEST_CASE("a pitcher means each type for the zone by its share, keeping the count's intent for his mix", "[baseball][pitcher]") {
  std::vector<PitchType> mix(2);
  mix[0].type = "four-seam";
  mix[0].usage = 0.5;
  mix[0].zone_share = 0.6;
  mix[1].type = "changeup";
  mix[1].usage = 0.5;
  mix[1].zone_share = 0.4;
  // Odds: 0.5 at the mix's share 0.5 (odds 1) becomes 0.6 and 0.4 exactly.
  CHECK(type_zone_intent(0.5, mix[0], mix) == Approx(0.6));
  CHECK(type_zone_intent(0.5, mix[1], mix) == Approx(0.4));
  // A type at the mix's own share keeps the count's intent; 3-0 stays mostly in the zone.
  PitchType even = mix[0];
  even.zone_share = 0.5;
  CHECK(type_zone_intent(0.3, even, mix) == Approx(0.3));
  CHECK(type_zone_intent(0.95, mix[1], mix) > 0.9);
  CHECK(type_zone_intent(0.95, mix[1], mix) < 0.95);
  // Over the mix the intent is about kept (odds, not shares, are scaled).
  const double kept = 0.5 * type_zone_intent(0.58, mix[0], mix) + 0.5 * type_zone_intent(0.58, mix[1], mix);
  CHECK(kept == Approx(0.58).margin(0.01));
}

TEST_CASE("a pitch into the batter's body or his hands is a hit-by-pitch; one past them is not (Rule 5.05(b)(2))",
          "[baseball][rules]") {
  const double r = 0.0369;
  // A right-hander stands on the third-base side (−z): up and in at his hands, or at his hip.
  CHECK(hits_batter(Vec3(0.0, kStanceHandsHigh, -kStanceHandsFromMiddle), false, r));
  CHECK(hits_batter(Vec3(0.0, 0.9, -0.6), false, r));
  // Under his hands and short of his body: a ball inside, not a hit batter.
  CHECK_FALSE(hits_batter(Vec3(0.0, 1.0, -0.40), false, r));
  // Over the plate, or a foot away on the other side: nothing to hit.
  CHECK_FALSE(hits_batter(Vec3(0.0, 0.8, 0.0), false, r));
  CHECK_FALSE(hits_batter(Vec3(0.0, kStanceHandsHigh, kStanceHandsFromMiddle), false, r));
  // A left-hander is the mirror image.
  CHECK(hits_batter(Vec3(0.0, kStanceHandsHigh, kStanceHandsFromMiddle), true, r));
}
