// The one way in: a ShotSpec built in code (as the game modes, the bench and a launch
// monitor build one) resolves against the Assets context and runs like a scenario file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "game/content/scenario.hpp"
#include "game/rules/run_shot.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

/// A full-swing stroke with `club` at `mph` and `attack_deg`, the ball at [x, z] on golf_hole.
ShotSpec club_stroke(const char* club, double mph, double attack_deg, double x, double z) {
  ShotSpec spec;
  auto& c = std::get<ClubStrike>(spec.strike);
  c.club = club;
  c.swing.club_speed = mph_to_mps(mph);
  c.swing.attack_angle = deg_to_rad(attack_deg);
  spec.placement.x = x;
  spec.placement.z = z;
  return spec;
}

}  // namespace
using Catch::Matchers::Contains;

TEST_CASE("a ShotSpec in code and the scenario file of the same shot give the same bytes", "[run_shot]") {
  const Assets& A = test::assets();
  ShotSpec spec;
  spec.sport = "golf";
  ClubStrike c;
  c.club = "7-iron";
  c.swing.club_speed = mph_to_mps(90.0);
  c.swing.attack_angle = deg_to_rad(-4.3);
  spec.strike = c;
  const ShotResult a = run_shot(resolve(spec, A), "code");
  const ShotResult b = run_scenario(load_scenario(A, "golf/7-iron", {}));
  CHECK(a.launch_state.velocity == b.launch_state.velocity);
  CHECK(a.launch_state.spin == b.launch_state.spin);
  CHECK(a.trajectory.summary.rest_position == b.trajectory.summary.rest_position);
}

TEST_CASE("resolve picks the sport's defaults and refuses a strike of the other sport", "[run_shot]") {
  const Assets& A = test::assets();
  ShotSpec golf;
  const ResolvedShot g = resolve(golf, A);
  CHECK(g.ball.name == "tour");
  CHECK(g.club->name == "driver");
  CHECK(g.aero->name == "tour_fit");
  CHECK(g.world_name == "golf_hole");
  CHECK(g.start_surface == "tee");
  // Teed up: the driver's tee height under the ball.
  CHECK(g.ball_centre.y() - g.ground.y() == Approx(g.ball.radius + g.club_info->tee_height));
  ShotSpec bad;
  bad.strike = BatStrike{};
  CHECK_THROWS_WITH(resolve(bad, A), Contains("bat strike") && Contains("golf"));
  ShotSpec fast;
  std::get<ClubStrike>(fast.strike).swing.club_speed = 200.0;
  CHECK_THROWS_WITH(resolve(fast, A), Contains("swing.speed") && Contains("[0.1, 90] m/s"));
  ShotSpec odd;
  odd.impact.mu = 5.0;
  CHECK_THROWS_WITH(resolve(odd, A), Contains("impact.mu = 5"));
  ShotSpec sport;
  sport.sport = "cricket";
  CHECK_THROWS_WITH(resolve(sport, A), Contains("cricket") && Contains("golf, baseball"));
}

TEST_CASE("the putter needs no tee and no code: a putt rolls on the green", "[run_shot][putter]") {
  const Assets& A = test::assets();
  ShotSpec spec;
  ClubStrike c;
  c.club = "putter";
  c.swing.club_speed = 1.5;  // a firm 3 m putt
  spec.strike = c;
  spec.placement.x = 400.0;  // on the green, short of the pin at 405 m
  spec.placement.z = 3.0;
  const ResolvedShot r = resolve(spec, A);
  CHECK(r.start_surface == "green");
  CHECK(r.ball_centre.y() - r.ground.y() == Approx(r.ball.radius));
  const ShotResult s = run_shot(r, "putt");
  CHECK(s.impactor_mesh == "putter_head");
  CHECK(rad_to_deg(s.launch.vertical_angle) < 5.0);
  CHECK(s.end == ShotEnd::Rest);
  CHECK(s.trajectory.summary.total_m > 1.0);
  CHECK(s.trajectory.summary.total_m < 8.0);
}

