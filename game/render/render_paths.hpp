// Where the renderer finds its run-time files: GLSL sources and meshes.
#pragma once

#include <filesystem>
#include <string>

namespace sweetspot {

/// Directory of the GLSL sources: $SWEETSPOT_SHADERS, else <source dir>/shaders, else
/// shaders/ next to the executable's directory.
std::filesystem::path shader_dir();

/// <assets root>/meshes/<name>.obj for a mesh name ("golf_ball", "driver_head", ...), or
/// `name` itself when it names an existing file. Throws InputError naming the path.
std::filesystem::path mesh_path(const std::filesystem::path& assets_root, const std::string& name);

}  // namespace sweetspot
