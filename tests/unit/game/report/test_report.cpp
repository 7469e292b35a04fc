// Report writers: key names of DESIGN §6, GSPro v1 field names and units, CSV columns,
// and display-unit conversion in the launch-monitor table.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "game/content/scenario.hpp"
#include "game/report/metrics.hpp"
#include "game/report/report.hpp"
#include "physics/error.hpp"
#include "physics/math.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"
#include "game/rules/run_shot.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {

constexpr double kDeg = kPi / 180.0;

ShotResult golf_shot() {
  ShotResult r;
  r.scenario = "golf/driver";
  r.sport = "golf";
  // 167 mph, 10.9 deg up, 1.5 deg right, 2686 rpm with a 3 deg axis (TrackMan driver row).
  r.launch_state = launch_from_metrics(mph_to_mps(167), 10.9 * kDeg, 1.5 * kDeg, rpm_to_radps(2686), 3 * kDeg,
                                       Vec3(0, 0.021335, 0));
  r.launch = measure_launch(r.launch_state);
  r.smash_factor = 167.0 / 113.0;
  r.impact.present = true;
  r.impact.e = 0.8;
  r.impact.mu = 0.4;
  r.impact.friction = FrictionModel::Coulomb;
  r.impact.contact = ContactKind::Grip;
  r.impact.normal_impulse = 3.4;
  r.impact.tangential_impulse = 0.4;
  r.impact.energy_loss = 25.0;
  r.club.club = "driver";
  r.club.speed = mph_to_mps(113);
  r.club.speed_at_impact = mph_to_mps(112);
  r.club.attack_angle = -1.3 * kDeg;
  r.club.dynamic_loft = 13.0 * kDeg;
  r.club.strike_loft = 15.2 * kDeg;  // a launch monitor's dynamic loft: at the strike, not the face centre
  r.club.spin_loft = 17.0 * kDeg;    // its spin loft: 3D, more than strike loft less attack
  r.club.lie = 58 * kDeg;
  r.club.impact_toe = 0.010;
  r.club.closure_rate = 2000 * kDeg;
  auto& s = r.trajectory.summary;
  s.carry_m = yd_to_m(275);
  s.total_m = yd_to_m(295);
  s.apex_m = yd_to_m(32);
  s.landing_angle_deg = 38;
  s.hang_time_s = 6.5;
  s.lateral_m = yd_to_m(-4);
  s.rest_position = Vec3(269.7, 0.02, -3.6);
  s.end = EndReason::Rest;
  r.end = ShotEnd::Rest;
  return r;
}

}  // namespace

TEST_CASE("shot_json carries the DESIGN §6 keys in SI", "[report]") {
  const auto j = shot_json(golf_shot());
  CHECK(j["scenario"] == "golf/driver");
  CHECK(j["sport"] == "golf");
  for (const char* k : {"ball_speed_mps", "vertical_angle_deg", "horizontal_angle_deg", "spin_rpm", "backspin_rpm",
                        "sidespin_rpm", "spin_axis_deg", "smash_factor"}) {
    INFO(k);
    CHECK(j["launch"].contains(k));
  }
  for (const char* k : {"e", "mu", "friction", "contact", "normal_impulse_Ns", "tangential_impulse_Ns", "energy_loss_J"}) {
    INFO(k);
    CHECK(j["impact"].contains(k));
  }
  for (const char* k : {"carry_m", "total_m", "apex_m", "landing_angle_deg", "hang_time_s", "lateral_m", "end",
                        "rest_position_m"}) {
    INFO(k);
    CHECK(j["flight"].contains(k));
  }
  CHECK(j["launch"]["ball_speed_mps"].get<double>() == Approx(mph_to_mps(167)).epsilon(1e-12));
  CHECK(j["launch"]["vertical_angle_deg"].get<double>() == Approx(10.9).epsilon(1e-12));
  CHECK(j["launch"]["spin_rpm"].get<double>() == Approx(2686).epsilon(1e-12));
  CHECK(j["launch"]["spin_axis_deg"].get<double>() == Approx(3).epsilon(1e-9));
  CHECK(j["impact"]["contact"] == "grip");
  CHECK(j["impact"]["friction"] == "coulomb");
  CHECK(j["flight"]["end"] == "rest");
  CHECK(j["flight"]["rest_position_m"].size() == 3);
  // A launch-only shot has no impact object.
  ShotResult launch_only = golf_shot();
  launch_only.impact.present = false;
  CHECK_FALSE(shot_json(launch_only).contains("impact"));
}

