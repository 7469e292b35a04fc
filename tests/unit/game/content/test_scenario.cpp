// Scenarios end to end: a TOML file with overrides -> ShotSpec -> resolve -> run, errors
// naming where a value came from, worlds and lies, launch-only files.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "game/content/scenario.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"
#include "game/rules/run_shot.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

TEST_CASE("load_scenario builds a ShotSpec from the file and overrides, resolved against the assets", "[scenario-run]") {
  const Assets& A = test::assets();
  const Scenario s = load_scenario(A, "golf/driver", {"swing.speed=100mph", "impact.e=0.75", "impact.friction=none"});
  CHECK(s.spec.sport == "golf");
  const auto& club = std::get<ClubStrike>(s.spec.strike);
  CHECK(s.resolved.club->name == "driver");
  CHECK(s.resolved.ball.name == "tour");
  CHECK(club.swing.club_speed == Approx(100 * 0.44704).epsilon(1e-15));
  CHECK(club.swing.attack_angle == Approx(-1.3 * kPi / 180).epsilon(1e-15));
  CHECK(std::isnan(club.swing.dynamic_loft));  // the club's own typical loft
  CHECK(s.resolved.material.e.count == 1);
  CHECK(s.resolved.material.e.at(40.0) == 0.75);
  CHECK(s.resolved.material.friction == FrictionModel::None);
  CHECK(s.resolved.world_name == "golf_hole");
  CHECK(s.resolved.aero->name == "tour_fit");
  const Scenario b = load_scenario(A, "baseball/line-drive", {});
  CHECK(b.resolved.bat->name == "maple");
  CHECK(b.resolved.world_name == "ballpark");
  CHECK(b.resolved.aero->name == "nathan");
  CHECK_THROWS_WITH(load_scenario(A, "golf/driver", {"club.name=spoon"}),
                    Contains("--set club.name=spoon") && Contains("club.name") && Contains("driver"));
  CHECK_THROWS_WITH(load_scenario(A, "golf/driver", {"world.name=moon"}), Contains("world.name") && Contains("moon"));
  CHECK_THROWS_WITH(load_scenario(A, "golf/driver", {"aero.model=magic"}), Contains("aero.model") && Contains("ferguson2022"));
  // One range per key: the schema refuses with the physics parameter's range, naming the flag.
  CHECK_THROWS_WITH(load_scenario(A, "golf/driver", {"swing.speed=210mph"}),
                    Contains("--set swing.speed=210mph") && Contains("[0.1, 90] m/s"));
  CHECK_THROWS_WITH(load_scenario(A, "baseball/line-drive", {"pitch.spin=5000rpm"}),
                    Contains("pitch.spin") && Contains("4000 rpm"));
}

TEST_CASE("the loft is given at the face centre or where the face meets the ball, never both", "[scenario-run]") {
  const Scenario s = load_scenario(test::assets(), "golf/driver", {"swing.strike_loft=15.1deg"});
  const auto& club = std::get<ClubStrike>(s.spec.strike);
  CHECK(rad_to_deg(club.swing.strike_loft) == Approx(15.1));
  CHECK(std::isnan(club.swing.dynamic_loft));
  CHECK_THROWS_WITH(load_scenario(test::assets(), "golf/driver", {"swing.strike_loft=15.1deg", "swing.dynamic_loft=12deg"}),
                    Catch::Contains("swing.strike_loft") && Catch::Contains("not both"));
}

TEST_CASE("the face angle is given at the face centre or where the face meets the ball, never both", "[scenario-run]") {
  // The built-in driver says its face is square (0°): that is no face angle, and the strike's
  // may stand on it.
  const Scenario s = load_scenario(test::assets(), "golf/driver", {"swing.strike_face_angle=-1.5deg"});
  const auto& club = std::get<ClubStrike>(s.spec.strike);
  CHECK(rad_to_deg(club.swing.strike_face_angle) == Approx(-1.5));
  CHECK(club.swing.face_angle == 0.0);
  CHECK_THROWS_WITH(load_scenario(test::assets(), "golf/driver", {"swing.strike_face_angle=-1.5deg", "swing.face_angle=2deg"}),
                    Catch::Contains("--set swing.strike_face_angle") && Catch::Contains("not both"));
}

