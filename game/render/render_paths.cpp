#include "game/render/render_paths.hpp"

#include <unistd.h>

#include <cstdlib>
#include <system_error>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

std::filesystem::path executable_dir() {
  std::error_code ec;
  auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::current_path() : exe.parent_path();
}

std::filesystem::path resolve(const char* env_name, const char* sub) {
  if (const char* env = std::getenv(env_name); env != nullptr && *env != '\0') return env;
#ifdef SWEETSPOT_SOURCE_DIR
  const std::filesystem::path src = std::filesystem::path(SWEETSPOT_SOURCE_DIR) / sub;
  if (std::filesystem::is_directory(src)) return src;
#endif
  // Installed layout: bin/sweetspot next to share-like folders, or the build tree.
  for (auto dir = executable_dir(); !dir.empty(); dir = dir.parent_path()) {
    if (std::filesystem::is_directory(dir / sub)) return dir / sub;
    if (dir == dir.parent_path()) break;
  }
  return std::filesystem::path(sub);
}

}  // namespace

std::filesystem::path shader_dir() { return resolve("SWEETSPOT_SHADERS", "shaders"); }

std::filesystem::path mesh_path(const std::filesystem::path& assets_root, const std::string& name) {
  if (name.find('/') != std::string::npos || name.ends_with(".obj")) {
    if (std::filesystem::is_regular_file(name)) return name;
    throw InputError("mesh file '" + name + "' does not exist");
  }
  auto p = assets_root / "meshes" / (name + ".obj");
  if (std::filesystem::is_regular_file(p)) return p;
  throw InputError("mesh '" + name + "' not found at " + p.string());
}

}  // namespace sweetspot
