// Equipment files: assets/equipment/{balls,clubs,bats}.toml -> BallSpec, ClubSpec, BatSpec.
// Every value carries its unit in the file ("204g", "9.8deg"); errors name the file, line,
// key and the allowed range.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "physics/equipment.hpp"

namespace sweetspot {

struct EquipmentCatalog {
  std::vector<BallSpec> balls;
  std::vector<ClubSpec> clubs;
  std::vector<BatSpec> bats;
  /// Look-ups by name; throw InputError listing the allowed names.
  const BallSpec& ball(std::string_view name) const;
  const ClubSpec& club(std::string_view name) const;
  const BatSpec& bat(std::string_view name) const;
};

/// Reads balls.toml, clubs.toml and bats.toml from `dir`. Throws InputError
/// ("clubs.toml:42: club 'driver': head_mass must be in [50, 1000] g, got 5000 g").
EquipmentCatalog load_equipment(const std::filesystem::path& dir);

/// The built-in equipment, loaded once from asset_root()/equipment (game/assets/assets.hpp).
const EquipmentCatalog& default_equipment();

}  // namespace sweetspot