TEST_CASE("aim turns the shot on the world, not its launch numbers", "[run_shot]") {
  const Assets& A = test::assets();
  ShotSpec straight;
  straight.world = "none";
  ShotSpec right = straight;
  right.placement.aim = deg_to_rad(10.0);
  const ShotResult a = run_shot(resolve(straight, A), "a");
  const ShotResult b = run_shot(resolve(right, A), "b");
  CHECK(b.launch.ball_speed == a.launch.ball_speed);
  CHECK(b.launch.horizontal_angle == a.launch.horizontal_angle);
  const Vec3 pa = a.trajectory.summary.rest_position, pb = b.trajectory.summary.rest_position;
  // Frame independence up to round-off, which the hops and roll amplify (a rotated frame
  // rounds differently): 10 µm over ~270 m of carry and run.
  CHECK(std::hypot(pa.x(), pa.z()) == Approx(std::hypot(pb.x(), pb.z())).margin(1e-5));
  CHECK(rad_to_deg(std::atan2(pb.z(), pb.x()) - std::atan2(pa.z(), pa.x())) == Approx(10.0).epsilon(1e-6));
}

TEST_CASE("the lie acts on the strike: a flyer from the rough", "[run_shot][lie]") {
  // Grass and water between face and ball (materials.toml lie_friction) lower the face's
  // grip: less spin and a higher launch together. A wedge study's wet faces (Peterfield Golf,
  // 2020) lost ~35 % of the spin on average, 10 % for the best wedges and 60 % for the worst,
  // and launched higher; ball speed falls a few per cent with the club slowed in the grass.
  const Assets& A = test::assets();
  ShotSpec spec = club_stroke("8-iron", 87.0, -4.5, 150.0, 0.0);
  const ShotResult clean = run_shot(resolve(spec, A), "fairway", {true, false});
  REQUIRE(clean.lie == "fairway");
  spec.placement.z = 30.0;
  const ShotResult rough = run_shot(resolve(spec, A), "rough", {true, false});
  REQUIRE(rough.lie == "rough");
  const double spin = rough.launch.spin.total / clean.launch.spin.total - 1.0;
  const double speed = rough.launch.ball_speed / clean.launch.ball_speed - 1.0;
  INFO("rough: spin " << 100 * spin << " %, ball speed " << 100 * speed << " %, launch "
                      << rad_to_deg(rough.launch.vertical_angle - clean.launch.vertical_angle) << " deg");
  CHECK(spin < -0.10);
  CHECK(spin > -0.60);
  CHECK(speed < -0.02);
  CHECK(speed > -0.08);
  CHECK(rough.launch.vertical_angle > clean.launch.vertical_angle);
}

