// The launch-monitor flags of `flight` and `render` (--sport, --ball-speed, --launch-angle,
// --spin, --spin-axis, --direction, --aero, --world, --set). They are one more way in to a
// shot: each flag becomes the scenario key it stands for, with the flag as its origin, and
// goes through the same schema, so a flag takes units exactly like a scenario key does and
// is refused with the key's one range.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "game/content/scenario.hpp"

namespace sweetspot::cli {

struct LaunchFlags {
  std::string sport = "golf";
  std::string ball_speed, launch_angle, spin;
  std::string spin_axis, direction;
  std::string aero, world;
  std::vector<std::string> sets;
};

/// Adds the flags to `sub`; `required` makes the three launch numbers mandatory.
void add_launch_flags(CLI::App& sub, LaunchFlags& f, bool required);

/// True when any of the three launch numbers was given.
bool has_launch_numbers(const LaunchFlags& f);

/// The launch-only scenario the flags describe (name "flight"); throws InputError naming
/// the flag, the key and its range. --set accepts ball.*, environment.*, aero.* and world.*.
Scenario launch_scenario(const Assets& assets, const LaunchFlags& f, const std::string& name);

}  // namespace sweetspot::cli
