// CPU-side triangle meshes shared by the importer, the overlay builders and the GPU upload.
// Plain data, float precision (what the GPU gets); positions in metres, world or mesh frame.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sweetspot {

/// One vertex as uploaded: 40 bytes, attribute slots 0..3 of every shader.
struct Vertex {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();  ///< m
  Eigen::Vector3f normal = Eigen::Vector3f::UnitY();   ///< unit; ignored by unlit shaders
  Eigen::Vector3f color = Eigen::Vector3f::Ones();     ///< linear-ish RGB 0..1
  float pattern = 0.0f;  ///< lit meshes: a surface_look code (mesh_import.hpp); ribbons: the across-ribbon coordinate
};

struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;             ///< triangles, 3 per face
  std::vector<std::string> materials;             ///< material names (from the .mtl)
  std::vector<std::uint16_t> triangle_material;   ///< per triangle, index into materials; may be empty

  std::size_t triangle_count() const { return indices.size() / 3; }
  /// Material name of triangle `i`, "" when the mesh has none.
  const std::string& material_of(std::size_t i) const;
  /// Appends `other` (indices shifted, materials merged by name).
  void append(const MeshData& other);
};

/// `mesh` cut into square tiles of `tile` m in the ground plane (x, z), each triangle in the
/// tile of its centroid, each tile with only the vertices its triangles use: a course's one
/// mesh as pieces the renderer can leave out when they are out of view. Empty tiles are not
/// returned; together the tiles hold every triangle once, in order within a tile.
std::vector<MeshData> split_into_tiles(const MeshData& mesh, float tile);

/// A `cell` m cube of space, by its integer coordinates.
using CellKey = std::array<long, 3>;
CellKey cell_of(const Eigen::Vector3f& position, float cell);

/// Where the surfaces that meet in a cell put their shared corners when a mesh is coarsened
/// piece by piece: the mean position and normal, per cell, of the vertices of the whole mesh
/// that `shares` picks (a course's ground: every surface that touches its neighbours). The
/// tiles of one world and the surfaces of one tile (each its own copy of the corners along
/// its edge) then move those corners to one place, and no crack opens between them.
struct SharedCells {
  float cell = 0.0f;  ///< m
  std::function<bool(const Vertex&)> shares;
  std::map<CellKey, std::pair<Eigen::Vector3f, Eigen::Vector3f>> at;  ///< position, unit normal
};
SharedCells shared_cells(const MeshData& whole, float cell, std::function<bool(const Vertex&)> shares);

/// A coarser `mesh` for far away (vertex clustering: J. Rossignac & P. Borrel, "Multi-
/// resolution 3D approximations for rendering complex scenes", 1993): the vertices of one
/// `cell` m cube and one colour become one, at their mean, and triangles left with two
/// corners in one place go. Colours never merge, so a green keeps its edge against the
/// rough, to within a cell. With `shared` (made with the same cell), a vertex it picks goes
/// to its cell's shared place instead of its own colour's mean.
MeshData cluster_vertices(const MeshData& mesh, float cell, const SharedCells* shared = nullptr);

}  // namespace sweetspot