TEST_CASE("GSPro message uses OpenConnect v1 names and units", "[report]") {
  const auto j = gspro_json(golf_shot(), 7);
  CHECK(j["APIversion"] == "1");
  CHECK(j["ShotNumber"] == 7);
  CHECK(j["Units"] == "Yards");
  const auto& b = j["BallData"];
  CHECK(b["Speed"].get<double>() == Approx(167).epsilon(1e-12));
  CHECK(b["VLA"].get<double>() == Approx(10.9).epsilon(1e-12));
  CHECK(b["HLA"].get<double>() == Approx(1.5).epsilon(1e-12));
  CHECK(b["TotalSpin"].get<double>() == Approx(2686).epsilon(1e-12));
  CHECK(b["SpinAxis"].get<double>() == Approx(3).epsilon(1e-9));
  CHECK(b["BackSpin"].get<double>() == Approx(2686 * std::cos(3 * kDeg)).epsilon(1e-9));
  CHECK(b["SideSpin"].get<double>() == Approx(2686 * std::sin(3 * kDeg)).epsilon(1e-9));
  CHECK(b["CarryDistance"].get<double>() == Approx(275).epsilon(1e-12));
  const auto& c = j["ClubData"];
  for (const char* k : {"Speed", "AngleOfAttack", "FaceToTarget", "Lie", "Loft", "Path", "SpeedAtImpact",
                        "VerticalFaceImpact", "HorizontalFaceImpact", "ClosureRate"}) {
    INFO(k);
    CHECK(c.contains(k));
  }
  CHECK(c["Speed"].get<double>() == Approx(113).epsilon(1e-12));
  CHECK(c["AngleOfAttack"].get<double>() == Approx(-1.3).epsilon(1e-12));
  CHECK(c["HorizontalFaceImpact"].get<double>() == Approx(10).epsilon(1e-12));
  CHECK(c["ClosureRate"].get<double>() == Approx(2000).epsilon(1e-12));
  CHECK(j["ShotDataOptions"]["ContainsClubData"] == true);
}

TEST_CASE("launch-monitor table converts to display units", "[report]") {
  const auto r = golf_shot();
  const SportProfile& golf = test::assets().sport("golf");
  const std::string imperial = launch_table(r, golf, UnitSystem::Imperial);
  CHECK_THAT(imperial, Contains("167.0 mph") && Contains("113.0 mph") && Contains("275.0 yd") &&
                           Contains("2686 rpm") && Contains("10.9 deg") && Contains("-1.3 deg") && Contains("1.48"));
  const std::string metric = launch_table(r, golf, UnitSystem::Metric);
  CHECK_THAT(metric, Contains("74.7 m/s") && Contains("251.5 m"));
  CHECK(parse_unit_system("metric") == UnitSystem::Metric);
  CHECK_THROWS_WITH(parse_unit_system("furlongs"), Contains("--units") && Contains("imperial, metric"));
}

