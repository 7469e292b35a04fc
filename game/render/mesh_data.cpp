#include "game/render/mesh_data.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

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

std::vector<MeshData> split_into_tiles(const MeshData& mesh, float tile) {
  std::vector<MeshData> out;
  if (mesh.indices.empty() || !(tile > 0.0f)) return out;
  const auto centroid = [&](std::size_t t) {
    return (mesh.vertices[mesh.indices[3 * t]].position + mesh.vertices[mesh.indices[3 * t + 1]].position +
            mesh.vertices[mesh.indices[3 * t + 2]].position) / 3.0f;
  };
  float min_x = std::numeric_limits<float>::max(), min_z = std::numeric_limits<float>::max();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Eigen::Vector3f c = centroid(t);
    min_x = std::min(min_x, c.x());
    min_z = std::min(min_z, c.z());
  }
  // Each triangle's tile, then the tiles in order of their key.
  std::map<std::pair<long, long>, std::vector<std::uint32_t>> tiles;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Eigen::Vector3f c = centroid(t);
    const long i = std::isfinite(c.x()) ? static_cast<long>((c.x() - min_x) / tile) : 0;
    const long k = std::isfinite(c.z()) ? static_cast<long>((c.z() - min_z) / tile) : 0;
    tiles[{i, k}].push_back(static_cast<std::uint32_t>(t));
  }
  std::vector<std::uint32_t> remap(mesh.vertices.size(), std::numeric_limits<std::uint32_t>::max());
  for (const auto& [key, tris] : tiles) {
    MeshData m;
    m.materials = mesh.materials;
    std::vector<std::uint32_t> touched;
    for (std::uint32_t t : tris) {
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t v = mesh.indices[3 * t + static_cast<std::size_t>(c)];
        if (remap[v] == std::numeric_limits<std::uint32_t>::max()) {
          remap[v] = static_cast<std::uint32_t>(m.vertices.size());
          m.vertices.push_back(mesh.vertices[v]);
          touched.push_back(v);
        }
        m.indices.push_back(remap[v]);
      }
      if (!mesh.triangle_material.empty()) m.triangle_material.push_back(mesh.triangle_material[t]);
    }
    for (std::uint32_t v : touched) remap[v] = std::numeric_limits<std::uint32_t>::max();
    out.push_back(std::move(m));
  }
  return out;
}

MeshData cluster_vertices(const MeshData& mesh, float cell) {
  if (!(cell > 0.0f)) return mesh;
  // A vertex's cluster: its cell and its colour (quantised to 1/256).
  using Key = std::array<long, 6>;
  std::map<Key, std::uint32_t> ids;
  MeshData out;
  out.materials = mesh.materials;
  std::vector<std::uint32_t> cluster(mesh.vertices.size());
  std::vector<float> weight;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vertex& x = mesh.vertices[v];
    Key k{};
    for (int a = 0; a < 3; ++a) {
      k[static_cast<std::size_t>(a)] = static_cast<long>(std::floor(x.position[a] / cell));
      k[static_cast<std::size_t>(3 + a)] = std::lround(x.color[a] * 256.0f);
    }
    auto [it, fresh] = ids.try_emplace(k, static_cast<std::uint32_t>(out.vertices.size()));
    if (fresh) {
      Vertex first = x;
      first.position.setZero();
      first.normal.setZero();
      out.vertices.push_back(first);
      weight.push_back(0.0f);
    }
    Vertex& c = out.vertices[it->second];
    c.position += x.position;
    c.normal += x.normal;
    weight[it->second] += 1.0f;
    cluster[v] = it->second;
  }
  for (std::size_t c = 0; c < out.vertices.size(); ++c) {
    out.vertices[c].position /= weight[c];
    const float n = out.vertices[c].normal.norm();
    out.vertices[c].normal = n > 0.0f ? Eigen::Vector3f(out.vertices[c].normal / n) : Eigen::Vector3f::UnitY();
  }
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const std::uint32_t a = cluster[mesh.indices[3 * t]], b = cluster[mesh.indices[3 * t + 1]], c = cluster[mesh.indices[3 * t + 2]];
    if (a == b || b == c || a == c) continue;
    out.indices.insert(out.indices.end(), {a, b, c});
    if (!mesh.triangle_material.empty()) out.triangle_material.push_back(mesh.triangle_material[t]);
  }
  return out;
}

}  // namespace sweetspot
