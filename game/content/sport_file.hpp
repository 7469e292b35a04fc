// assets/sports.toml -> SportCatalog (game/core/sport.hpp).
#pragma once

#include <filesystem>

#include "game/core/sport.hpp"

namespace sweetspot {

/// Reads every [[sport]]. Throws InputError naming file:line and key.
SportCatalog load_sports(const std::filesystem::path& path);

}  // namespace sweetspot
