// What the panels edit, kept apart from ImGui so it is unit-tested: the scenario chosen and
// the values the user changed, held as `--set` style overrides ("swing.speed=105mph").
// Every change reloads the scenario through the same validation as the command line and
// recomputes the shot, so the window, `sweetspot shot --set ...` and a saved TOML agree.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "game/content/scenario.hpp"

namespace sweetspot {

/// Shown beside the friction choice: the textbook model is kept for teaching only.
inline constexpr const char* kTextbookEnergyNote =
    "textbook: applies mu*J in full every time; it can reverse sliding and CREATE energy "
    "(see the energy-loss readout). Use coulomb for real shots.";

struct UiState {
  std::string scenario = "golf/driver";          ///< built-in name or .toml path
  std::map<std::string, std::string> overrides;  ///< dotted key -> value text with unit

  /// Sets one key (value text as on the command line, with its unit).
  void set(const std::string& key, const std::string& value) { overrides[key] = value; }
  /// Switching scenario (or sport) drops the edits made to the previous one.
  void choose_scenario(const std::string& name) {
    scenario = name;
    overrides.clear();
  }
  /// The overrides as `--set` arguments, in key order (deterministic).
  std::vector<std::string> override_list() const;
};

/// A number with its unit as scenario text: quantity_text(105, "mph") == "105mph". The
/// shortest digits that read back as the same double, so a value survives the round trip.
std::string quantity_text(double value, const std::string& unit);
/// The decimal a float slider meant: the shortest decimal that is the same float (0.808f ->
/// 0.808, not 0.80800002813).
double float_as_decimal(float value);
/// "[12.5mm, -3mm]".
std::string quantity_list_text(const std::vector<double>& values, const std::string& unit);

/// load_scenario(assets, state.scenario, state.override_list()). Throws InputError like the CLI.
Scenario load_ui_scenario(const Assets& assets, const UiState& state);

/// The scenario's document with the overrides applied, as TOML that `sweetspot shot FILE`
/// loads back to the same shot (sections in schema order, values quoted with units).
std::string scenario_toml(const Scenario& scenario);

}  // namespace sweetspot
