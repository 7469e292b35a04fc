#include "game/render/mesh_import.hpp"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <string>

#include "game/render/render_error.hpp"

namespace sweetspot {
namespace {

struct Named {
  std::string_view name;
  PaletteEntry entry;
};

// Colours chosen to read at a glance from far away: fairway a mid green with stripes, rough
// darker and bluer, green the lightest and stripy, sand pale, dirt and warning track warm
// browns, the outfield wall a dark green as in most ballparks.
const std::array<Named, 20>& palette() {
  static const std::array<Named, 20> p{{
      {"tee", {{0.40f, 0.66f, 0.27f}, 1.0f}},
      {"fairway", {{0.36f, 0.64f, 0.23f}, 1.0f}},
      {"rough", {{0.18f, 0.40f, 0.15f}, 0.0f}},
      {"sand", {{0.90f, 0.82f, 0.60f}, 0.0f}},
      {"green", {{0.46f, 0.80f, 0.34f}, 1.0f}},
      {"water", {{0.16f, 0.38f, 0.66f}, 0.0f}},
      {"dirt", {{0.62f, 0.43f, 0.27f}, 0.0f}},
      {"grass", {{0.30f, 0.58f, 0.22f}, 1.0f}},
      {"warning_track", {{0.52f, 0.36f, 0.24f}, 0.0f}},
      {"wall", {{0.10f, 0.30f, 0.20f}, 0.0f}},
      {"flag", {{0.90f, 0.10f, 0.10f}, 0.0f}},
      {"pole", {{0.95f, 0.95f, 0.95f}, 0.0f}},
      {"ball", {{0.97f, 0.97f, 0.97f}, 0.0f}},
      {"clubhead", {{0.45f, 0.46f, 0.50f}, 0.0f}},
      {"face", {{0.80f, 0.82f, 0.86f}, 0.0f}},
      {"shaft", {{0.65f, 0.67f, 0.70f}, 0.0f}},
      {"grip", {{0.08f, 0.08f, 0.08f}, 0.0f}},
      {"bat", {{0.82f, 0.63f, 0.38f}, 0.0f}},
      {"out_of_bounds", {{0.16f, 0.30f, 0.13f}, 0.0f}},
      {"foul_pole", {{0.95f, 0.85f, 0.10f}, 0.0f}},
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
  Assimp::Importer importer;
  // Flat normals for files without them keep terrain facets readable; pre-transform bakes
  // node transforms so the mesh is in the file's frame.
  const aiScene* scene = importer.ReadFile(
      path.string(), aiProcess_Triangulate | aiProcess_GenNormals | aiProcess_PreTransformVertices |
                         aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) {
    throw RenderError("mesh " + path.string() + " cannot be read: " + importer.GetErrorString());
  }
  MeshData out;
  for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
    const aiMesh* mesh = scene->mMeshes[mi];
    if ((mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    const aiMaterial* mat = scene->mMaterials[mesh->mMaterialIndex];
    aiString ai_name;
    mat->Get(AI_MATKEY_NAME, ai_name);
    const std::string name = ai_name.C_Str();
    PaletteEntry entry{{0.7f, 0.7f, 0.7f}, 0.0f};
    if (auto p = palette_color(name)) {
      entry = *p;
    } else if (aiColor3D kd; mat->Get(AI_MATKEY_COLOR_DIFFUSE, kd) == AI_SUCCESS) {
      entry.color = {kd.r, kd.g, kd.b};
    }
    auto it = std::find(out.materials.begin(), out.materials.end(), name);
    if (it == out.materials.end()) {
      out.materials.push_back(name);
      it = out.materials.end() - 1;
    }
    const auto mat_index = static_cast<std::uint16_t>(it - out.materials.begin());
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      Vertex vx;
      vx.position = {mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z};
      if (mesh->HasNormals()) vx.normal = {mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z};
      vx.color = entry.color;
      vx.pattern = entry.pattern;
      out.vertices.push_back(vx);
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (int k = 0; k < 3; ++k) out.indices.push_back(base + face.mIndices[k]);
      out.triangle_material.push_back(mat_index);
    }
  }
  if (out.indices.empty()) throw RenderError("mesh " + path.string() + " holds no triangles");
  return out;
}

}  // namespace sweetspot
