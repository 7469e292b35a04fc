// Sections: 1. asset root   2. materials.toml   3. world .toml + assimp mesh
#include "game/assets/assets.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <system_error>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <toml++/toml.h>

#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace fs = std::filesystem;

// ---- 1. asset root ---------------------------------------------------------------------
fs::path asset_root() {
  if (const char* env = std::getenv("SWEETSPOT_ASSETS"); env != nullptr && *env != '\0') return env;
#ifdef SWEETSPOT_SOURCE_DIR
  const fs::path src = fs::path(SWEETSPOT_SOURCE_DIR) / "assets";
  if (std::error_code e; fs::is_directory(src, e)) return src;
#endif
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  for (fs::path dir = ec ? fs::current_path() : exe.parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (std::error_code e; fs::is_directory(dir / "assets", e)) return dir / "assets";
    if (dir == dir.parent_path()) break;
  }
  return "assets";
}

namespace {

std::string where(const fs::path& file, const toml::node& node, std::string_view key) {
  std::ostringstream s;
  s << file.string() << ":" << node.source().begin.line << ": " << key;
  return s.str();
}

std::string where(const fs::path& file, std::string_view key) { return file.string() + ": " + std::string(key); }

toml::table parse_toml(const fs::path& path) {
  // error_code overloads: a path the OS refuses (too long, bad permissions) is bad input,
  // not a filesystem_error escaping as an internal error (a fuzzer finding).
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError(path.string() + ": file not found" + (ec ? " (" + ec.message() + ")" : std::string()));
  try {
    return toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream s;
    s << path.string() << ":" << e.source().begin.line << ": " << e.description();
    throw InputError(s.str());
  }
}

/// A number (SI) or a string with units.
double quantity(const fs::path& file, const toml::node& node, std::string_view key, Dimension dim) {
  if (auto v = node.value<double>()) return *v;
  if (auto s = node.value<std::string>()) {
    try {
      return parse_quantity(*s, dim);
    } catch (const InputError& e) {
      throw InputError(where(file, node, key) + ": " + e.what());
    }
  }
  throw InputError(where(file, node, key) + ": expected a number or a quantity string (" +
                   std::string(dimension_name(dim)) + ")");
}

double number(const fs::path& file, const toml::node& node, std::string_view key) {
  if (auto v = node.value<double>()) return *v;
  throw InputError(where(file, node, key) + ": expected a number");
}

Vec3 vec3(const fs::path& file, const toml::node& node, std::string_view key) {
  const toml::array* a = node.as_array();
  if (a == nullptr || a->size() != 3) throw InputError(where(file, node, key) + ": expected [x, y, z] in metres");
  return Vec3(number(file, *a->get(0), key), number(file, *a->get(1), key), number(file, *a->get(2), key));
}

}  // namespace

// ---- 2. materials ----------------------------------------------------------------------
std::vector<SurfaceMaterial> load_materials(const fs::path& path) {
  const toml::table root = parse_toml(path);
  std::vector<SurfaceMaterial> out;
  for (const auto& [name_key, node] : root) {
    const std::string name(name_key.str());
    const toml::table* t = node.as_table();
    if (t == nullptr) throw InputError(where(path, node, name) + ": expected a [" + name + "] table");
    SurfaceMaterial m;
    m.name = name;
    m.e = CorCurve::constant(0.0);
    m.mu = 0.0;
    m.rolling_resistance = 0.0;
    static const std::vector<std::string> allowed = {"kind", "e", "mu", "rolling_resistance", "stimp", "crater_tilt"};
    for (const auto& [k, v] : *t) {
      const std::string key = name + "." + std::string(k.str());
      if (std::find(allowed.begin(), allowed.end(), k.str()) == allowed.end())
        throw InputError(where(path, v, key) + ": unknown key (allowed: kind, e, mu, rolling_resistance, stimp, crater_tilt)");
      if (k == "kind") {
        const auto s = v.value<std::string>();
        if (!s || !surface_kind_from_string(*s, &m.kind))
          throw InputError(where(path, v, key) + ": unknown kind (allowed: " + surface_kind_names() + ")");
      } else if (k == "e") {
        const toml::array* a = v.as_array();
        if (a == nullptr || a->empty() || a->size() > static_cast<size_t>(CorCurve::kMaxPoints))
          throw InputError(where(path, v, key) + ": expected 1.." + std::to_string(CorCurve::kMaxPoints) +
                           " points [[speed m/s, e], ...]");
        m.e.count = static_cast<int>(a->size());
        for (size_t i = 0; i < a->size(); ++i) {
          const toml::array* p = a->get(i)->as_array();
          if (p == nullptr || p->size() != 2) throw InputError(where(path, v, key) + ": each point is [speed m/s, e]");
          m.e.speed[i] = quantity(path, *p->get(0), key, Dimension::Speed);
          m.e.cor[i] = number(path, *p->get(1), key);
        }
      } else if (k == "mu") {
        m.mu = number(path, v, key);
      } else if (k == "rolling_resistance") {
        m.rolling_resistance = number(path, v, key);
      } else if (k == "stimp") {
        m.stimp = quantity(path, v, key, Dimension::Length);
      } else if (k == "crater_tilt") {
        m.crater_tilt = quantity(path, v, key, Dimension::Angle);
      }
    }
    if (!t->contains("kind")) throw InputError(where(path, node, name) + ": missing kind (allowed: " + surface_kind_names() + ")");
    const std::string why = validate_surface_material(m);
    if (!why.empty()) throw InputError(where(path, node, name) + ": " + why);
    out.push_back(std::move(m));
  }
  if (out.empty()) throw InputError(path.string() + ": no materials");
  return out;
}