TEST_CASE("from sand a ball struck first plays as from the fairway, and a splash pushes it out through the sand",
          "[run_shot][lie][sand]") {
  // golf_hole: fairway at [255 m, 0], its fairway bunker at [255 m, 17 m]. A sand wedge's
  // pitch stroke (40 mph, -4 deg).
  const Assets& A = test::assets();
  ShotSpec spec = club_stroke("sw", 40.0, -4.0, 255.0, 0.0);
  auto& c = std::get<ClubStrike>(spec.strike);
  const ShotResult grass = run_shot(resolve(spec, A), "fairway", {true, false});
  REQUIRE(grass.lie == "fairway");
  spec.placement.z = 17.0;
  const ShotResult pick = run_shot(resolve(spec, A), "pick", {true, false});
  REQUIRE(pick.lie == "sand");
  // Picked clean: nothing between face and ball, the club not slowed.
  CHECK(pick.launch.ball_speed == Approx(grass.launch.ball_speed).epsilon(1e-9));
  CHECK(pick.launch.spin.total == Approx(grass.launch.spin.total).epsilon(1e-9));

  c.swing.sand_entry = kSplashEntry;
  const ResolvedShot splash_spec = resolve(spec, A);
  const ShotResult splash = run_shot(splash_spec, "splash", {true, false});
  // The plough: the head reaches the ball at the closed form's speed (sand_splash.hpp).
  const ClubSpec& sw = *splash_spec.club;
  CHECK(splash.club.speed_at_impact ==
        Approx(club_speed_after_sand(pick.club.speed_at_impact, sw.head_mass + sw.shaft_tip_mass, 2.0 * sw.face_half_width,
                                     kSplashEntry))
            .epsilon(1e-9));
  CHECK(splash.club.sand_entry == kSplashEntry);
  CHECK(splash.warnings.empty());  // the sand's rebound is no face's out of its measured range
  // The cushion: the sand's own rebound (~0.07 at this approach) where the face gives ~0.87,
  // so about (1 + 0.07) / (1 + 0.87) of the ball's speed at 88 % of the club's: about half.
  CHECK(splash.impact.e < 0.2);
  const double speed = splash.launch.ball_speed / pick.launch.ball_speed;
  INFO("splash/pick: ball speed " << speed << ", spin " << splash.launch.spin.total / pick.launch.spin.total << ", launch "
                                  << rad_to_deg(splash.launch.vertical_angle) << " against "
                                  << rad_to_deg(pick.launch.vertical_angle) << " deg");
  CHECK(speed > 0.4);
  CHECK(speed < 0.6);
  // Through sliding layers of sand the face barely grips: the ball comes out "knuckling",
  // higher and with a fraction of the spin (golf-info-guide, "Explosion shot").
  CHECK(splash.launch.spin.total < 0.3 * pick.launch.spin.total);
  CHECK(splash.launch.vertical_angle > pick.launch.vertical_angle);
  CHECK(splash.trajectory.summary.carry_m < 0.5 * pick.trajectory.summary.carry_m);

  // Between the pick and the inch nothing jumps: a few millimetres of sand are pressed through
  // (the cushion thinner than the ball flattens), and the carry falls step by step from the
  // pick's to the splash's. Each quarter millimetre moves it less than a tenth of the way.
  double last = pick.trajectory.summary.carry_m;
  const double span = last - splash.trajectory.summary.carry_m;
  for (double x = 2.5e-4; x <= 0.008; x += 2.5e-4) {
    c.swing.sand_entry = x;
    const double carry = run_shot(resolve(spec, A), "thin layer", {true, false}).trajectory.summary.carry_m;
    INFO(x * 1e3 << " mm of sand: " << carry << " m (the step before " << last << " m)");
    CHECK(carry < last);
    CHECK(last - carry < 0.1 * span);
    last = carry;
  }

  // Sand before the ball is sand: from the fairway there is none to enter.
  spec.placement.z = 0.0;
  CHECK_THROWS_WITH(run_shot(resolve(spec, A), "fat", {true, false}),
                    Catch::Contains("swing.sand_entry") && Catch::Contains("fairway"));
}

