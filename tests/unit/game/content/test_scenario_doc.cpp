// Scenario documents: TOML flattening, --set overrides, and every class of bad input
// rejected with its origin (file:line or flag), the key and the allowed range.
#include <catch2/catch.hpp>

#include <string>

#include "game/content/scenario.hpp"
#include "game/content/scenario_doc.hpp"
#include "physics/delivery.hpp"
#include "physics/error.hpp"
#include "physics/math.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

#include <filesystem>

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {

const char* kDriver = R"(sport = "golf"
description = "test driver"
[club]
name = "driver"
[swing]
speed = "113mph"
attack_angle = "-1.3deg"
impact_offset = ["10mm", "-2mm"]
[impact]
e = 0.8
friction = "textbook"
)";

CheckedDoc check(const std::string& text, const std::vector<std::string>& sets = {}) {
  ScenarioDoc doc = parse_toml_doc(text, "case.toml");
  for (const auto& s : sets) apply_set(doc, s);
  return CheckedDoc(doc, scenario_schema(), &test::assets().sports());
}

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    (void)check(text, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("a scenario file flattens to dotted keys in SI", "[scenario]") {
  const CheckedDoc d = check(kDriver);
  CHECK(d.sport()->name == "golf");
  CHECK(d.strikes() == kClubKeys);
  CHECK(d.quantity("swing.speed") == 113 * kMpsPerMph);
  CHECK(d.quantity("swing.attack_angle") == Approx(-1.3 * kPi / 180).epsilon(1e-15));
  CHECK(d.list("swing.impact_offset") == std::vector<double>{0.010, -0.002});
  CHECK(d.quantity("impact.e") == 0.8);
  CHECK(d.text("impact.friction") == "textbook");
  CHECK(d.origin("swing.speed") == "case.toml:6");
  CHECK(d.has("swing.speed"));
  // Defaults apply but do not count as set.
  CHECK_FALSE(d.has("swing.path"));
  CHECK(d.quantity("swing.path") == 0.0);
  CHECK_FALSE(d.text_if_set("ball.name").has_value());  // the sport's ball, by its profile
  CHECK(d.quantity("environment.temperature") == Approx(294.15).epsilon(1e-15));
  CHECK_FALSE(d.quantity_if_set("swing.dynamic_loft").has_value());
}

TEST_CASE("--set overrides any key in dotted form, with units and lists", "[scenario]") {
  const CheckedDoc d = check(kDriver, {"swing.speed=105mph", "swing.impact_offset=[10mm,0mm]",
                                       "environment.altitude=1600m", "impact.friction=coulomb", "impact.mu=0.3"});
  CHECK(d.quantity("swing.speed") == 105 * kMpsPerMph);
  CHECK(d.origin("swing.speed") == "--set swing.speed=105mph");
  CHECK(d.list("swing.impact_offset") == std::vector<double>{0.010, 0.0});
  CHECK(d.quantity("environment.altitude") == 1600.0);
  CHECK(d.text("impact.friction") == "coulomb");
  CHECK(d.quantity("impact.mu") == 0.3);
  CHECK_THAT(error_of(kDriver, {"swing.speed"}), Contains("--set swing.speed") && Contains("key=value"));
}

TEST_CASE("malformed TOML names file, line and column", "[scenario][bad-input]") {
  const std::string bad = "sport = \"golf\"\n[swing]\nspeed = \"113mph\n";
  CHECK_THAT(error_of(bad), Contains("case.toml:3:") && Contains("malformed TOML"));
}

TEST_CASE("unknown keys and sections list what is allowed", "[scenario][bad-input]") {
  const std::string text = std::string(kDriver) + "[swing2]\nspeed = \"1mph\"\n";
  CHECK_THAT(error_of(text), Contains("case.toml:12") && Contains("swing2") && Contains("sections"));
  const std::string typo = "sport = \"golf\"\n[swing]\nsped = \"113mph\"\n";
  CHECK_THAT(error_of(typo), Contains("case.toml:3") && Contains("swing.sped") && Contains("unknown key") &&
                                 Contains("swing.speed"));
  CHECK_THAT(error_of(kDriver, {"swing.sped=1mph"}), Contains("--set swing.sped=1mph") && Contains("unknown key"));
  // A key of the other sport is named as such.
  CHECK_THAT(error_of(kDriver, {"swing.undercut=10mm"}), Contains("scenarios that swing a bat") && Contains("golf"));
  CHECK_THAT(error_of("sport = \"golf\"\n[swing.extra]\n"), Contains("case.toml:2") && Contains("swing.extra"));
}

TEST_CASE("wrong types are rejected with the expected type", "[scenario][bad-input]") {
  CHECK_THAT(error_of("sport = \"golf\"\n[swing]\nspeed = true\n"),
             Contains("case.toml:3") && Contains("swing.speed") && Contains("wrong type") && Contains("boolean"));
  CHECK_THAT(error_of("sport = \"golf\"\n[club]\nname = 7\n"), Contains("club.name") && Contains("wrong type"));
  CHECK_THAT(error_of("sport = \"golf\"\n[swing]\nimpact_offset = \"3mm\"\n"),
             Contains("expected 2 values") && Contains("swing.impact_offset"));
  CHECK_THAT(error_of("sport = \"golf\"\n[swing]\nimpact_offset = [[\"1mm\"]]\n"), Contains("wrong type"));
  CHECK_THAT(error_of("sport = 1\n"), Contains("case.toml:1") && Contains("sport") && Contains("wrong type"));
}

TEST_CASE("missing and unknown units are rejected with the accepted units", "[scenario][bad-input]") {
  CHECK_THAT(error_of("sport = \"golf\"\n[swing]\nspeed = 50\n"),
             Contains("case.toml:3") && Contains("missing unit") && Contains("50mph"));
  CHECK_THAT(error_of(kDriver, {"swing.speed=50"}), Contains("--set swing.speed=50") && Contains("missing unit") &&
                                                        Contains("mph"));
  CHECK_THAT(error_of(kDriver, {"swing.speed=50furlongs"}), Contains("unknown unit 'furlongs'") && Contains("m/s"));
  CHECK_THAT(error_of(kDriver, {"swing.impact_offset=[10mm,0]"}), Contains("missing unit"));
  // Dimensionless keys take bare numbers.
  CHECK(check(kDriver, {"impact.e=0.75"}).quantity("impact.e") == 0.75);
}

TEST_CASE("out-of-range values quote the allowed range", "[scenario][bad-input]") {
  CHECK_THAT(error_of(kDriver, {"impact.e=1.2"}), Contains("impact.e") && Contains("0 <= impact.e <= 1"));
  // The range is the physics parameter's (ImpactMaterial::kE), not a copy.
  CHECK(scenario_schema().find("impact.e", kAnyStrike)->range[0] == &ImpactMaterial::kE);
  CHECK(scenario_schema().find("swing.speed", kClubKeys)->range[0] == &GolfSwing::kClubSpeed);
  CHECK(scenario_schema().find("swing.speed", kBatKeys)->range[0] == &BatSwing::kBatSpeed);
  CHECK_THAT(error_of(kDriver, {"impact.e_t=-0.1"}), Contains("0 <= impact.e_t <= 1"));
  CHECK_THAT(error_of(kDriver, {"impact.mu=-0.1"}), Contains("0 <= impact.mu"));
  CHECK_THAT(error_of(kDriver, {"swing.speed=-5mph"}), Contains("out of range") && Contains("0.223694 mph <= swing.speed"));
  // Resource bounds name the limit in display and SI units.
  CHECK_THAT(error_of(kDriver, {"swing.speed=400mph"}), Contains("201.324 mph") && Contains("[0.1, 90] m/s"));
  // A bound written in another unit that lands a rounding error outside the SI constant is in.
  CHECK(check(kDriver, {"environment.temperature=-50C"}).quantity("environment.temperature") ==
        Approx(223.15).epsilon(1e-12));
  CHECK(check(kDriver, {"environment.temperature=-58F"}).quantity("environment.temperature") ==
        Approx(223.15).epsilon(1e-12));
  CHECK_THAT(error_of(kDriver, {"environment.temperature=-50.1C"}), Contains("out of range"));
  CHECK_THAT(error_of(kDriver, {"ball.mass=-45g"}), Contains("ball.mass") && Contains("out of range"));
  const std::string bb = "sport = \"baseball\"\n[pitch]\nspin = \"25000rpm\"\n";
  CHECK_THAT(error_of(bb), Contains("case.toml:3") && Contains("pitch.spin") && Contains("4000 rpm"));
}

TEST_CASE("NaN and infinity are rejected", "[scenario][bad-input]") {
  CHECK_THAT(error_of(kDriver, {"impact.e=nan"}), Contains("NaN"));
  CHECK_THAT(error_of(kDriver, {"swing.speed=infmph"}), Contains("NaN and infinity"));
  CHECK_THAT(error_of("sport = \"golf\"\n[impact]\ne = nan\n"), Contains("case.toml:3") && Contains("NaN"));
  CHECK_THAT(error_of("sport = \"golf\"\n[impact]\nmu = inf\n"), Contains("case.toml:3") && Contains("infinity"));
}

TEST_CASE("sport is required and must be known", "[scenario][bad-input]") {
  CHECK_THAT(error_of("[swing]\nspeed = \"1mph\"\n"), Contains("missing key 'sport'") && Contains("golf, baseball"));
  CHECK_THAT(error_of("sport = \"cricket\"\n"), Contains("unknown sport 'cricket'") && Contains("golf, baseball"));
  CHECK_THAT(error_of("sport = \"golf\"\n[impact]\nfriction = \"sticky\"\n"),
             Contains("none, textbook, coulomb"));
}

TEST_CASE("expectations come with tolerances", "[scenario][bad-input]") {
  CHECK_THAT(error_of(std::string(kDriver) + "[expect]\nball_speed = \"167mph\"\n"),
             Contains("expect.ball_speed_tol"));
  CHECK_THAT(error_of(std::string(kDriver) + "[expect]\nspin_tol = \"50rpm\"\n"), Contains("without its expected"));
  const CheckedDoc d = check(std::string(kDriver) + "[expect]\nspin = \"2686rpm\"\nspin_tol = \"50rpm\"\n");
  CHECK(d.quantity("expect.spin") == Approx(rpm_to_radps(2686)).epsilon(1e-15));
  CHECK_THAT(error_of(std::string(kDriver) + "[expect]\nspin = \"2686rpm\"\nspin_tol = \"-5rpm\"\n"),
             Contains("out of range"));
  // An expectation no shot can meet (a negative carry, a launch past vertical) can never pass.
  CHECK_THAT(error_of(std::string(kDriver) + "[expect]\ncarry = \"-5yd\"\ncarry_tol = \"1yd\"\n"),
             Contains("case.toml:") && Contains("expect.carry") && Contains("out of range"));
  CHECK_THAT(error_of(std::string(kDriver) + "[expect]\nvertical_angle = \"100deg\"\nvertical_angle_tol = \"1deg\"\n"),
             Contains("expect.vertical_angle") && Contains("out of range"));
  CHECK(check(std::string(kDriver) + "[expect]\nbackspin = \"-500rpm\"\nbackspin_tol = \"50rpm\"\n").quantity("expect.backspin") < 0.0);
}

TEST_CASE("a missing file is named", "[scenario][bad-input]") {
  CHECK_THROWS_WITH(read_toml_doc("/nonexistent/x.toml"), Contains("/nonexistent/x.toml") && Contains("not found"));
}

TEST_CASE("every built-in scenario is valid and described", "[scenario]") {
  const Assets& A = test::assets();
  const auto& all = A.scenarios();
  REQUIRE(all.size() >= 14);
  for (const auto& s : all) {
    INFO(s.name);
    const CheckedDoc d(read_toml_doc(s.path), scenario_schema(), &A.sports());
    CHECK(d.sport()->name == s.sport);
    CHECK_FALSE(scenario_description(s).empty());
    CHECK_NOTHROW(load_scenario(A, s.name, {}));
  }
  for (const char* name : {"golf/driver", "golf/3-wood", "golf/7-iron", "golf/pw", "golf/sand-wedge", "golf/toe-hook",
                           "golf/heel-slice", "golf/into-wind", "golf/altitude", "baseball/line-drive",
                           "baseball/home-run", "baseball/grounder", "baseball/pop-up", "baseball/opposite-field"}) {
    INFO(name);
    CHECK(std::filesystem::exists(resolve_scenario(A, name)));
  }
  CHECK_THROWS_WITH(resolve_scenario(A, "golf/drivr"), Contains("unknown scenario 'golf/drivr'") && Contains("golf/driver"));
  CHECK_THROWS_WITH(load_scenario(A, "nope.toml", {}), Contains("nope.toml") && Contains("not found"));
}

TEST_CASE("a quoted dotted key is refused, not taken for the nested key", "[scenario][bad-input]") {
  CHECK_THAT(error_of("sport = \"golf\"\n\"swing.speed\" = \"100mph\"\n"),
             Contains("case.toml:2") && Contains("swing.speed") && Contains("quoted key"));
  CHECK_THAT(error_of(kDriver, {"swing.impact_offset=[10mm]"}), Contains("expected 2 values"));
  CHECK_THAT(error_of(kDriver, {"club.name="}), Contains("club.name") && Contains("empty"));
}
