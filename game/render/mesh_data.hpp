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

}  // namespace sweetspot
