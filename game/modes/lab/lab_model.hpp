// The Lab as a headless model (DESIGN §1): one shot and everything that decides it, edited
// as a typed ShotSpec. An edit sets the field, resolve() checks it against its physics range
// and the shot runs again; a refused value leaves the last good shot and says why, naming
// the scenario key. Text is written only by Save, as the scenario TOML `shot FILE` loads
// back to the same shot.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/scenario.hpp"
#include "game/core/shot_result.hpp"
#include "game/modes/intent.hpp"

namespace sweetspot {

/// A number the Lab edits (Intent::param of an Edit), each one field of the ShotSpec.
enum class LabParam : int {
  ClubSpeed, AttackAngle, ClubPath, DynamicLoft, FaceAngle, ClosureRate, ImpactToe, ImpactUp,
  BatSpeed, BatAttack, BatDirection, PitchSpeed, PitchSpin, ImpactFromTip, Undercut,
  E, Et, Mu,
  Temperature, Altitude, Humidity, WindSpeed, WindDirection,
};

/// A choice the Lab makes (Intent::param of a Choose).
enum class LabChoice : int { Scenario, Sport, Club, Bat, ImpactModel, Friction, Aero };

/// The scenario key a parameter is saved under and whose range bounds it.
struct LabParamInfo {
  LabParam param;
  std::string_view key;        ///< "swing.speed"
  std::uint8_t strikes;        ///< StrikeMask of the key (a club's and a bat's swing.speed differ)
  int element;                 ///< index in a list key (swing.impact_offset: toe 0, up 1), else 0
};
const LabParamInfo& lab_param_info(LabParam p);

class LabModel {
 public:
  /// Loads `scenario` with `overrides` ("key=value", as --set). Throws InputError like the CLI.
  LabModel(const Assets& assets, const std::string& scenario, std::vector<std::string> overrides = {});

  /// Applies edits, choices, Save and Swing (run the shot again) in time order.
  void update(const Intents& intents, double now);

  const Scenario& scenario() const { return scenario_; }  ///< as loaded (its doc, description, expectations)
  const ShotSpec& spec() const { return resolved_.spec; } ///< the edited spec of the shot shown
  const ResolvedShot& resolved() const { return resolved_; }
  const ShotResult& result() const { return result_; }
  /// Counts the shots run: a view restarts its replay when it changes.
  int shot_serial() const { return serial_; }
  /// The last refusal or "saved FILE"; empty after a good edit.
  const std::string& status() const { return status_; }

  /// The parameter's value in the shot shown (SI): the spec's, or what it defaults to (a
  /// club's own loft and strike height; the e the contact used).
  double value(LabParam p) const;
  /// Whether the shot's e is a constant set here in place of the equipment's speed-dependent
  /// COR law (the panel says so beside the slider).
  bool e_replaces_law() const { return e_replaces_law_; }
  /// The scenario as TOML with every edit, as Save writes it.
  std::string scenario_text() const;

 private:
  void apply(const Intent& in);
  bool run(const ShotSpec& spec);
  /// True when `spec` sets a constant e and its equipment's own e depends on speed.
  bool e_over_law(const ShotSpec& spec) const;
  void load(const std::string& scenario, const std::vector<std::string>& overrides);
  std::vector<std::string> edit_overrides() const;

  const Assets& assets_;
  Scenario scenario_;
  std::vector<std::string> start_overrides_;
  ResolvedShot resolved_;
  ShotResult result_;
  std::vector<LabParam> edited_;                         ///< in first-edit order, once each
  std::vector<std::pair<LabChoice, std::string>> chosen_; ///< the same for choices
  bool e_replaces_law_ = false;
  int serial_ = 0;
  std::string status_;
};

}  // namespace sweetspot
