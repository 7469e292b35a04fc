// A world loaded once into a WorldAsset: the physics collision world (Bullet, built from
// the assimp-loaded mesh) plus what the game and the renderer need of it (tee, pin, fence
// line, material colours come from the mesh's material names). The renderer draws the
// world's own triangles and asks the physics world for ground heights; nothing re-imports
// the mesh (DESIGN §1, one world asset).
//
// Files: assets/worlds/NAME.toml (metadata, every value with its unit) naming NAME.obj (+ its
// .mtl, whose material names are the surfaces of assets/materials.toml).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/tree_crowns.hpp"
#include "physics/ground.hpp"
#include "physics/world.hpp"

namespace sweetspot {
struct SportCatalog;
}

namespace sweetspot {

/// Surface materials from a materials.toml. Throws InputError naming the file, line and
/// key with the allowed values.
std::vector<SurfaceMaterial> load_materials(const std::filesystem::path& path);

/// Limits of a world mesh: the OBJ (and each material library) size in bytes, and how far
/// any vertex may lie from the world origin in each axis (m). A course or ballpark is well
/// inside both.
inline constexpr std::uintmax_t kMaxWorldMeshBytes = std::uintmax_t{256} << 20;
inline constexpr double kMaxWorldExtent = 100000.0;

struct WorldAsset {
  std::string name;                   ///< "golf_hole", "ballpark", or the file stem
  std::string sport;                  ///< "golf", "baseball", or "" (a bare .obj)
  std::filesystem::path source;       ///< the .toml (or .obj) it came from
  std::unique_ptr<const World> world; ///< collision world; its description() holds every mesh, decorations too
  std::optional<Vec3> pin;            ///< golf: the cup centre on the green surface (m)
  double fence_height = 0.0;          ///< baseball: m above the field (10 ft = 3.048), 0 = none
  static constexpr Range kFenceHeight{0.0, 30.0};  ///< Fenway's Green Monster is 11.3 m
  /// baseball: foot of the outfield fence from the left-field pole to the right-field pole
  /// (xz used; y = the origin's). With home plate it closes fair territory inside the fence.
  std::vector<Vec3> fence_line;
  std::vector<TreeCrown> trees;       ///< its trees' crowns (tree_crowns), read once at load

  const WorldDescription& description() const { return world->description(); }
};

/// A world by name ("golf_hole", "ballpark": <root>/worlds/NAME.toml) or by path to its
/// .toml (or a bare .obj: bounds are the mesh box and the origin, 10 m wider, 400 m
/// higher), with the surfaces of `materials`. Refuses non-regular or oversized files,
/// non-finite or far-flung vertices, dangling indices and unknown material names
/// (InputError naming file and mesh); drops zero-area triangles and says so in the
/// description's notes.
/// Whether a world name is a path (it has a '/' or ends in .toml or .obj) rather than a
/// name of <root>/worlds.
bool is_world_path(const std::string& name_or_path);

/// Where a world's ground lies, for a refusal of a spot off it: "its ground spans x -30 to
/// 450 m and z -70 to 70 m" (coordinates less `relative_to`: a tee or ball position is
/// given from the world's origin, a course's spots in world coordinates).
std::string ground_extent_text(const WorldDescription& d, const Vec3& relative_to = Vec3::Zero());

/// `sports`, when given, is what the file's `sport` key may name.
WorldAsset load_world_asset(const std::filesystem::path& root, const std::string& name_or_path,
                            const std::vector<SurfaceMaterial>& materials, const SportCatalog* sports = nullptr);

/// Names of the worlds in <root>/worlds (the .toml files), sorted.
std::vector<std::string> world_names(const std::filesystem::path& root);

}  // namespace sweetspot