TEST_CASE("run_scenario is deterministic and follows DESIGN §2 signs", "[scenario-run]") {
  const Assets& A = test::assets();
  const Scenario s = load_scenario(A, "golf/driver", {"world.name=none"});
  const ShotResult a = run_scenario(s);
  const ShotResult b = run_scenario(s);
  CHECK(a.launch_state.velocity == b.launch_state.velocity);
  CHECK(a.launch_state.spin == b.launch_state.spin);
  CHECK(a.trajectory.summary.carry_m == b.trajectory.summary.carry_m);
  CHECK(a.trajectory.summary.rest_position == b.trajectory.summary.rest_position);
  CHECK(a.impact.present);
  CHECK(a.smash_factor == Approx(a.launch.ball_speed / a.club.speed_at_impact).epsilon(1e-12));
  CHECK(a.launch.spin.backspin > 0);
  CHECK(a.trajectory.summary.carry_m > 200.0);
  // Gear effect: a toe strike hooks (axis < 0), a heel strike slices (axis > 0).
  const ShotResult toe = run_scenario(load_scenario(A, "golf/toe-hook", {}), RunOptions{false, false});
  const ShotResult heel = run_scenario(load_scenario(A, "golf/heel-slice", {}), RunOptions{false, false});
  CHECK(toe.launch.spin.axis_rad < 0.0);
  CHECK(heel.launch.spin.axis_rad > 0.0);
  // Headwind shortens, altitude lengthens.
  const double carry = run_scenario(load_scenario(A, "golf/driver", {})).trajectory.summary.carry_m;
  CHECK(run_scenario(load_scenario(A, "golf/into-wind", {})).trajectory.summary.carry_m < carry - 10.0);
  CHECK(run_scenario(load_scenario(A, "golf/altitude", {})).trajectory.summary.carry_m > carry + 5.0);
}

TEST_CASE("the sand wedge starts in the bunker and the lie is checked", "[scenario-run]") {
  const Assets& A = test::assets();
  const Scenario s = load_scenario(A, "golf/sand-wedge", {});
  CHECK(s.resolved.start_surface == "sand");
  CHECK(s.resolved.ground.x() == 255.0);
  CHECK(s.resolved.ground.y() < 0.0);  // the bunker is dug into the fairway
  const ShotResult r = run_scenario(s);
  CHECK(r.launch_state.position.x() == Approx(255.0).margin(0.05));
  CHECK(r.launch_state.velocity.z() < 0.0);  // aimed left, at the flag
  CHECK_THROWS_WITH(load_scenario(A, "golf/sand-wedge", {"world.ball_position=[100m,0m]"}),
                    Contains("world.lie") && Contains("not sand") && Contains("sand-wedge.toml:"));
}

TEST_CASE("launch-only scenarios skip the impact", "[scenario-run]") {
  const Assets& A = test::assets();
  ScenarioDoc doc = parse_toml_doc("sport = \"golf\"\n[launch]\nball_speed = \"167mph\"\nvertical_angle = \"10.9deg\"\n"
                                   "spin = \"2686rpm\"\n[world]\nname = \"none\"\n",
                                   "launch.toml");
  const ShotResult r = run_scenario(scenario_from_doc(A, doc, "launch"));
  CHECK_FALSE(r.impact.present);
  CHECK_FALSE(r.has_impactor);
  CHECK(r.launch.ball_speed == Approx(167 * 0.44704).epsilon(1e-12));
  CHECK(r.launch.spin.total == Approx(2686 * kRadPerSecPerRpm).epsilon(1e-12));
  apply_set(doc, "launch.ball_speed=200m/s");
  CHECK_THROWS_WITH(scenario_from_doc(A, doc, "x"), Contains("launch.ball_speed") && Contains("[0, 150] m/s"));
}

