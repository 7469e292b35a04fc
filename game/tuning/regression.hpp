// The regression harness behind `sweetspot regress`: each tests/regression/*.toml case is
// either an impact case (`case = "impact"`, the textbook's worked examples) or a scenario
// (full shot or launch-only) with an [expect] section. Every expectation is compared with
// what the current build computes; `--update` rewrites the expected values in place.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "game/content/assets.hpp"

namespace sweetspot {

struct RegressionRow {
  std::string quantity;   ///< "ball_speed", "ball_velocity.x", "contact"
  std::string expected;   ///< display text in the unit the case wrote ("167 mph")
  std::string got;
  std::string delta;      ///< got - expected, same unit ("" for text)
  std::string tolerance;
  bool pass = false;
  bool numeric = true;    ///< false for text rows (contact); the *_si fields are then 0
  std::string unit;       ///< the unit of expected/got/delta/tolerance ("mph", "" for text)
  double expected_si = 0; ///< SI (m/s, rad, rad/s, m ...): what machine readers compare
  double got_si = 0;
  double tolerance_si = 0;
  std::string si_unit;    ///< the SI unit of the *_si fields ("m/s", "rad")
  std::string origin;     ///< "file:line" of the expectation in the case file
};

struct RegressionCaseResult {
  std::filesystem::path path;
  std::string name;                  ///< file stem
  std::vector<RegressionRow> rows;
  std::string original_text;         ///< the file as read
  std::string updated_text;          ///< the file with every expected value set to what was measured
  bool reference = false;            ///< `update = false`: external reference values, never rewritten
  bool passed() const;
};

/// The case files named by `args` (files, or directories whose *.toml are taken in name
/// order); with no args, <source root>/tests/regression (SWEETSPOT_ROOT or the build's
/// source dir). A missing path -> InputError naming it.
std::vector<std::filesystem::path> regression_paths(const std::vector<std::string>& args);

/// Runs one case. Bad case files -> InputError (file:line, key, range). A case with no
/// expectations -> InputError (it would check nothing).
RegressionCaseResult run_regression_case(const Assets& assets, const std::filesystem::path& path);

/// Fixed-width table: case, quantity, expected, got, delta, tol, pass/FAIL.
std::string regression_table(const std::vector<RegressionCaseResult>& results);

}  // namespace sweetspot