// ---- 3. worlds -------------------------------------------------------------------------
namespace {

struct MeshLoad {
  int dropped = 0;
};

void add_node_meshes(const aiScene* scene, const aiNode* node, const aiMatrix4x4& parent, const fs::path& file,
                     WorldDescription* d, MeshLoad* stats) {
  const aiMatrix4x4 xf = parent * node->mTransformation;
  for (unsigned k = 0; k < node->mNumMeshes; ++k) {
    const aiMesh* am = scene->mMeshes[node->mMeshes[k]];
    aiString ainame;
    scene->mMaterials[am->mMaterialIndex]->Get(AI_MATKEY_NAME, ainame);
    const std::string mname = ainame.C_Str();
    const auto it = std::find_if(d->materials.begin(), d->materials.end(),
                                 [&](const SurfaceMaterial& m) { return m.name == mname; });
    if (it == d->materials.end()) {
      std::string names;
      for (const auto& m : d->materials) names += (names.empty() ? "" : ", ") + m.name;
      throw InputError(file.string() + ": mesh '" + std::string(am->mName.C_Str()) + "' uses material '" + mname +
                       "', which materials.toml does not define (allowed: " + names + ")");
    }
    WorldMesh wm;
    wm.material = static_cast<int>(it - d->materials.begin());
    wm.vertices.reserve(am->mNumVertices);
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D p = xf * am->mVertices[v];
      const Vec3 q(p.x, p.y, p.z);
      if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()))
        throw InputError(file.string() + ": mesh '" + mname + "' vertex " + std::to_string(v) +
                         " is not a finite number (NaN or infinity); fix the file");
      // Far-away vertices would swamp Bullet's quantised triangle tree and the bounds, so a
      // world is limited to kMaxWorldExtent from its origin in every axis.
      if (q.cwiseAbs().maxCoeff() > kMaxWorldExtent)
        throw InputError(file.string() + ": mesh '" + mname + "' vertex " + std::to_string(v) +
                         " lies beyond the world limit of " + std::to_string(static_cast<long>(kMaxWorldExtent)) +
                         " m from the origin in some axis; fix the file");
      wm.vertices.push_back(q);
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      if (face.mIndices[0] >= am->mNumVertices || face.mIndices[1] >= am->mNumVertices ||
          face.mIndices[2] >= am->mNumVertices)
        throw InputError(file.string() + ": mesh '" + mname + "' face " + std::to_string(f) +
                         " refers to a vertex that does not exist (truncated or corrupt file)");
      const Vec3& a = wm.vertices[face.mIndices[0]];
      const Vec3& b = wm.vertices[face.mIndices[1]];
      const Vec3& c = wm.vertices[face.mIndices[2]];
      if (!((b - a).cross(c - a).norm() > 1e-12 * std::max((b - a).squaredNorm(), (c - a).squaredNorm()))) {
        ++stats->dropped;
        continue;
      }
      wm.indices.insert(wm.indices.end(), {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
    }
    if (!wm.indices.empty()) d->meshes.push_back(std::move(wm));
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) add_node_meshes(scene, node->mChildren[c], xf, file, d, stats);
}

void load_mesh(const fs::path& obj, WorldDescription* d) {
  std::error_code ec;
  if (!fs::is_regular_file(obj, ec))
    throw InputError(obj.string() + ": world mesh not found" + (ec ? " (" + ec.message() + ")" : std::string()));
  // Refuse a file that would take minutes and gigabytes to import before assimp reads it.
  const std::uintmax_t bytes = fs::file_size(obj, ec);
  if (ec) throw InputError(obj.string() + ": cannot read the world mesh's size (" + ec.message() + ")");
  if (bytes > kMaxWorldMeshBytes)
    throw InputError(obj.string() + ": world mesh is " + std::to_string(bytes >> 20) +
                     " MiB, over the limit of " + std::to_string(kMaxWorldMeshBytes >> 20) + " MiB");
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(obj.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr)
    throw InputError(obj.string() + ": cannot read the world mesh: " + importer.GetErrorString());
  MeshLoad stats;
  add_node_meshes(scene, scene->mRootNode, aiMatrix4x4(), obj, d, &stats);
  if (stats.dropped > 0)
    d->notes.push_back(obj.string() + ": dropped " + std::to_string(stats.dropped) + " zero-area triangle" +
                       (stats.dropped == 1 ? "" : "s"));
}