TEST_CASE("the 30-yard pitch stroke splashes the ball roughly 30 feet out of a greenside bunker", "[run_shot][lie][sand]") {
  // Backswing, "Calibrate your sand explosion shots" (undated): "the 30 yard pitch stroke if
  // used in a bunker will have the ball traveling roughly 30 feet if you hit the sand first an
  // inch behind the ball". The stroke is found from the fairway short of golf_hole's green
  // ([380 m, 4 m], toward the cup), its total 30 yd; then played from the greenside bunker's
  // green side ([388 m, -14 m], onto the green). "Roughly": a third either way, 10 ft.
  const Assets& A = test::assets();
  ShotSpec spec = club_stroke("sw", 30.0, -4.0, 380.0, 4.0);
  auto& c = std::get<ClubStrike>(spec.strike);
  const auto total = [&](double mph, double x, double z, double aim_deg, double entry) {
    c.swing.club_speed = mph_to_mps(mph);
    c.swing.sand_entry = entry;
    spec.placement.x = x;
    spec.placement.z = z;
    spec.placement.aim = deg_to_rad(aim_deg);
    return run_shot(resolve(spec, A), "splash", {true, false}).trajectory.summary.total_m;
  };
  double lo = 15.0, hi = 45.0;  // mph: a 30-yd pitch lies between
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (total(mid, 380.0, 4.0, -2.3, 0.0) < 30.0 * 0.9144 ? lo : hi) = mid;
  }
  const double stroke = 0.5 * (lo + hi);
  const double splash_ft = total(stroke, 388.0, -14.0, 45.0, kSplashEntry) / 0.3048;
  INFO("the 30-yd pitch stroke: " << stroke << " mph; its splash travels " << splash_ft << " ft");
  CHECK(splash_ft == Approx(30.0).margin(10.0));
}

TEST_CASE("from a wet grassy lie the contact gives TrackMan's launch, spin and ball speed together", "[run_shot][lie]") {
  // Drive Golf Performance Blog (2014), TrackMan III, 10 shots each from wet grassy lies at
  // ~10 C: PW 80.1 mph club -> 93.4 mph, 28.6 deg, 5218 rpm; 7-iron 87.3 mph -> 114.1 mph,
  // 17.7 deg, 5686 rpm. Launch and spin are tied by the face's grip (less grip: higher launch
  // and less spin), so one lie_friction has to give both; the project's launch bands (ball
  // speed 3 %, launch 1.5 deg, spin 15 %), the tour delivery's attack (the blog gives none).
  struct Row {
    const char* club;
    double club_mph, attack_deg, ball_mph, launch_deg, spin_rpm;
  };
  const Row rows[] = {{"pw", 80.1, -5.0, 93.4, 28.6, 5218}, {"7-iron", 87.3, -4.3, 114.1, 17.7, 5686}};
  const Assets& A = test::assets();
  for (const Row& row : rows) {
    const ShotSpec spec = club_stroke(row.club, row.club_mph, row.attack_deg, 150.0, 30.0);
    const ShotResult r = run_shot(resolve(spec, A), "wet", {true, false});
    REQUIRE(r.lie == "rough");
    INFO(row.club << ": " << mps_to_mph(r.launch.ball_speed) << " mph, " << rad_to_deg(r.launch.vertical_angle)
                  << " deg, " << radps_to_rpm(r.launch.spin.total) << " rpm");
    CHECK(mps_to_mph(r.launch.ball_speed) == Approx(row.ball_mph).epsilon(0.03));
    CHECK(rad_to_deg(r.launch.vertical_angle) == Approx(row.launch_deg).margin(1.5));
    CHECK(radps_to_rpm(r.launch.spin.total) == Approx(row.spin_rpm).epsilon(0.15));
  }
}

TEST_CASE("values outside what laboratories measure run, with a warning naming the range and source",
          "[run_shot][plausibility]") {
  const auto warnings_of = [](const char* scenario, std::vector<std::string> sets) {
    sets.push_back("world.name=none");
    return run_scenario(load_scenario(test::assets(), scenario, sets), RunOptions{true, false}).warnings;
  };
  const auto mentions = [](const std::vector<std::string>& w, const std::string& what) {
    return std::any_of(w.begin(), w.end(), [&](const std::string& s) { return s.find(what) != std::string::npos; });
  };
  // e = 0.81 on a baseball gives 152 mph: never without a word.
  const auto bat = warnings_of("baseball/line-drive", {"impact.e=0.81"});
  CHECK(mentions(bat, "e = 0.810 is outside the 0.20-0.60 measured for a baseball on a bat"));
  CHECK(mentions(bat, "Nathan 2000"));
  CHECK(mentions(warnings_of("golf/driver", {"impact.mu=0.05"}), "mu = 0.050 is outside"));
  // e_t is an input of the rigid model only; the compliant contact makes its own.
  CHECK(mentions(warnings_of("golf/driver", {"impact.model=rigid", "impact.e_t=0.9"}), "e_t = 0.900"));
  // Under the compliant contact a set e_t is no range to warn about but an input it does not
  // use, and the reader is told so.
  const auto compliant = warnings_of("golf/driver", {"impact.e_t=0.9"});
  CHECK_FALSE(mentions(compliant, "e_t = 0.900"));
  CHECK(mentions(compliant, "impact.e_t acts in the rigid model only"));
  // The built-in deliveries are real ones.
  for (const char* s : {"golf/driver", "golf/7-iron", "golf/pw", "baseball/line-drive"})
    CHECK_FALSE(mentions(warnings_of(s, {}), "measured for"));
}

