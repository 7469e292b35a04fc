// Meshes from files through assimp (OBJ + MTL; anything assimp reads). Each material's
// colour comes from the render palette when its name is a known surface or equipment part
// (so fairway, rough, sand... read the same in every world file), else from the file's
// diffuse colour.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "game/render/mesh_data.hpp"
#include "physics/world.hpp"

namespace sweetspot {

/// How lit.frag textures a surface procedurally (the vertex `pattern`, as a float): the
/// detail that makes a flat colour read as turf, sand, water or dirt.
namespace surface_look {
inline constexpr float kPlain = 0.0f;      ///< equipment, walls: the colour only
inline constexpr float kMown = 1.0f;       ///< tee, fairway, green, infield grass: mowing stripes, fine blade noise
inline constexpr float kLongGrass = 2.0f;  ///< rough, out of bounds: patchy, no stripes
inline constexpr float kSand = 3.0f;       ///< bunkers: fine grain and wind ripples
inline constexpr float kWater = 4.0f;      ///< ponds: the sky reflected at grazing angles, sun glints
inline constexpr float kDirt = 5.0f;       ///< infield skin, warning track: clods and raked grain
inline constexpr float kCloth = 6.0f;      ///< a flag: thin cloth, bright from any side
}  // namespace surface_look

struct PaletteEntry {
  Eigen::Vector3f color;  ///< RGB 0..1 as lit under the noon sun
  float pattern;          ///< a surface_look code
};

/// The palette colour for a material name (tee, fairway, rough, sand, green, water, dirt,
/// grass, warning_track, wall, flag, ball, ...), or nothing for unknown names.
std::optional<PaletteEntry> palette_color(std::string_view material);

/// Loads every mesh of the file into one MeshData (triangulated, normals generated where the
/// file has none, node transforms applied), through the bounded reader of
/// game/content/mesh_file.hpp. Throws InputError naming the file when it cannot be read or
/// holds no triangles.
MeshData import_mesh(const std::filesystem::path& path);

/// A world's own triangles (game/content WorldAsset: the meshes physics collides with, and
/// its decorations) as one MeshData, coloured by surface name, with smooth vertex normals.
MeshData world_mesh_data(const WorldDescription& world);

}  // namespace sweetspot
