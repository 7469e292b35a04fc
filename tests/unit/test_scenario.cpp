// Scenarios end to end: loading with overrides, determinism, worlds and lies, sweeps
// (ordering and thread independence), fitting e and µ, and the regression harness.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "game/scenario/fit.hpp"
#include "game/scenario/regression.hpp"
#include "game/scenario/scenario.hpp"
#include "game/scenario/sweep.hpp"
#include "physics/error.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

TEST_CASE("load_scenario builds physics inputs from the file and overrides", "[scenario-run]") {
  const Scenario s = load_scenario("golf/driver", {"swing.speed=100mph", "impact.e=0.75", "impact.friction=none"});
  CHECK(s.sport == Sport::Golf);
  CHECK(s.club.name == "driver");
  CHECK(s.ball.name == "tour");
  CHECK(s.golf_swing.club_speed == Approx(100 * 0.44704).epsilon(1e-15));
  CHECK(s.golf_swing.attack_angle == Approx(-1.3 * kPi / 180).epsilon(1e-15));
  CHECK(s.golf_swing.dynamic_loft == s.club.dynamic_loft);
  CHECK(s.material.e.count == 1);
  CHECK(s.material.e.at(40.0) == 0.75);
  CHECK(s.material.friction == FrictionModel::None);
  CHECK(s.world == "golf_hole");
  CHECK(s.aero->name == "ferguson2022");
  const Scenario b = load_scenario("baseball/line-drive", {});
  CHECK(b.bat.name == "maple");
  CHECK(b.world == "ballpark");
  CHECK(b.aero->name == "nathan");
  CHECK_THROWS_WITH(load_scenario("golf/driver", {"club.name=putter"}), Contains("club.name") && Contains("driver"));
  CHECK_THROWS_WITH(load_scenario("golf/driver", {"world.name=moon"}), Contains("world.name") && Contains("moon"));
  CHECK_THROWS_WITH(load_scenario("golf/driver", {"aero.model=magic"}), Contains("aero.model") && Contains("ferguson2022"));
}

TEST_CASE("run_scenario is deterministic and follows DESIGN §2 signs", "[scenario-run]") {
  const Scenario s = load_scenario("golf/driver", {"world.name=none"});
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
  const ShotResult toe = run_scenario(load_scenario("golf/toe-hook", {}), RunOptions{false, false});
  const ShotResult heel = run_scenario(load_scenario("golf/heel-slice", {}), RunOptions{false, false});
  CHECK(toe.launch.spin.axis_rad < 0.0);
  CHECK(heel.launch.spin.axis_rad > 0.0);
  // Headwind shortens, altitude lengthens.
  const double carry = run_scenario(load_scenario("golf/driver", {})).trajectory.summary.carry_m;
  CHECK(run_scenario(load_scenario("golf/into-wind", {})).trajectory.summary.carry_m < carry - 10.0);
  CHECK(run_scenario(load_scenario("golf/altitude", {})).trajectory.summary.carry_m > carry + 5.0);
}

TEST_CASE("the sand wedge starts in the bunker and the lie is checked", "[scenario-run]") {
  const Scenario s = load_scenario("golf/sand-wedge", {});
  CHECK(s.start_surface == "sand");
  CHECK(s.ball_offset.x() == 255.0);
  CHECK(s.ball_offset.y() < 0.0);  // the bunker is dug into the fairway
  const ShotResult r = run_scenario(s);
  CHECK(r.launch_state.position.x() == Approx(255.0).margin(0.05));
  CHECK(r.launch_state.velocity.z() < 0.0);  // aimed left, at the flag
  CHECK_THROWS_WITH(load_scenario("golf/sand-wedge", {"world.ball_position=[100m,0m]"}),
                    Contains("world.lie") && Contains("not sand"));
}

TEST_CASE("launch-only scenarios skip the impact", "[scenario-run]") {
  ScenarioDoc doc = parse_toml_doc("sport = \"golf\"\n[launch]\nball_speed = \"167mph\"\nvertical_angle = \"10.9deg\"\n"
                                   "spin = \"2686rpm\"\n[world]\nname = \"none\"\n",
                                   "launch.toml");
  const ShotResult r = run_scenario(scenario_from_doc(doc, "launch"));
  CHECK_FALSE(r.impact.present);
  CHECK_FALSE(r.has_impactor);
  CHECK(r.launch.ball_speed == Approx(167 * 0.44704).epsilon(1e-12));
  CHECK(r.launch.spin.total == Approx(2686 * kRadPerSecPerRpm).epsilon(1e-12));
  apply_set(doc, "launch.ball_speed=200m/s");
  CHECK_THROWS_WITH(scenario_from_doc(doc, "x"), Contains("launch.ball_speed") && Contains("150 m/s"));
}

