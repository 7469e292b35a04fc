// CPU-side triangle meshes shared by the importer, the overlay builders and the GPU upload.
// Plain data, float precision (what the GPU gets); positions in metres, world or mesh frame.
#pragma once

#include <cstdint>
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

/// A coarser `mesh` for far away (vertex clustering: J. Rossignac & P. Borrel, "Multi-
/// resolution 3D approximations for rendering complex scenes", 1993): the vertices of one
/// `cell` m cube and one colour become their mean, and triangles left with two corners in
/// one cluster go. Colours never merge, so a green keeps its edge against the rough, to
/// within a cell.
MeshData cluster_vertices(const MeshData& mesh, float cell);

}  // namespace sweetspot
