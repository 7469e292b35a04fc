// A course's mesh for drawing: cut into ground tiles the renderer can leave out of view, and
// coarsened by vertex clustering for far away (game/render/mesh_data.hpp).
#include <cmath>
#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "game/render/mesh_data.hpp"

using namespace sweetspot;

namespace {

// A flat square of `size` m meshed every `step` m, green where x < size/2, rough beyond.
MeshData grid(float size, float step) {
  MeshData m;
  m.materials = {"green", "rough"};
  const int n = static_cast<int>(std::lround(size / step));
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n; ++i) {
      Vertex v;
      v.position = Eigen::Vector3f(i * step, 0.0f, k * step);
      v.color = i * step < 0.5f * size ? Eigen::Vector3f(0.3f, 0.7f, 0.3f) : Eigen::Vector3f(0.2f, 0.4f, 0.2f);
      m.vertices.push_back(v);
    }
  const auto at = [&](int i, int k) { return static_cast<std::uint32_t>(k * (n + 1) + i); };
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) {
      m.indices.insert(m.indices.end(), {at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k), at(i + 1, k + 1), at(i, k + 1)});
      const std::uint16_t mat = (i + 0.5f) * step < 0.5f * size ? 0 : 1;
      m.triangle_material.insert(m.triangle_material.end(), {mat, mat});
    }
  return m;
}

double area(const MeshData& m) {
  double a = 0.0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const Eigen::Vector3f p = m.vertices[m.indices[3 * t]].position, q = m.vertices[m.indices[3 * t + 1]].position,
                          r = m.vertices[m.indices[3 * t + 2]].position;
    a += 0.5 * static_cast<double>((q - p).cross(r - p).norm());
  }
  return a;
}

}  // namespace

TEST_CASE("tiles hold every triangle once, each in the tile of its centroid", "[mesh_lod]") {
  const MeshData m = grid(250.0f, 5.0f);
  const auto tiles = split_into_tiles(m, 100.0f);
  REQUIRE(tiles.size() == 9);  // 250 m in 100 m tiles: 3 x 3
  std::size_t triangles = 0;
  for (const MeshData& t : tiles) {
    triangles += t.triangle_count();
    CHECK(t.materials == m.materials);
    CHECK(t.triangle_material.size() == t.triangle_count());
    std::set<std::uint32_t> used(t.indices.begin(), t.indices.end());
    CHECK(used.size() == t.vertices.size());  // only the vertices its triangles use
    // One tile's centroids span less than a tile.
    float lo_x = 1e9f, hi_x = -1e9f, lo_z = 1e9f, hi_z = -1e9f;
    for (std::size_t i = 0; i < t.triangle_count(); ++i) {
      const Eigen::Vector3f c = (t.vertices[t.indices[3 * i]].position + t.vertices[t.indices[3 * i + 1]].position +
                                 t.vertices[t.indices[3 * i + 2]].position) / 3.0f;
      lo_x = std::min(lo_x, c.x()), hi_x = std::max(hi_x, c.x()), lo_z = std::min(lo_z, c.z()), hi_z = std::max(hi_z, c.z());
    }
    CHECK(hi_x - lo_x < 100.0f);
    CHECK(hi_z - lo_z < 100.0f);
  }
  CHECK(triangles == m.triangle_count());
  CHECK(area(tiles[0]) + area(tiles[4]) > 0.0);
  CHECK(split_into_tiles(MeshData{}, 100.0f).empty());
}

TEST_CASE("far away, vertex clustering keeps the shape and the colours with far fewer triangles", "[mesh_lod]") {
  const MeshData fine = grid(40.0f, 0.5f);  // a green's putting mesh: 12800 triangles
  const MeshData coarse = cluster_vertices(fine, 2.0f);
  CHECK(coarse.triangle_count() * 10 < fine.triangle_count());
  CHECK(coarse.triangle_count() > 0);
  // The surface is still there: its area within the cell's width along the edges.
  CHECK(area(coarse) == Approx(area(fine)).epsilon(0.12));
  // Colours never merge: both surfaces keep vertices of their own colour, nothing in between.
  std::set<float> reds;
  for (const Vertex& v : coarse.vertices) reds.insert(v.color.x());
  CHECK(reds == std::set<float>{0.2f, 0.3f});
  CHECK(coarse.triangle_material.size() == coarse.triangle_count());
  // No triangle is left with two corners in one cluster.
  for (std::size_t t = 0; t < coarse.triangle_count(); ++t) {
    CHECK(coarse.indices[3 * t] != coarse.indices[3 * t + 1]);
    CHECK(coarse.indices[3 * t + 1] != coarse.indices[3 * t + 2]);
    CHECK(coarse.indices[3 * t] != coarse.indices[3 * t + 2]);
  }
  // Cells finer than the mesh change nothing.
  CHECK(cluster_vertices(fine, 0.1f).triangle_count() == fine.triangle_count());
}