TEST_CASE("sweep output is ordered and independent of the thread count", "[sweep]") {
  const Scenario s = load_scenario("golf/7-iron", {"world.name=none"});
  SweepOptions o;
  o.e = parse_grid_axis("0.7:0.9:3", "--e", 0, 1);
  o.mu = parse_grid_axis("0.1:0.5:4", "--mu", 0, 2);
  o.threads = 1;
  const auto one = run_sweep(s, o);
  o.threads = 3;
  const auto three = run_sweep(s, o);
  REQUIRE(one.size() == 12);
  CHECK(sweep_csv(one) == sweep_csv(three));
  CHECK(one[0].e == 0.7);
  CHECK(one[0].mu == 0.1);
  CHECK(one[3].mu == Approx(0.5).epsilon(1e-15));
  CHECK(one[4].e == Approx(0.8).epsilon(1e-15));
  CHECK(one[11].e == Approx(0.9).epsilon(1e-15));
  // Ball speed rises with e at fixed µ.
  CHECK(one[8].shot.launch.ball_speed > one[0].shot.launch.ball_speed);
  CHECK_THROWS_WITH(parse_grid_axis("0.5:1.5:3", "--e", 0, 1), Contains("--e 0.5:1.5:3") && Contains("<= 1"));
  CHECK_THROWS_WITH(parse_grid_axis("0:1:0", "--e", 0, 1), Contains("N = 0"));
  CHECK_THROWS_WITH(parse_grid_axis("0:1", "--e", 0, 1), Contains("A:B:N"));
  CHECK_THROWS_WITH(parse_grid_axis("0:nan:3", "--mu", 0, 2), Contains("NaN"));
  o.e = parse_grid_axis("0:1:1000", "--e", 0, 1);
  o.mu = parse_grid_axis("0:1:101", "--mu", 0, 2);
  CHECK_THROWS_WITH(run_sweep(s, o), Contains("101000") && Contains("100000"));
}

TEST_CASE("fit recovers e and mu that produced a launch", "[fit]") {
  Scenario s = load_scenario("golf/7-iron", {"world.name=none"});
  Scenario truth = s;
  truth.material.e = CorCurve::constant(0.78);
  truth.material.mu = 0.15;
  const ShotResult r = run_scenario(truth, RunOptions{false, false});
  FitTarget t;
  t.ball_speed = r.launch.ball_speed;
  t.launch_angle = r.launch.vertical_angle;
  t.spin = r.launch.spin.total;
  const FitResult f = fit_e_mu(s, t);
  CHECK(f.reached);
  CHECK(f.e == Approx(0.78).margin(0.002));
  CHECK(std::fabs(f.ball_speed_residual) < 0.01);
  CHECK(std::fabs(f.spin_residual) < rpm_to_radps(5));
  if (r.impact.contact == ContactKind::Slip) CHECK(f.mu == Approx(0.15).margin(0.005));
  // Unreachable: faster than any e can give.
  FitTarget fast;
  fast.ball_speed = mph_to_mps(200);
  const FitResult g = fit_e_mu(s, fast);
  CHECK_FALSE(g.reached);
  CHECK(g.e == Approx(1.0).margin(1e-9));
  const FitTarget parsed = parse_fit_target("ball_speed=120mph,launch_angle=16.3deg,spin=7097rpm");
  CHECK(*parsed.ball_speed == Approx(mph_to_mps(120)).epsilon(1e-15));
  CHECK_THROWS_WITH(parse_fit_target("ball_speed=120"), Contains("--target ball_speed=120") && Contains("missing unit"));
  CHECK_THROWS_WITH(parse_fit_target("carry=200yd"), Contains("unknown target 'carry'"));
  CHECK_THROWS_WITH(parse_fit_target("spin=30000rpm"), Contains("20000 rpm"));
}

TEST_CASE("regression cases detect drift and --update rewrites only pinned values", "[regression]") {
  const auto src = std::filesystem::path(SWEETSPOT_SOURCE_DIR) / "tests/regression";
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_regress_unit";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(src / "trackman_driver_launch.toml", dir / "a.toml");
  std::filesystem::copy_file(src / "friction_plane_coulomb.toml", dir / "b.toml");
  const auto a = run_regression_case(dir / "a.toml");
  CHECK(a.passed());
  // Drift: move the expected carry by 5 yd.
  std::string text = a.original_text;
  const auto pos = text.find("carry = \"");
  REQUIRE(pos != std::string::npos);
  text.replace(pos, 9, "carry = \"5");
  std::ofstream(dir / "a.toml") << text;
  const auto drifted = run_regression_case(dir / "a.toml");
  CHECK_FALSE(drifted.passed());
  CHECK_THAT(regression_table({drifted}), Contains("FAIL") && Contains("carry"));
  // The update restores a passing file that keeps comments and other lines.
  std::ofstream(dir / "a.toml") << drifted.updated_text;
  const auto updated = run_regression_case(dir / "a.toml");
  CHECK(updated.passed());
  CHECK_THAT(updated.original_text, Contains("# TrackMan PGA Tour average"));
  const auto b = run_regression_case(dir / "b.toml");
  CHECK(b.reference);
  CHECK(b.updated_text == b.original_text);
  std::filesystem::remove_all(dir);
  CHECK_THROWS_WITH(regression_paths({"/nonexistent/case.toml"}), Contains("/nonexistent/case.toml"));
}

TEST_CASE("sweep threads share one golf_hole world and still agree bit for bit", "[sweep][world]") {
  // The world is built once per process and queried by every worker at once (its default
  // sweep method only reads). Full flights to rest on the course, 1 thread against 4.
  const Scenario s = load_scenario("golf/driver", {});
  SweepOptions o;
  o.e = parse_grid_axis("0.70:0.86:5", "--e", 0, 1);
  o.mu = parse_grid_axis("0.2:0.6:5", "--mu", 0, 2);
  o.threads = 1;
  const auto one = run_sweep(s, o);
  o.threads = 4;
  const auto four = run_sweep(s, o);
  REQUIRE(one.size() == 25);
  CHECK(sweep_csv(one) == sweep_csv(four));
  for (const auto& p : one) CHECK(p.shot.trajectory.summary.end == EndReason::Rest);
}
