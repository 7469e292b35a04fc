// The regression harness: drift detection and --update.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "game/content/scenario.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"
#include "game/tuning/regression.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

TEST_CASE("regression cases detect drift and --update rewrites only pinned values", "[regression]") {
  const Assets& A = test::assets();
  const auto src = std::filesystem::path(SWEETSPOT_SOURCE_DIR) / "tests/regression";
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_regress_unit";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(src / "trackman_driver_launch.toml", dir / "a.toml");
  std::filesystem::copy_file(src / "friction_plane_coulomb.toml", dir / "b.toml");
  const auto a = run_regression_case(A, dir / "a.toml");
  CHECK(a.passed());
  // Drift: move the expected carry by 5 yd.
  std::string text = a.original_text;
  const auto pos = text.find("carry = \"");
  REQUIRE(pos != std::string::npos);
  text.replace(pos, 9, "carry = \"5");
  std::ofstream(dir / "a.toml") << text;
  const auto drifted = run_regression_case(A, dir / "a.toml");
  CHECK_FALSE(drifted.passed());
  CHECK_THAT(regression_table({drifted}), Contains("FAIL") && Contains("carry"));
  // The update restores a passing file that keeps comments and other lines.
  std::ofstream(dir / "a.toml") << drifted.updated_text;
  const auto updated = run_regression_case(A, dir / "a.toml");
  CHECK(updated.passed());
  CHECK_THAT(updated.original_text, Contains("# TrackMan PGA Tour average"));
  const auto b = run_regression_case(A, dir / "b.toml");
  CHECK(b.reference);
  CHECK(b.updated_text == b.original_text);
  std::filesystem::remove_all(dir);
  CHECK_THROWS_WITH(regression_paths({"/nonexistent/case.toml"}), Contains("/nonexistent/case.toml"));
}


TEST_CASE("--update rewrites values inside an inline expect table, keeping the table", "[regression][hostile]") {
  // Hostile input: the whole `expect = { ... }` line must not become one string.
  const Assets& A = test::assets();
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_regress_inline";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "c.toml") << "sport = \"baseball\"\n"
                                   "expect = { ball_speed = \"100mph\", ball_speed_tol = \"0.1mph\", \"spin\" = \"1500rpm\", "
                                   "spin_tol = \"10rpm\" }  # pinned\n"
                                   "[bat]\nname = \"maple\"\n[swing]\nspeed = \"70mph\"\n[pitch]\nspeed = \"90mph\"\n"
                                   "[world]\nname = \"none\"\n";
  const auto first = run_regression_case(A, dir / "c.toml");
  CHECK_FALSE(first.passed());
  CHECK_THAT(first.updated_text, Contains("expect = { ball_speed = \"") && Contains("\"spin\" = \"") &&
                                     Contains(", ball_speed_tol = \"0.1mph\"") && Contains("spin_tol = \"10rpm\" }  # pinned"));
  std::ofstream(dir / "c.toml") << first.updated_text;
  CHECK(run_regression_case(A, dir / "c.toml").passed());
  std::filesystem::remove_all(dir);
}