fs::path resolve_world(const std::string& name_or_path) {
  if (name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".toml") ||
      name_or_path.ends_with(".obj"))
    return name_or_path;
  const fs::path p = asset_root() / "worlds" / (name_or_path + ".toml");
  if (std::error_code ec; !fs::is_regular_file(p, ec)) {
    std::string names;
    for (const auto& n : world_names()) names += (names.empty() ? "" : ", ") + n;
    throw InputError("unknown world '" + name_or_path + "' (allowed: " + names + ", none, or a path to a .toml)");
  }
  return p;
}

}  // namespace

WorldDescription load_world(const std::string& name_or_path) {
  const fs::path path = resolve_world(name_or_path);
  WorldDescription d;
  d.materials = load_materials(asset_root() / "materials.toml");
  if (path.extension() == ".obj") {
    d.name = path.stem().string();
    load_mesh(path, &d);
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const auto& m : d.meshes)
      for (const auto& v : m.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
    if (d.meshes.empty())
      throw InputError(path.string() + ": no triangles with area (empty, truncated or degenerate mesh)");
    // The shot starts at the origin, so the box holds it even when the mesh does not (a
    // lone wall); a margin keeps a flat or single-plane mesh from giving an empty box.
    lo = lo.cwiseMin(d.origin);
    hi = hi.cwiseMax(d.origin);
    d.bounds_min = lo - Vec3(10.0, 10.0, 10.0);
    d.bounds_max = hi + Vec3(10.0, 400.0, 10.0);
  } else {
    const toml::table t = parse_toml(path);
    static const std::vector<std::string> allowed = {"name", "sport", "mesh", "origin", "bounds_min", "bounds_max",
                                                     "flag", "fence_height", "fence_line", "green_stimp_ft",
                                                     "foul_line_ft", "centre_field_ft", "triangles"};
    for (const auto& [k, v] : t)
      if (std::find(allowed.begin(), allowed.end(), k.str()) == allowed.end())
        throw InputError(where(path, v, k.str()) + ": unknown key (allowed: name, sport, mesh, origin, bounds_min, "
                         "bounds_max, flag, fence_height, fence_line, and informational keys)");
    d.name = t["name"].value_or(path.stem().string());
    d.sport = t["sport"].value_or(std::string());
    const auto mesh = t["mesh"].value<std::string>();
    if (!mesh) throw InputError(where(path, "mesh") + ": missing (the .obj file, relative to the .toml)");
    if (const toml::node* n = t.get("origin")) d.origin = vec3(path, *n, "origin");
    if (const toml::node* n = t.get("bounds_min")) d.bounds_min = vec3(path, *n, "bounds_min");
    if (const toml::node* n = t.get("bounds_max")) d.bounds_max = vec3(path, *n, "bounds_max");
    if (const toml::node* n = t.get("flag")) d.flag = vec3(path, *n, "flag");
    if (const toml::node* n = t.get("fence_height")) d.fence_height = quantity(path, *n, "fence_height", Dimension::Length);
    if (const toml::node* n = t.get("fence_line")) {
      const toml::array* a = n->as_array();
      if (a == nullptr) throw InputError(where(path, *n, "fence_line") + ": expected [[x, z], ...] in metres");
      for (const toml::node& p : *a) {
        const toml::array* xz = p.as_array();
        if (xz == nullptr || xz->size() != 2) throw InputError(where(path, p, "fence_line") + ": each point is [x, z]");
        d.fence_line.emplace_back(number(path, *xz->get(0), "fence_line"), d.origin.y(),
                                  number(path, *xz->get(1), "fence_line"));
      }
    }
    load_mesh(path.parent_path() / *mesh, &d);
  }
  const std::string why = validate_world(d);
  if (!why.empty()) throw InputError(path.string() + ": " + why);
  return d;
}

std::string default_world_name(std::string_view sport) {
  if (sport == "golf") return "golf_hole";
  if (sport == "baseball") return "ballpark";
  throw InputError("unknown sport '" + std::string(sport) + "' (allowed: golf, baseball)");
}

std::vector<std::string> world_names() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(asset_root() / "worlds", ec))
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace sweetspot
