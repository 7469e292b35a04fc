// `validate`'s runner: a case runs through the one shot path (the same number as run_shot
// on the same scenario), a baseline case is the difference of two runs, pitches fly through
// throw_pitch, and the reports add up.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "game/content/scenario.hpp"
#include "game/modes/baseball/pitching.hpp"
#include "game/rules/run_shot.hpp"
#include "game/tuning/validation.hpp"
#include "game/tuning/validation_report.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {

ValidationLibrary library(const std::string& cases) {
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_validation_run";
  std::filesystem::create_directories(dir);
  const auto p = dir / "cases.toml";
  std::ofstream(p) << "[sources.s]\nauthors = \"A\"\ntitle = \"T\"\nyear = 2020\nwhere = \"W\"\n" << cases;
  return load_validation_library(p);
}

// One case after the library's source, its [[case]] on the file's line 7.
ValidationLibrary one_case(const std::string& id, const std::string& tags, const std::string& scenario,
                           const std::string& set, const std::string& quantity, const std::string& published,
                           const std::string& tolerance) {
  return library("\n[[case]]\nid = \"" + id + "\"\nsource = \"s\"\ntags = " + tags + "\n" +
                 (scenario.empty() ? std::string() : "scenario = \"" + scenario + "\"\n") + "set = " + set +
                 "\nquantity = \"" + quantity + "\"\npublished = \"" + published + "\"\ntolerance = \"" + tolerance +
                 "\"\nwhy = \"x\"\n");
}

const char* kCases = R"(
[[case]]
id = "driver-carry"
source = "s"
tags = ["golf", "carry"]
fitted = true
scenario = "golf/driver"
set = ["world.name=none"]
quantity = "carry"
published = "275yd"
tolerance = "11yd"
why = "4 %"

[[case]]
id = "hot-day"
source = "s"
tags = ["golf", "atmosphere"]
scenario = "golf/driver"
set = ["world.name=none", "environment.temperature=95F"]
baseline = ["environment.temperature=50F"]
quantity = "carry"
published = "0.5yd"
tolerance = "0.1yd"
why = "made to fail: a hot day carries farther than half a yard"

[[case]]
id = "slider"
source = "s"
tags = ["baseball", "pitch"]
scenario = "pitch:slider"
set = ["pitch.speed=85mph"]
quantity = "induced_vertical_break"
published = "2in"
tolerance = "50in"
why = "wide"
)";

}  // namespace

TEST_CASE("validate runs a case through the shot path, a baseline as a difference, a pitch as thrown", "[validation]") {
  const Assets& A = test::assets();
  const ValidationLibrary lib = library(kCases);
  const auto out = run_validation(A, lib);
  REQUIRE(out.size() == 3);

  const Scenario driver = load_scenario(A, "golf/driver", {"world.name=none"});
  CHECK(out[0].got == run_scenario(driver).trajectory.summary.carry_m);  // the same path, bit for bit
  CHECK(out[0].passed == (std::fabs(out[0].got - 275 * 0.9144) <= 11 * 0.9144));

  const Scenario hot = load_scenario(A, "golf/driver", {"world.name=none", "environment.temperature=95F"});
  const Scenario cold = load_scenario(A, "golf/driver", {"world.name=none", "environment.temperature=50F"});
  const double gain = run_scenario(hot).trajectory.summary.carry_m - run_scenario(cold).trajectory.summary.carry_m;
  CHECK(out[1].got == gain);
  CHECK(gain > 1.0);  // thinner warm air
  CHECK_FALSE(out[1].passed);
  CHECK(out[1].error_in_tolerances() > 1.0);

  PitchCall call;
  call.type = pitch_type(load_pitch_types(A), "slider");
  call.type.speed = 85 * 0.44704;
  CHECK(out[2].got == statcast_movement(A, throw_pitch(A, call)).induced_vertical_break);
  CHECK(out[2].passed);

  const ValidationTotals t = validation_totals(out);
  CHECK(t.all.passed == 2);
  CHECK(t.all.failed == 1);
  CHECK(t.not_fitted.total() == 2);
  const std::string card = validation_scorecard(out);
  CHECK_THAT(card, Contains("validate: 2 passed, 1 failed") && Contains("hot-day") && Contains("FAIL"));
  const auto j = validation_json(lib, out);
  CHECK(j["passed"] == 2);
  CHECK(j["failed"] == 1);
  CHECK(j["cases"].size() == 3);
  CHECK(j["cases"][1]["passed"] == false);
  const std::string xml = validation_junit(lib, out);
  CHECK_THAT(xml, Contains("tests=\"3\" failures=\"1\"") && Contains("<failure"));
}

TEST_CASE("a case whose conditions the schema refuses names the case's file:line", "[validation]") {
  const ValidationLibrary lib =
      one_case("too-fast", R"(["golf", "launch"])", "golf/driver", R"(["swing.speed=900mph"])", "spin", "2500rpm", "100rpm");
  try {
    run_validation(test::assets(), lib);
    FAIL("accepted");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Contains("cases.toml:7") && Contains("swing.speed"));
  }
}

TEST_CASE("a case that asks what its shot cannot give is refused, not failed", "[validation][hostile]") {
  // A launch-only shot has no club speed, so no smash factor (it would read 0 and fail);
  // a golf scenario under a baseball case's first tag is a golf shot in the baseball score.
  const ValidationLibrary no_club =
      one_case("no-club", R"(["golf", "launch"])", "",
               R"(["world.name=none", "launch.ball_speed=150mph", "launch.vertical_angle=10deg", "launch.spin=2500rpm"])",
               "smash_factor", "1.45", "0.05");
  CHECK_THROWS_WITH(run_validation(test::assets(), no_club), Contains("cases.toml:7") && Contains("no smash factor"));
  const ValidationLibrary wrong_sport =
      one_case("wrong-sport", R"(["baseball", "carry"])", "golf/driver", R"(["world.name=none"])", "carry", "275yd", "11yd");
  CHECK_THROWS_WITH(run_validation(test::assets(), wrong_sport), Contains("cases.toml:7") && Contains("golf shot"));
}