namespace {

// Two surfaces side by side as a world file gives them, each its own mesh with its own copy
// of the corners along their common edge: green for x <= size/2, rough beyond; gently rolling
// so the cells' means differ from the grid's points.
MeshData two_surfaces(float size, float step) {
  MeshData out;
  for (int s = 0; s < 2; ++s) {
    MeshData m;
    m.materials = {s == 0 ? "green" : "rough"};
    const int n = static_cast<int>(std::lround(0.5f * size / step));
    const float x0 = s * 0.5f * size;
    const int nz = static_cast<int>(std::lround(size / step));
    for (int k = 0; k <= nz; ++k)
      for (int i = 0; i <= n; ++i) {
        Vertex v;
        const float x = x0 + i * step, z = k * step;
        v.position = Eigen::Vector3f(x, 2.0f * std::sin(0.05f * x) * std::cos(0.07f * z), z);
        v.color = s == 0 ? Eigen::Vector3f(0.3f, 0.7f, 0.3f) : Eigen::Vector3f(0.2f, 0.4f, 0.2f);
        v.pattern = 1.0f + s;
        m.vertices.push_back(v);
      }
    const auto at = [&](int i, int k) { return static_cast<std::uint32_t>(k * (n + 1) + i); };
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < n; ++i) {
        m.indices.insert(m.indices.end(), {at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k), at(i + 1, k + 1), at(i, k + 1)});
        m.triangle_material.insert(m.triangle_material.end(), {0, 0});
      }
    out.append(m);
  }
  return out;
}

// Edges (by their corners' places) that only one triangle uses, farther than `margin` from
// the square's outer border: cracks inside the surface.
int inner_open_edges(const std::vector<MeshData>& pieces, float size, float margin) {
  using P = std::array<float, 3>;
  std::map<std::pair<P, P>, int> uses;
  const auto place = [](const Eigen::Vector3f& v) { return P{v.x(), v.y(), v.z()}; };
  for (const MeshData& m : pieces)
    for (std::size_t t = 0; t < m.triangle_count(); ++t)
      for (int e = 0; e < 3; ++e) {
        P a = place(m.vertices[m.indices[3 * t + static_cast<std::size_t>(e)]].position);
        P b = place(m.vertices[m.indices[3 * t + static_cast<std::size_t>((e + 1) % 3)]].position);
        if (b < a) std::swap(a, b);
        ++uses[{a, b}];
      }
  int open = 0;
  for (const auto& [edge, n] : uses) {
    const float x = 0.5f * (edge.first[0] + edge.second[0]), z = 0.5f * (edge.first[2] + edge.second[2]);
    const bool inner = x > margin && x < size - margin && z > margin && z < size - margin;
    if (n == 1 && inner) ++open;
  }
  return open;
}

}  // namespace

TEST_CASE("a world coarsened tile by tile keeps its surfaces and tiles joined", "[mesh_lod]") {
  // The map's grid of dark lines: each tile and each surface clustered on its own moved its
  // copy of a shared corner to its own mean, and the ground under the course showed through.
  constexpr float kSize = 250.0f, kCell = 12.0f;
  const MeshData whole = two_surfaces(kSize, 5.0f);
  REQUIRE(inner_open_edges({whole}, kSize, 1.0f) == 0);  // the surfaces' copies coincide: joined
  const auto tiles = split_into_tiles(whole, 100.0f);
  REQUIRE(tiles.size() == 9);
  const auto coarsen = [&](const SharedCells* shared) {
    std::vector<MeshData> out;
    for (const MeshData& t : tiles) out.push_back(cluster_vertices(t, kCell, shared));
    return out;
  };
  // Alone, the tiles and the surfaces part along their edges (what the test catches).
  CHECK(inner_open_edges(coarsen(nullptr), kSize, kCell) > 0);
  // Sharing the ground's places, nothing opens inside the square.
  const SharedCells shared = shared_cells(whole, kCell, [](const Vertex& v) { return v.pattern > 0.0f; });
  const auto joined = coarsen(&shared);
  CHECK(inner_open_edges(joined, kSize, kCell) == 0);
  // Still coarse, and both colours kept.
  std::size_t triangles = 0;
  std::set<float> reds;
  for (const MeshData& m : joined) {
    triangles += m.triangle_count();
    for (std::size_t t = 0; t < m.triangle_count(); ++t) reds.insert(m.vertices[m.indices[3 * t]].color.x());
  }
  CHECK(triangles * 4 < whole.triangle_count());  // (12 m cells over a 5 m mesh: ~5.8x at most)
  CHECK(reds == std::set<float>{0.2f, 0.3f});
}
