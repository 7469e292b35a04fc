// assets/aero_models.toml -> AeroModel (physics/aero.hpp): the named drag, lift and
// spin-decay models with their sources.
#pragma once

#include <filesystem>
#include <vector>

#include "game/core/sport.hpp"
#include "physics/aero.hpp"

namespace sweetspot {

/// Reads and validates every [[model]]; each model's sport must be one of `sports`. Throws
/// InputError naming file:line and key.
std::vector<AeroModel> load_aero_models(const std::filesystem::path& path, const SportCatalog& sports);

}  // namespace sweetspot
