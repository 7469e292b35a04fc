// Built-in scenarios: assets/scenarios/<sport>/<name>.toml, addressed as "golf/driver".
// The catalog turns a user's SCENARIO argument (built-in name or .toml path) into a file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "game/scenario/scenario_schema.hpp"

namespace sweetspot {

struct BuiltinScenario {
  std::string name;                ///< "golf/driver"
  std::filesystem::path path;      ///< the .toml file
  std::string description;         ///< the file's `description` line
  Sport sport = Sport::Golf;
};

/// Directory of the built-in scenarios: <asset root>/scenarios.
std::filesystem::path scenario_directory();

/// Every built-in scenario, golf first then baseball, each sport in name order. Throws
/// InputError when the directory is missing or a file does not parse.
std::vector<BuiltinScenario> builtin_scenarios();

/// A SCENARIO argument -> the file to read. Anything ending in ".toml" or naming an
/// existing file is a path (a missing .toml -> InputError "no such file"); otherwise a
/// built-in name. Unknown name -> InputError listing the built-in names.
std::filesystem::path resolve_scenario(std::string_view name_or_path);

}  // namespace sweetspot
