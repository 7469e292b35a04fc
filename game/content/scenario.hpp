// A scenario: a TOML file (or a built-in name) with `--set` overrides, checked against the
// schema into a ShotSpec, resolved against the Assets context, plus its expectations for
// `regress`. Scenario files are one of the ways in to a shot (DESIGN §1); the result is
// the same ShotSpec the flags, the UI and the game modes build.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/scenario_doc.hpp"
#include "game/content/assets.hpp"
#include "game/content/resolve.hpp"
#include "game/core/shot_spec.hpp"

namespace sweetspot {

/// One `expect.NAME` entry with its tolerance, SI.
struct Expectation {
  std::string name;               ///< "ball_speed", "carry", ...
  std::vector<double> value;      ///< one element for scalars
  double tolerance = 0.0;
};

struct Scenario {
  std::string name;               ///< built-in name ("golf/driver") or the path given
  std::string description;
  ShotSpec spec;                  ///< what to simulate
  ResolvedShot resolved;          ///< spec resolved against the Assets it was loaded with
  std::vector<Expectation> expectations;
  ScenarioDoc doc;                ///< the document it came from (origins, `regress --update`, Save)
};

/// A SCENARIO argument -> the file to read. Anything ending in ".toml" or naming an
/// existing file is a path; otherwise a built-in name. Unknown name -> InputError listing
/// the built-in names.
std::filesystem::path resolve_scenario(const Assets& assets, std::string_view name_or_path);

/// Loads a built-in name or .toml path, applies `overrides` ("key=value", as `--set`),
/// validates everything and resolves equipment, aero model and world. Throws InputError
/// naming file:line / flag / key and the allowed range.
Scenario load_scenario(const Assets& assets, std::string_view name_or_path, const std::vector<std::string>& overrides);
/// The same from an already-parsed document (UI edits, flags, tests); `name` labels it.
Scenario scenario_from_doc(const Assets& assets, const ScenarioDoc& doc, std::string name);

/// Where the keys a message names came from, for a refusal found only when the shot runs
/// (a ball the flight model cannot carry): " (ball.mass from --set ball.mass=10g; ball.radius
/// from case.toml:4)", or "" when the message names none of the document's keys.
std::string origins_named_in(const ScenarioDoc& doc, const std::string& message);

/// The description line of a built-in scenario file, or "(unreadable: why)".
std::string scenario_description(const BuiltinScenario& s);

}  // namespace sweetspot
