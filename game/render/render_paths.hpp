// Where the renderer finds its run-time files: GLSL sources and meshes.
#pragma once

#include <filesystem>
#include <string>

namespace sweetspot {

/// Directory of the GLSL sources: $SWEETSPOT_SHADERS, else <source dir>/shaders, else
/// shaders/ next to the executable's directory.
std::filesystem::path shader_dir();

/// Asset root for meshes and worlds: $SWEETSPOT_ASSETS, else <source dir>/assets, else
/// assets/ next to the executable's directory (the same rule as game/assets asset_root()).
std::filesystem::path render_asset_dir();

/// assets/meshes/<name>.obj for a mesh name ("golf_ball", "driver_head", ...), or `name`
/// itself when it names an existing file. Throws InputError listing the known meshes.
std::filesystem::path mesh_path(const std::string& name);

/// assets/worlds/<name>.obj for a world name ("golf_hole", "ballpark"), or `name` itself
/// when it is a path to an existing .obj. Throws InputError naming the path looked at.
std::filesystem::path world_mesh_path(const std::string& name);

}  // namespace sweetspot
