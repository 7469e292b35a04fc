// Regression reports for machines: JUnit XML that any reader can parse whatever the case is
// called, failures that carry expected, actual and tolerance, JSON with SI beside display.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "game/tuning/regression_report.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {
RegressionCaseResult drifted_case(const std::string& name) {
  RegressionCaseResult c;
  c.name = name;
  std::string file = name;
  file.append(".toml");
  c.path = std::filesystem::path("/cases") / file;
  // quantity, expected, got, delta, tolerance, pass, numeric, unit, SI expected/got/tol, SI unit, origin
  const RegressionRow ok{"ball_speed", "167 mph", "166.9 mph", "-0.1", "5", true, true, "mph", 74.65, 74.61, 2.235,
                         "m/s", c.path.string() + ":11"};
  const RegressionRow bad{"spin", "6000 rpm", "6901.05 rpm", "901", "100", false, true, "rpm", 628.3, 722.7, 10.47,
                          "rad/s", c.path.string() + ":12"};
  c.rows = {ok, bad};
  return c;
}
}  // namespace

TEST_CASE("JUnit: one testcase per check, a failure names expected, actual, delta and tolerance",
          "[regression][report]") {
  const std::string x = regression_junit({drifted_case("golf_7-iron")});
  CHECK_THAT(x, Contains("<?xml version=\"1.0\" encoding=\"UTF-8\"?>"));
  CHECK_THAT(x, Contains("<testsuites name=\"sweetspot regress\" tests=\"2\" failures=\"1\""));
  CHECK_THAT(x, Contains("<testcase classname=\"regress.golf_7-iron\" name=\"ball_speed\"/>"));
  CHECK_THAT(x, Contains("message=\"spin: expected 6000 rpm, actual 6901.05 rpm, delta 901 rpm, tolerance 100 rpm\""));
  CHECK_THAT(x, Contains("where: /cases/golf_7-iron.toml:12"));
}

TEST_CASE("JUnit: markup, control bytes and broken UTF-8 in a case name cannot break the XML",
          "[regression][report][hostile]") {
  const std::string x = regression_junit({drifted_case("a<b>&\"c'\x01\xff\xc3(\xe2\x82\xac")});
  CHECK_THAT(x, Contains("name=\"a&lt;b&gt;&amp;&quot;c&apos;\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD(\xe2\x82\xac\""));
  CHECK(x.find('\x01') == std::string::npos);
  CHECK(x.find('\xff') == std::string::npos);
}

TEST_CASE("regression JSON: display values in the case's unit and SI values side by side", "[regression][report]") {
  const nlohmann::json j = regression_json({drifted_case("golf_7-iron")});
  CHECK(j["checks"] == 2);
  CHECK(j["failed"] == 1);
  const auto& spin = j["cases"][0]["checks"][1];
  CHECK(spin["quantity"] == "spin");
  CHECK(spin["pass"] == false);
  CHECK(spin["unit"] == "rpm");
  CHECK(j["cases"][0]["checks"][0]["got_si"].get<double>() == Approx(74.61));
  CHECK(j["cases"][0]["checks"][0]["si_unit"] == "m/s");
  CHECK(j["cases"][0]["passed"] == false);
}
