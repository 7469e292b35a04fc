// The player's settings file (TOML): what the game remembers between runs on this machine,
// now the input latency the calibration measured. Found at $SWEETSPOT_SETTINGS, else
// $XDG_CONFIG_HOME/sweetspot/settings.toml, else ~/.config/sweetspot/settings.toml.
#pragma once

#include <filesystem>
#include <string>

#include "physics/range.hpp"

namespace sweetspot {

struct Settings {
  double input_latency = 0.0;  ///< s, subtracted from each meter click's time
  static constexpr Range kInputLatency{0.0, 0.25};
};

std::filesystem::path settings_path();
/// The settings; defaults when the file does not exist. InputError naming file:line and the
/// key (with its range) for a bad one.
Settings load_settings(const std::filesystem::path& path);
std::string settings_toml(const Settings& s);

}  // namespace sweetspot
