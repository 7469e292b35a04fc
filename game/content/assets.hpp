// The Assets context (DESIGN §1): equipment, sports, aero models, surface materials, worlds
// and the built-in scenario catalogue, each read from the assets folder the first time it
// is asked for and kept for the life of the context. It is made once (by main, a test, the
// bench) and passed down by reference: there are no process-wide caches. Every accessor is
// safe to call from many threads at once; what it returns is immutable.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/equipment_file.hpp"
#include "game/content/world_asset.hpp"
#include "game/core/sport.hpp"
#include "physics/aero.hpp"
#include "physics/ground.hpp"

namespace sweetspot {

/// A built-in scenario: assets/scenarios/<sport>/<name>.toml, addressed as "golf/driver".
struct BuiltinScenario {
  std::string name;                ///< "golf/driver"
  std::filesystem::path path;      ///< the .toml file
  std::string sport;               ///< its folder: "golf", "baseball"
};

class Assets {
 public:
  /// Reads nothing yet. `root` is the assets folder (default_root() for the shipped one).
  explicit Assets(std::filesystem::path root = default_root());
  ~Assets();
  Assets(const Assets&) = delete;
  Assets& operator=(const Assets&) = delete;

  /// $SWEETSPOT_ASSETS, else <source dir>/assets, else assets/ in the executable's
  /// directory or one of its parents.
  static std::filesystem::path default_root();
  const std::filesystem::path& root() const;

  /// Each loads its files on first use and throws InputError (naming file:line) when they
  /// are bad; later calls return the same object.
  const EquipmentCatalog& equipment() const;
  const SportCatalog& sports() const;
  const SportProfile& sport(std::string_view name) const { return sports().get(name); }
  const std::vector<AeroModel>& aero_models() const;
  /// The model named `name`; throws InputError listing the names.
  const AeroModel& aero(std::string_view name) const;
  const std::vector<SurfaceMaterial>& materials() const;
  /// The world by name or path, loaded and built once; nullptr for kFlatWorld ("none").
  /// Its queries only read, so any number of threads may fly on it at once.
  const WorldAsset* world(const std::string& name_or_path) const;
  /// Every built-in scenario by file name, sports in assets/sports.toml order, names sorted.
  /// Listing reads no scenario file, so one broken file breaks only its own name.
  const std::vector<BuiltinScenario>& scenarios() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sweetspot