TEST_CASE("CSV rows match their header; baseball uses Statcast names", "[report]") {
  auto count = [](const std::string& line) { return std::count(line.begin(), line.end(), ',') + 1; };
  const auto g = golf_shot();
  const SportProfile& golf = test::assets().sport("golf");
  const SportProfile& baseball = test::assets().sport("baseball");
  CHECK(count(csv_header(golf, UnitSystem::Imperial)) == count(csv_row(g, golf, UnitSystem::Imperial)));
  CHECK(count(csv_header(golf, UnitSystem::Metric)) == count(csv_row(g, golf, UnitSystem::Metric)));
  CHECK_THAT(csv_header(golf, UnitSystem::Metric), Contains("carry_m") && Contains("ball_speed_mps"));
  ShotResult b = g;
  b.sport = "baseball";
  b.scenario = "baseball/line-drive";
  b.bat.bat = "maple";
  b.bat.speed = mph_to_mps(70);
  const std::string header = csv_header(baseball, UnitSystem::Imperial);
  CHECK_THAT(header, Contains("launch_speed") && Contains("launch_angle") && Contains("spray_angle") &&
                         Contains("hit_distance_sc") && Contains("bat_speed"));
  const std::string row = csv_row(b, baseball, UnitSystem::Imperial);
  CHECK(count(header) == count(row));
  CHECK_THAT(row, Contains(",167,10.9,1.5,"));
  CHECK(csv_field("a,b") == "\"a,b\"");
  CHECK(csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
}

TEST_CASE("every metric a sport's profile names exists, and a table row can be added as data", "[report][metrics]") {
  for (const SportProfile& p : test::assets().sports().sports) {
    for (const std::string& id : p.report) {
      INFO(p.name << " report " << id);
      CHECK(find_metric(id) != nullptr);
    }
    for (const std::string& id : p.csv) {
      INFO(p.name << " csv " << id);
      CHECK(find_metric(id) != nullptr);
    }
  }
  // A sport-specific row is a profile edit: the table follows the list.
  SportProfile golf = test::assets().sport("golf");
  golf.report = {"ball_speed", "spin_loft", "dynamic_loft"};
  const std::string t = launch_table(golf_shot(), golf, UnitSystem::Imperial);
  CHECK_THAT(t, Contains("Ball speed") && Contains("Spin loft") && Contains("17.0 deg") && Contains("15.2 deg"));
  CHECK_THAT(t, !Contains("13.0 deg") && !Contains("14.3 deg"));  // the face-centre loft, and it less attack
  CHECK_THAT(t, !Contains("Carry"));
  golf.report = {"no_such_metric"};
  CHECK_THROWS_WITH(launch_table(golf_shot(), golf, UnitSystem::Imperial), Contains("no_such_metric"));
}

TEST_CASE("one vocabulary: the CSV's golf columns are the JSON's names; baseball follows --units", "[report][units]") {
  const SportProfile& golf = test::assets().sport("golf");
  const SportProfile& baseball = test::assets().sport("baseball");
  const std::string g = csv_header(golf, UnitSystem::Imperial);
  CHECK_THAT(g, Contains("vertical_angle_deg") && Contains("horizontal_angle_deg") && Contains("side_yd") &&
                    Contains("side_total_yd"));
  CHECK(g.find("launch_angle_deg") == std::string::npos);
  // Statcast's names and units in imperial; the SI columns say their unit in metric.
  CHECK_THAT(csv_header(baseball, UnitSystem::Imperial), Contains(",launch_speed,") && Contains(",hit_distance_sc,") &&
                                                            Contains(",apex_ft,") && Contains(",attack_angle,"));
  CHECK_THAT(csv_header(baseball, UnitSystem::Metric), Contains(",launch_speed_mps,") &&
                                                          Contains(",hit_distance_sc_m,") && Contains(",apex_m,") &&
                                                          Contains(",launch_angle,"));
}

TEST_CASE("side and side total are measured from the target line, not the world axis", "[report][metrics]") {
  ShotResult r = golf_shot();
  r.launch_state.position = Vec3(10.0, 0.0, 20.0);
  r.aim = 90.0 * kDeg;  // the target line runs along the world's +z
  CHECK(side_of_aim(r, Vec3(10.0, 0.0, 220.0)) == Approx(0.0).margin(1e-12));  // on the line, 200 m out
  CHECK(side_of_aim(r, Vec3(5.0, 0.0, 200.0)) == Approx(5.0));    // world -x is right of a +z target
  r.aim = 0.0;
  CHECK(side_of_aim(r, Vec3(200.0, 0.0, 17.0)) == Approx(-3.0));  // left of a +x target
}

TEST_CASE("batting's collision efficiency: EV = q pitch + (1 + q) bat (Nathan)", "[report][metrics]") {
  ShotResult r = golf_shot();
  r.bat.speed = mph_to_mps(70);
  r.bat.pitch_speed = mph_to_mps(90);
  const double q = 0.2;
  r.launch.ball_speed = q * r.bat.pitch_speed + (1 + q) * r.bat.speed;  // 102 mph
  CHECK(collision_efficiency(r) == Approx(q).epsilon(1e-12));
  r.bat.pitch_speed = 0.0;  // a batting tee: q = EV/bat - 1
  CHECK(collision_efficiency(r) == Approx(r.launch.ball_speed / r.bat.speed - 1.0).epsilon(1e-12));
}

TEST_CASE("the JSON reports the restitution the solver used, the nominal e_t beside it", "[report][impact]") {
  // The compliant driver: its contact makes its own tangential restitution.
  const ShotResult r = run_scenario(load_scenario(test::assets(), "golf/driver", {"world.name=none"}), RunOptions{false, false});
  const auto j = shot_json(r);
  CHECK(j["impact"]["e"].get<double>() == r.impact.e);
  CHECK(j["impact"]["e_t"].get<double>() == r.impact.e_t);
  CHECK(j["impact"]["e_t_nominal"].get<double>() == 0.25);  // clubs.toml [face] e_t
  CHECK(std::fabs(r.impact.e_t - 0.25) > 0.01);              // what the contact produced differs
  CHECK(r.impact.e < 0.83);  // the USGA-limit face at the driver's ~49.5 m/s normal speed, 11.5 mm up
}
