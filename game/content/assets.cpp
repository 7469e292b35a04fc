#include "game/content/assets.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <mutex>
#include <optional>

#include "game/content/aero_file.hpp"
#include "game/content/sport_file.hpp"
#include "game/content/toml_file.hpp"
#include "game/core/shot_spec.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace fs = std::filesystem;

struct Assets::Impl {
  fs::path root;
  mutable std::mutex mutex;  // guards the lazily filled members below
  mutable std::optional<EquipmentCatalog> equipment;
  mutable std::optional<SportCatalog> sports;
  mutable std::optional<std::vector<AeroModel>> aero;
  mutable std::optional<std::vector<SurfaceMaterial>> materials;
  mutable std::map<std::string, std::unique_ptr<const WorldAsset>> worlds;
  mutable std::optional<std::vector<BuiltinScenario>> scenarios;

  // Loads `slot` once under the lock. A failed load leaves it empty, so the next call
  // reports the same error instead of a half-built object.
  template <class T, class F>
  const T& once(std::optional<T>& slot, F&& load) const {
    std::lock_guard<std::mutex> lock(mutex);
    if (!slot) slot.emplace(load());
    return *slot;
  }
};

Assets::Assets(fs::path root) : impl_(std::make_unique<Impl>()) { impl_->root = std::move(root); }
Assets::~Assets() = default;

fs::path Assets::default_root() {
  if (const char* env = std::getenv("SWEETSPOT_ASSETS"); env != nullptr) {
    // Set but empty is a mistake (an unset variable in a script), not "the default".
    if (*env == '\0') throw InputError("SWEETSPOT_ASSETS is set but empty: unset it, or name the assets directory");
    return env;
  }
#ifdef SWEETSPOT_SOURCE_DIR
  const fs::path src = fs::path(SWEETSPOT_SOURCE_DIR) / "assets";
  if (std::error_code e; fs::is_directory(src, e)) return src;
#endif
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  for (fs::path dir = ec ? fs::current_path() : exe.parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (std::error_code e; fs::is_directory(dir / "assets", e)) return dir / "assets";
    if (dir == dir.parent_path()) break;
  }
  return "assets";
}

const fs::path& Assets::root() const { return impl_->root; }

const EquipmentCatalog& Assets::equipment() const {
  return impl_->once(impl_->equipment, [&] { return load_equipment(impl_->root / "equipment"); });
}

namespace {

// A name sports.toml gives, refused at the line that gives it.
[[noreturn]] void refuse(const SportProfile& p, const std::string& key, const std::string& message) {
  const auto it = p.source.find(key);
  throw InputError((it != p.source.end() ? it->second + ": " : "sports.toml: ") + key + ": " + message);
}

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// What each sport names must exist among the other assets, and be of that sport: a ball and
// an impactor of the equipment, a world file and a built-in scenario.
void check_sport_names(const SportCatalog& catalog, const EquipmentCatalog& eq, const fs::path& root) {
  for (const SportProfile& p : catalog.sports) {
    std::vector<std::string> names;
    for (const BallSpec& b : eq.balls) names.push_back(b.name);
    if (std::find(names.begin(), names.end(), p.ball) == names.end())
      refuse(p, "ball", "unknown ball '" + p.ball + "' (allowed: " + listed(names) + ")");
    names.clear();
    if (p.impactor == ImpactorKind::Club)
      for (const ClubSpec& c : eq.clubs) names.push_back(c.name);
    else
      for (const BatSpec& b : eq.bats) names.push_back(b.name);
    if (std::find(names.begin(), names.end(), p.default_impactor) == names.end())
      refuse(p, "default_impactor",
             "unknown " + std::string(to_string(p.impactor)) + " '" + p.default_impactor + "' (allowed: " + listed(names) + ")");
    if (p.default_world != kFlatWorld) {
      const fs::path world = root / "worlds" / (p.default_world + ".toml");
      std::error_code ec;
      if (p.default_world.find('/') != std::string::npos || !fs::is_regular_file(world, ec))
        refuse(p, "default_world", "no world '" + p.default_world + "' in assets/worlds (or none, flat ground)");
      const TomlFile w = TomlFile::read(world, "world");
      const toml::node* sport = w.root().get("sport");
      const std::string its = sport != nullptr ? w.text(*sport, "sport") : "";
      if (its != p.name) refuse(p, "default_world", "world '" + p.default_world + "' is a " + its + " world, not " + p.name);
    }
    std::error_code ec;
    if (!p.default_scenario.starts_with(p.name + "/") || p.default_scenario.find("..") != std::string::npos ||
        !fs::is_regular_file(root / "scenarios" / (p.default_scenario + ".toml"), ec))
      refuse(p, "default_scenario",
             "no built-in scenario '" + p.default_scenario + "' (allowed: " + p.name + "/NAME of assets/scenarios/" +
                 p.name + ")");
  }
}

}  // namespace

