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

CellKey cell_of(const Eigen::Vector3f& position, float cell) {
  return {static_cast<long>(std::floor(position.x() / cell)), static_cast<long>(std::floor(position.y() / cell)),
          static_cast<long>(std::floor(position.z() / cell))};
}

SharedCells shared_cells(const MeshData& whole, float cell, std::function<bool(const Vertex&)> shares) {
  SharedCells out;
  out.cell = cell;
  out.shares = std::move(shares);
  if (!(cell > 0.0f)) return out;
  std::map<CellKey, float> count;
  for (const Vertex& v : whole.vertices) {
    if (!out.shares(v)) continue;
    auto [it, fresh] = out.at.try_emplace(cell_of(v.position, cell), Eigen::Vector3f::Zero(), Eigen::Vector3f::Zero());
    it->second.first += v.position;
    it->second.second += v.normal;
    count[it->first] += 1.0f;
  }
  for (auto& [key, place] : out.at) {
    place.first /= count[key];
    const float n = place.second.norm();
    place.second = n > 0.0f ? Eigen::Vector3f(place.second / n) : Eigen::Vector3f::UnitY();
  }
  return out;
}

MeshData cluster_vertices(const MeshData& mesh, float cell, const SharedCells* shared) {
  if (!(cell > 0.0f)) return mesh;
  // A vertex's cluster: its cell and its colour (quantised to 1/256).
  using Key = std::array<long, 6>;
  std::map<Key, std::uint32_t> ids;
  MeshData out;
  out.materials = mesh.materials;
  std::vector<std::uint32_t> cluster(mesh.vertices.size());
  std::vector<float> weight;
  std::vector<const std::pair<Eigen::Vector3f, Eigen::Vector3f>*> anchor;  // per cluster: its shared place, if any
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vertex& x = mesh.vertices[v];
    const CellKey c = cell_of(x.position, cell);
    Key k{};
    for (std::size_t a = 0; a < 3; ++a) {
      k[a] = c[a];
      k[3 + a] = std::lround(x.color[static_cast<Eigen::Index>(a)] * 256.0f);
    }
    auto [it, fresh] = ids.try_emplace(k, static_cast<std::uint32_t>(out.vertices.size()));
    if (fresh) {
      Vertex first = x;
      first.position.setZero();
      first.normal.setZero();
      out.vertices.push_back(first);
      weight.push_back(0.0f);
      const std::pair<Eigen::Vector3f, Eigen::Vector3f>* place = nullptr;
      if (shared != nullptr && shared->cell == cell && shared->shares(x)) {
        const auto found = shared->at.find(c);
        if (found != shared->at.end()) place = &found->second;
      }
      anchor.push_back(place);
    }
    Vertex& cv = out.vertices[it->second];
    cv.position += x.position;
    cv.normal += x.normal;
    weight[it->second] += 1.0f;
    cluster[v] = it->second;
  }
  for (std::size_t c = 0; c < out.vertices.size(); ++c) {
    if (anchor[c] != nullptr) {
      out.vertices[c].position = anchor[c]->first;
      out.vertices[c].normal = anchor[c]->second;
      continue;
    }
    out.vertices[c].position /= weight[c];
    const float n = out.vertices[c].normal.norm();
    out.vertices[c].normal = n > 0.0f ? Eigen::Vector3f(out.vertices[c].normal / n) : Eigen::Vector3f::UnitY();
  }
  // Surfaces that share a place keep a vertex each (their colours): a triangle with two
  // corners at one place has no area left either.
  const auto same = [&](std::uint32_t a, std::uint32_t b) { return a == b || out.vertices[a].position == out.vertices[b].position; };
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const std::uint32_t a = cluster[mesh.indices[3 * t]], b = cluster[mesh.indices[3 * t + 1]], c = cluster[mesh.indices[3 * t + 2]];
    if (same(a, b) || same(b, c) || same(a, c)) continue;
    out.indices.insert(out.indices.end(), {a, b, c});
    if (!mesh.triangle_material.empty()) out.triangle_material.push_back(mesh.triangle_material[t]);
  }
  return out;
}

}  // namespace sweetspot
