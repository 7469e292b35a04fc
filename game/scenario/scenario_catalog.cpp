// Scenario look-up by name. Built-in names are the file paths relative to the scenario
// directory without ".toml", so adding a file adds a scenario.
#include "game/scenario/scenario_catalog.hpp"

#include <algorithm>

#include "game/assets/assets.hpp"
#include "game/scenario/scenario_doc.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

std::string names_of(const std::vector<BuiltinScenario>& all) {
  std::string out;
  for (const auto& s : all) {
    if (!out.empty()) out += ", ";
    out += s.name;
  }
  return out;
}

}  // namespace

std::filesystem::path scenario_directory() { return asset_root() / "scenarios"; }

std::vector<BuiltinScenario> builtin_scenarios() {
  const auto dir = scenario_directory();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError("built-in scenario directory '" + dir.string() +
                     "' not found (set SWEETSPOT_ASSETS to the assets directory)");
  }
  std::vector<BuiltinScenario> out;
  for (const Sport sport : {Sport::Golf, Sport::Baseball}) {
    const auto sub = dir / to_string(sport);
    if (!std::filesystem::is_directory(sub, ec)) continue;
    std::vector<BuiltinScenario> these;
    for (const auto& entry : std::filesystem::directory_iterator(sub)) {
      if (!entry.is_regular_file() || entry.path().extension() != ".toml") continue;
      BuiltinScenario s;
      s.name = std::string(to_string(sport)) + "/" + entry.path().stem().string();
      s.path = entry.path();
      s.sport = sport;
      const ScenarioDoc doc = read_toml_doc(entry.path());
      if (const DocEntry* d = doc.find("description")) s.description = d->text;
      these.push_back(std::move(s));
    }
    std::sort(these.begin(), these.end(),
              [](const BuiltinScenario& a, const BuiltinScenario& b) { return a.name < b.name; });
    out.insert(out.end(), these.begin(), these.end());
  }
  return out;
}

std::filesystem::path resolve_scenario(std::string_view name_or_path) {
  const std::filesystem::path as_path{std::string(name_or_path)};
  std::error_code ec;
  if (as_path.extension() == ".toml") {
    if (!std::filesystem::exists(as_path, ec)) {
      throw InputError("cannot read scenario '" + as_path.string() + "': no such file");
    }
    return as_path;
  }
  if (std::filesystem::is_regular_file(as_path, ec)) return as_path;
  const auto all = builtin_scenarios();
  for (const auto& s : all) {
    if (s.name == name_or_path) return s.path;
  }
  throw InputError("unknown scenario '" + std::string(name_or_path) + "'; built-in scenarios: " +
                   names_of(all) + "; or give a path to a .toml file");
}

}  // namespace sweetspot
