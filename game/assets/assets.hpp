// Asset files: where they live, and loading a world (assimp OBJ + MTL names, TOML metadata,
// assets/materials.toml) into the plain WorldDescription that physics/world builds from.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "physics/ground.hpp"
#include "physics/world.hpp"

namespace sweetspot {

/// $SWEETSPOT_ASSETS, else <source dir>/assets, else assets/ in the executable's directory
/// or one of its parents.
std::filesystem::path asset_root();

/// Surface materials from a materials.toml (default: asset_root()/materials.toml). Throws
/// InputError naming the file, line and key with the allowed values.
std::vector<SurfaceMaterial> load_materials(const std::filesystem::path& path);

/// Limits of a world mesh: the OBJ file size (bytes) and how far any vertex may lie from the
/// world origin in each axis (m). A course or ballpark is well inside both.
inline constexpr std::uintmax_t kMaxWorldMeshBytes = std::uintmax_t{256} << 20;
inline constexpr double kMaxWorldExtent = 100000.0;

/// A world by name ("golf_hole", "ballpark": asset_root()/worlds/NAME.toml) or by path to
/// its .toml (or a bare .obj: bounds are the mesh box and the origin, 10 m wider, 400 m
/// higher). Rejects non-finite vertices
/// and unknown material names (InputError naming file and mesh); drops zero-area triangles
/// and says so in WorldDescription::notes.
WorldDescription load_world(const std::string& name_or_path);

/// "golf_hole" for golf, "ballpark" for baseball; throws InputError otherwise.
std::string default_world_name(std::string_view sport);

/// Names accepted by load_world() (the .toml files in asset_root()/worlds), sorted.
std::vector<std::string> world_names();

}  // namespace sweetspot
