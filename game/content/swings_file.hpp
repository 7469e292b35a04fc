// A swings file: scripted three-click meter inputs for `sweetspot round --swings FILE`, one
// [[stroke]] per stroke in playing order (DESIGN §9):
//   [[stroke]]
//   club = "driver"      # optional: the club the game suggests for the distance
//   power = "100%"       # (0, 110] %
//   accuracy = "0ms"     # the third click's timing error, + late; [-200, 200] ms
//   aim = "0deg"         # + right of the line to the cup; [-90, 90] deg
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "game/core/stroke_input.hpp"

namespace sweetspot {

struct ScriptedStroke {
  std::optional<std::string> club;  ///< none: the suggested club
  MeterInput meter;
  double aim = 0.0;                 ///< rad
  std::string where;                ///< "file:line" for messages
};

/// Throws InputError naming file:line, the key and its allowed range.
std::vector<ScriptedStroke> load_swings(const std::filesystem::path& path);

}  // namespace sweetspot
