// The validation library's reader: the shipped library loads whole, and each malformed
// entry is refused with its file:line and key.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "game/content/validation_file.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {

const char* kSource = R"([sources.s]
authors = "A. Author"
title = "A title"
year = 2020
where = "J. Sport Sci. 1:1"
)";

const char* kCase = R"(
[[case]]
id = "s-carry"
source = "s"
tags = ["golf", "carry"]
set = ["launch.ball_speed=167mph", "launch.vertical_angle=10.9deg", "launch.spin=2686rpm"]
quantity = "carry"
published = "275yd"
tolerance = "11yd"
why = "the source's 4 % spread"
)";

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_validation_file";
  std::filesystem::create_directories(dir);
  const auto p = dir / name;
  std::ofstream(p) << text;
  return p;
}

std::string refusal(const std::string& text) {
  const auto p = write("bad.toml", text);
  try {
    load_validation_library(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("a validation case reads into SI with its display unit", "[validation]") {
  const auto lib = load_validation_library(write("good.toml", std::string(kSource) + kCase));
  REQUIRE(lib.cases.size() == 1);
  const ValidationCase& c = lib.cases[0];
  CHECK(c.published == Approx(275 * 0.9144));
  CHECK(c.tolerance == Approx(11 * 0.9144));
  CHECK(c.unit == "yd");
  CHECK(c.tags == std::vector<std::string>{"golf", "carry"});
  CHECK_FALSE(c.fitted);
  CHECK(c.set.size() == 3);
  CHECK(lib.source("s")->year == 2020);
  CHECK_THAT(c.origin, Contains("good.toml:7"));
}

TEST_CASE("malformed validation cases are refused with file:line and key", "[validation]") {
  const std::string good = std::string(kSource) + kCase;
  CHECK_THAT(refusal(with(good, "source = \"s\"", "source = \"t\"")), Contains("bad.toml:7") && Contains("'t' is not defined"));
  CHECK_THAT(refusal(with(good, "\"golf\", \"carry\"", "\"carry\", \"golf\"")), Contains("tags") && Contains("sport"));
  CHECK_THAT(refusal(with(good, "\"golf\", \"carry\"", "\"golf\", \"flying\"")), Contains("unknown tag 'flying'"));
  CHECK_THAT(refusal(with(good, "quantity = \"carry\"", "quantity = \"joy\"")), Contains("unknown quantity 'joy'"));
  CHECK_THAT(refusal(with(good, "published = \"275yd\"", "published = \"275\"")), Contains("published") && Contains("unit"));
  CHECK_THAT(refusal(with(good, "published = \"275yd\"", "published = \"275mph\"")), Contains("published"));
  CHECK_THAT(refusal(with(good, "tolerance = \"11yd\"", "tolerance = \"0yd\"")), Contains("tolerance"));
  CHECK_THAT(refusal(with(good, "\"launch.spin=2686rpm\"", "\"launch.spin\"")), Contains("not key=value"));
  CHECK_THAT(refusal(with(good, "why = ", "whence = ")), Contains("unknown key"));
  CHECK_THAT(refusal(with(good, "quantity = \"carry\"", "quantity = \"horizontal_break\"")), Contains("pitch:TYPE"));
  CHECK_THAT(refusal(good + with(kCase, "id = \"s-carry\"", "id = \"s-carry\"")), Contains("used twice"));
  CHECK_THAT(refusal(std::string(kSource) + kSource + kCase), Contains("malformed TOML"));
  CHECK_THAT(refusal(kSource), Contains("[[case]]"));
}

TEST_CASE("the shipped validation library loads, with sources for every case", "[validation]") {
  const auto lib = load_validation_library(test::assets().root() / "validation");
  std::set<std::string> sources;
  for (const auto& c : lib.cases) {
    REQUIRE(lib.source(c.source) != nullptr);
    sources.insert(c.source);
    CHECK(c.tolerance > 0.0);
  }
  CHECK(lib.cases.size() >= 150);
  CHECK(sources.size() >= 30);
}