const SportCatalog& Assets::sports() const {
  const EquipmentCatalog& eq = equipment();
  return impl_->once(impl_->sports, [&] {
    SportCatalog c = load_sports(impl_->root / "sports.toml");
    check_sport_names(c, eq, impl_->root);
    return c;
  });
}

const std::vector<AeroModel>& Assets::aero_models() const {
  const SportCatalog& catalog = sports();
  return impl_->once(impl_->aero, [&] {
    std::vector<AeroModel> models = load_aero_models(impl_->root / "aero_models.toml", catalog);
    for (const SportProfile& p : catalog.sports) {
      std::vector<std::string> names;
      for (const AeroModel& m : models)
        if (m.sport == p.name) names.push_back(m.name);
      if (std::find(names.begin(), names.end(), p.default_aero) == names.end())
        refuse(p, "default_aero", "no " + p.name + " aero model '" + p.default_aero + "' in aero_models.toml (allowed: " +
                                      listed(names) + ")");
    }
    return models;
  });
}

const AeroModel& Assets::aero(std::string_view name) const {
  const auto& models = aero_models();
  for (const AeroModel& m : models)
    if (m.name == name) return m;
  std::string names;
  for (const AeroModel& m : models) names += (names.empty() ? "" : ", ") + m.name;
  throw InputError("unknown aero model '" + std::string(name) + "' (allowed: " + names + ")");
}

const std::vector<SurfaceMaterial>& Assets::materials() const {
  return impl_->once(impl_->materials, [&] { return load_materials(impl_->root / "materials.toml"); });
}

const WorldAsset* Assets::world(const std::string& name_or_path) const {
  if (name_or_path == kFlatWorld) return nullptr;
  const auto& mats = materials();
  const SportCatalog& catalog = sports();
  std::lock_guard<std::mutex> lock(impl_->mutex);
  auto it = impl_->worlds.find(name_or_path);
  if (it != impl_->worlds.end()) return it->second.get();
  // Reading the OBJ (~100 ms for a hole) and building Bullet's trees (~30 ms) happen once.
  auto asset = std::make_unique<const WorldAsset>(load_world_asset(impl_->root, name_or_path, mats, &catalog));
  const WorldAsset* out = asset.get();
  impl_->worlds.emplace(name_or_path, std::move(asset));
  return out;
}

const std::vector<BuiltinScenario>& Assets::scenarios() const {
  const SportCatalog& catalog = sports();
  return impl_->once(impl_->scenarios, [&] {
    std::vector<BuiltinScenario> out;
    const fs::path dir = impl_->root / "scenarios";
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
      throw InputError("built-in scenario directory '" + dir.string() +
                       "' not found (set SWEETSPOT_ASSETS to the assets directory)");
    for (const SportProfile& sport : catalog.sports) {
      std::vector<BuiltinScenario> these;
      for (const auto& entry : fs::directory_iterator(dir / sport.name, ec)) {
        if (entry.path().extension() != ".toml") continue;
        these.push_back({sport.name + "/" + entry.path().stem().string(), entry.path(), sport.name});
      }
      std::sort(these.begin(), these.end(),
                [](const BuiltinScenario& a, const BuiltinScenario& b) { return a.name < b.name; });
      out.insert(out.end(), these.begin(), these.end());
    }
    return out;
  });
}

}  // namespace sweetspot