TEST_CASE("a ball that leaves the ballpark in the air reports where it comes down at field level", "[run_shot][projection]") {
  // Statcast projects a home run's distance to field level. The ballpark's bounds end
  // ~130 m out; a 120 mph fly carries ~150 m. Over the flat world the same launch lands in
  // open air all the way: the projection must match it (same air, same field level).
  const Assets& A = test::assets();
  const std::vector<std::string> launch = {"launch.ball_speed=120mph", "launch.vertical_angle=30deg",
                                           "launch.spin=1500rpm"};
  auto with_world = [&](const char* world) {
    std::vector<std::string> sets = launch;
    sets.push_back(std::string("world.name=") + world);
    ScenarioDoc doc = parse_toml_doc("sport = \"baseball\"\n", "test");
    for (const auto& s : sets) apply_set(doc, s);
    return run_scenario(scenario_from_doc(A, doc, "projection"), RunOptions{true, false});
  };
  const ShotResult park = with_world("ballpark");
  const ShotResult open = with_world("none");
  REQUIRE(park.trajectory.summary.end == EndReason::LeftWorld);
  CHECK(park.trajectory.summary.carry_m > 140.0);
  CHECK(std::fabs(park.trajectory.summary.carry_m - open.trajectory.summary.carry_m) < 0.01);
  CHECK(std::fabs(park.trajectory.summary.landing_angle_deg - open.trajectory.summary.landing_angle_deg) < 0.05);
  CHECK(std::fabs(park.trajectory.summary.hang_time_s - open.trajectory.summary.hang_time_s) < 1e-3);
  CHECK(park.trajectory.summary.total_m == park.trajectory.summary.carry_m);
}

TEST_CASE("a shot reports its lofts as a launch monitor does: at the strike, and the spin loft in 3D", "[run_shot]") {
  // The tour driver: 10.37° at the face centre, struck 11.5 mm up its 305 mm roll (+2.16°),
  // attack -1.3°. Square to the path the spin loft is the strike loft less the attack; a
  // face 4° open to the path adds to it as the hypotenuse does (TrackMan: spin loft is the
  // angle between the head's direction and the face).
  const ShotResult square = run_scenario(load_scenario(test::assets(), "golf/driver", {"world.name=none"}));
  CHECK(rad_to_deg(square.club.dynamic_loft) == Approx(10.37).margin(1e-9));
  CHECK(rad_to_deg(square.club.strike_loft) == Approx(10.37 + 2.159).margin(0.005));
  CHECK(rad_to_deg(square.club.spin_loft) == Approx(10.37 + 2.159 + 1.3).margin(0.05));
  const ShotResult open =
      run_scenario(load_scenario(test::assets(), "golf/driver", {"world.name=none", "swing.face_angle=4deg"}));
  const double sl = rad_to_deg(square.club.spin_loft);
  CHECK(rad_to_deg(open.club.spin_loft) == Approx(std::hypot(sl, 4.0)).margin(0.15));
}
