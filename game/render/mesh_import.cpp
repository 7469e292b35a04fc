#include "game/render/mesh_import.hpp"

#include <assimp/postprocess.h>

#include <algorithm>
#include <array>
#include <string>

#include "game/content/mesh_file.hpp"
#include "game/render/render_error.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

/// Equipment and decoration meshes are small; 64 MiB is far beyond any of them.
constexpr std::uintmax_t kMaxMeshBytes = std::uintmax_t{64} << 20;

struct Named {
  std::string_view name;
  PaletteEntry entry;
};

// Colours chosen to read at a glance from far away: fairway a mid green with stripes, rough
// darker and bluer, green the lightest and stripy, sand pale, dirt and warning track warm
// browns, the outfield wall a dark green as in most ballparks, tree crowns darker than rough.
const std::array<Named, 23>& palette() {
  static const std::array<Named, 23> p{{
      {"tee", {{0.40f, 0.66f, 0.27f}, surface_look::kMown}},
      {"fairway", {{0.36f, 0.64f, 0.23f}, surface_look::kMown}},
      {"rough", {{0.18f, 0.40f, 0.15f}, surface_look::kLongGrass}},
      {"sand", {{0.90f, 0.82f, 0.60f}, surface_look::kSand}},
      {"green", {{0.46f, 0.80f, 0.34f}, surface_look::kMown}},
      {"water", {{0.16f, 0.38f, 0.66f}, surface_look::kWater}},
      {"dirt", {{0.62f, 0.43f, 0.27f}, surface_look::kDirt}},
      {"grass", {{0.30f, 0.58f, 0.22f}, surface_look::kMown}},
      {"warning_track", {{0.52f, 0.36f, 0.24f}, surface_look::kDirt}},
      {"wall", {{0.10f, 0.30f, 0.20f}, surface_look::kPlain}},
      {"flag", {{0.90f, 0.10f, 0.10f}, surface_look::kCloth}},
      {"pole", {{0.95f, 0.95f, 0.95f}, surface_look::kPlain}},
      {"ball", {{0.97f, 0.97f, 0.97f}, surface_look::kPlain}},
      {"clubhead", {{0.45f, 0.46f, 0.50f}, surface_look::kPlain}},
      {"face", {{0.80f, 0.82f, 0.86f}, surface_look::kPlain}},
      {"shaft", {{0.65f, 0.67f, 0.70f}, surface_look::kPlain}},
      {"grip", {{0.08f, 0.08f, 0.08f}, surface_look::kPlain}},
      {"bat", {{0.82f, 0.63f, 0.38f}, surface_look::kPlain}},
      {"out_of_bounds", {{0.16f, 0.30f, 0.13f}, surface_look::kLongGrass}},
      {"foul_pole", {{0.95f, 0.85f, 0.10f}, surface_look::kPlain}},
      {"tree", {{0.11f, 0.27f, 0.10f}, surface_look::kLongGrass}},  // a crown: darker than the rough under it
      {"trunk", {{0.33f, 0.24f, 0.15f}, surface_look::kPlain}},
      {"cart_path", {{0.55f, 0.54f, 0.52f}, surface_look::kDirt}},
  }};
  return p;
}

}  // namespace

std::optional<PaletteEntry> palette_color(std::string_view material) {
  for (const auto& n : palette()) {
    if (n.name == material) return n.entry;
  }
  return std::nullopt;
}

MeshData import_mesh(const std::filesystem::path& path) {
  // Flat normals for files without them keep facets readable; pre-transform bakes node
  // transforms so the mesh is in the file's frame.
  const MeshFile imported = import_mesh_file(
      path, "mesh", kMaxMeshBytes,
      aiProcess_Triangulate | aiProcess_GenNormals | aiProcess_PreTransformVertices |
          aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (imported.incomplete) throw InputError("mesh " + path.string() + " is incomplete");
  MeshData out;
  for (const MeshPart& part : imported.parts) {
    if (part.triangles.empty()) continue;
    const std::string& name = part.material;
    PaletteEntry entry{{0.7f, 0.7f, 0.7f}, 0.0f};
    if (auto p = palette_color(name)) {
      entry = *p;
    } else if (part.has_diffuse) {
      entry.color = {part.diffuse[0], part.diffuse[1], part.diffuse[2]};
    }
    auto it = std::find(out.materials.begin(), out.materials.end(), name);
    if (it == out.materials.end()) {
      out.materials.push_back(name);
      it = out.materials.end() - 1;
    }
    const auto mat_index = static_cast<std::uint16_t>(it - out.materials.begin());
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (size_t v = 0; v < part.positions.size(); ++v) {
      Vertex vx;
      vx.position = {part.positions[v][0], part.positions[v][1], part.positions[v][2]};
      if (v < part.normals.size()) vx.normal = {part.normals[v][0], part.normals[v][1], part.normals[v][2]};
      vx.color = entry.color;
      vx.pattern = entry.pattern;
      out.vertices.push_back(vx);
    }
    for (const auto& tri : part.triangles) {
      if (tri[0] >= part.positions.size() || tri[1] >= part.positions.size() || tri[2] >= part.positions.size())
        throw InputError("mesh " + path.string() + " has a triangle that refers to a vertex that does not exist");
      for (int k = 0; k < 3; ++k) out.indices.push_back(base + tri[static_cast<size_t>(k)]);
      out.triangle_material.push_back(mat_index);
    }
  }
  if (out.indices.empty()) throw InputError("mesh " + path.string() + " holds no triangles");
  return out;
}

MeshData world_mesh_data(const WorldDescription& world) {
  MeshData out;
  for (const WorldMesh& m : world.meshes) {
    const std::string& name = world.materials[static_cast<size_t>(m.material)].name;
    const PaletteEntry entry = palette_color(name).value_or(PaletteEntry{{0.7f, 0.7f, 0.7f}, 0.0f});
    auto it = std::find(out.materials.begin(), out.materials.end(), name);
    if (it == out.materials.end()) {
      out.materials.push_back(name);
      it = out.materials.end() - 1;
    }
    const auto mat_index = static_cast<std::uint16_t>(it - out.materials.begin());
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    // Area-weighted vertex normals: terrain reads smooth, walls stay sharp at their own mesh.
    std::vector<Vec3> normals(m.vertices.size(), Vec3::Zero());
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      const Vec3& a = m.vertices[m.indices[t]];
      const Vec3 n = (m.vertices[m.indices[t + 1]] - a).cross(m.vertices[m.indices[t + 2]] - a);
      for (int k = 0; k < 3; ++k) normals[m.indices[t + static_cast<size_t>(k)]] += n;
    }
    for (size_t v = 0; v < m.vertices.size(); ++v) {
      Vertex vx;
      vx.position = m.vertices[v].cast<float>();
      const double len = normals[v].norm();
      vx.normal = len > 0.0 ? Eigen::Vector3f((normals[v] / len).cast<float>()) : Eigen::Vector3f::UnitY();
      vx.color = entry.color;
      vx.pattern = entry.pattern;
      out.vertices.push_back(vx);
    }
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      for (int k = 0; k < 3; ++k) out.indices.push_back(base + m.indices[t + static_cast<size_t>(k)]);
      out.triangle_material.push_back(mat_index);
    }
  }
  return out;
}

}  // namespace sweetspot
