#include "game/render/mesh_data.hpp"

#include <algorithm>

namespace sweetspot {

const std::string& MeshData::material_of(std::size_t i) const {
  static const std::string none;
  if (i >= triangle_material.size() || triangle_material[i] >= materials.size()) return none;
  return materials[triangle_material[i]];
}

void MeshData::append(const MeshData& other) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  const std::size_t first_tri = triangle_count();
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (auto i : other.indices) indices.push_back(base + i);
  if (other.triangle_material.empty()) return;
  triangle_material.resize(first_tri, 0);
  for (std::size_t t = 0; t < other.triangle_count(); ++t) {
    const std::string& name = other.material_of(t);
    auto it = std::find(materials.begin(), materials.end(), name);
    if (it == materials.end()) {
      materials.push_back(name);
      it = materials.end() - 1;
    }
    triangle_material.push_back(static_cast<std::uint16_t>(it - materials.begin()));
  }
}

}  // namespace sweetspot
