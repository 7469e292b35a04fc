#include "game/content/tree_crowns.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace sweetspot {
namespace {

// Union-find over a mesh's vertices: the pieces its triangles join.
struct Pieces {
  std::vector<std::uint32_t> parent;
  explicit Pieces(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t root(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[root(a)] = root(b); }
};

}  // namespace

std::vector<TreeCrown> tree_crowns(const WorldDescription& world) {
  std::vector<TreeCrown> out;
  for (const WorldMesh& m : world.meshes) {
    if (m.material < 0 || static_cast<std::size_t>(m.material) >= world.materials.size()) continue;
    const SurfaceMaterial& mat = world.materials[static_cast<std::size_t>(m.material)];
    if (mat.kind != SurfaceKind::Tree || mat.name == "trunk") continue;
    Pieces pieces(m.vertices.size());
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
      pieces.join(m.indices[i], m.indices[i + 1]);
      pieces.join(m.indices[i], m.indices[i + 2]);
    }
    // Each piece's footprint box and top, then its centre and the spread about it.
    struct Box {
      double x0 = HUGE_VAL, x1 = -HUGE_VAL, z0 = HUGE_VAL, z1 = -HUGE_VAL, top = -HUGE_VAL;
      std::size_t crown = 0;
      bool used = false;
    };
    std::vector<Box> boxes(m.vertices.size());
    for (const std::uint32_t i : m.indices) {
      Box& b = boxes[pieces.root(i)];
      const Vec3& v = m.vertices[i];
      b.x0 = std::min(b.x0, v.x());
      b.x1 = std::max(b.x1, v.x());
      b.z0 = std::min(b.z0, v.z());
      b.z1 = std::max(b.z1, v.z());
      b.top = std::max(b.top, v.y());
      b.used = true;
    }
    for (Box& b : boxes) {
      if (!b.used) continue;
      b.crown = out.size();
      out.push_back(TreeCrown{Vec3(0.5 * (b.x0 + b.x1), b.top, 0.5 * (b.z0 + b.z1)), 0.0});
    }
    for (const std::uint32_t i : m.indices) {
      TreeCrown& c = out[boxes[pieces.root(i)].crown];
      const Vec3& v = m.vertices[i];
      c.radius = std::max(c.radius, std::hypot(v.x() - c.centre.x(), v.z() - c.centre.z()));
    }
  }
  return out;
}

}  // namespace sweetspot
