// Sections: 1. materials.toml   2. the mesh (assimp)   3. the world .toml   4. names
#include "game/content/world_asset.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <system_error>

#include "game/content/gzip_file.hpp"
#include "game/content/mesh_file.hpp"
#include "game/core/sport.hpp"
#include "game/content/toml_file.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace fs = std::filesystem;

// ---- 1. materials ----------------------------------------------------------------------
std::vector<SurfaceMaterial> load_materials(const fs::path& path) {
  const TomlFile f = TomlFile::read(path, "materials");
  std::vector<SurfaceMaterial> out;
  for (const auto& [name_key, node] : f.root()) {
    const std::string name(name_key.str());
    const toml::table& t = f.table(node, name);
    f.only_keys(t, name, {"kind", "e", "mu", "rolling_resistance", "stimp", "crater_tilt", "layer_drag", "lie_friction",
                        "lie_speed_loss"});
    SurfaceMaterial m;
    m.name = name;
    const std::string kind = f.text(f.required(t, "kind", "allowed: " + surface_kind_names()), name + ".kind");
    if (!surface_kind_from_string(kind, &m.kind))
      f.fail(*t.get("kind"), name + ".kind", "unknown kind '" + kind + "' (allowed: " + surface_kind_names() + ")");
    m.e = CorCurve::constant(0.0);
    if (const toml::node* e = t.get("e")) {
      const auto pts = f.pairs(*e, name + ".e", Dimension::Speed, Dimension::Dimensionless);
      if (pts.size() > static_cast<size_t>(CorCurve::kMaxPoints))
        f.fail(*e, name + ".e", "at most " + std::to_string(CorCurve::kMaxPoints) + " points [speed, e]");
      m.e.count = static_cast<int>(pts.size());
      for (size_t i = 0; i < pts.size(); ++i) {
        m.e.speed[i] = pts[i].first;
        m.e.cor[i] = pts[i].second;
      }
    }
    m.mu = f.quantity_or(t, "mu", Dimension::Dimensionless, 0.0, &SurfaceMaterial::kMu);
    m.rolling_resistance =
        f.quantity_or(t, "rolling_resistance", Dimension::Dimensionless, 0.0, &SurfaceMaterial::kRollingResistance);
    m.stimp = f.quantity_or(t, "stimp", Dimension::Length, 0.0, &SurfaceMaterial::kStimp);
    m.crater_tilt = f.quantity_or(t, "crater_tilt", Dimension::Angle, 0.0, &SurfaceMaterial::kCraterTilt);
    m.layer_drag = f.quantity_or(t, "layer_drag", Dimension::Dimensionless, 0.0, &SurfaceMaterial::kLayerDrag);
    m.lie_friction = f.quantity_or(t, "lie_friction", Dimension::Dimensionless, 1.0, &SurfaceMaterial::kLieFriction);
    m.lie_speed_loss = f.quantity_or(t, "lie_speed_loss", Dimension::Dimensionless, 0.0, &SurfaceMaterial::kLieSpeedLoss);
    if (const std::string why = validate_surface_material(m); !why.empty()) throw InputError(f.where(node) + ": " + why);
    out.push_back(std::move(m));
  }
  if (out.empty()) throw InputError(path.string() + ": no materials");
  return out;
}

// ---- 2. the mesh -----------------------------------------------------------------------
namespace {

void add_meshes(const MeshFile& file_meshes, const fs::path& file, WorldDescription* d, int* dropped) {
  for (const MeshPart& part : file_meshes.parts) {
    const std::string& mname = part.material;
    const auto it = std::find_if(d->materials.begin(), d->materials.end(),
                                 [&](const SurfaceMaterial& m) { return m.name == mname; });
    if (it == d->materials.end()) {
      std::string names;
      for (const auto& m : d->materials) names += (names.empty() ? "" : ", ") + m.name;
      throw InputError(file.string() + ": mesh '" + part.name + "' uses material '" + mname +
                       "', which materials.toml does not define (allowed: " + names + ")");
    }
    WorldMesh wm;
    wm.material = static_cast<int>(it - d->materials.begin());
    wm.vertices.reserve(part.positions.size());
    for (size_t v = 0; v < part.positions.size(); ++v) {
      const Vec3 q(part.positions[v][0], part.positions[v][1], part.positions[v][2]);
      if (!q.allFinite())
        throw InputError(file.string() + ": mesh '" + mname + "' vertex " + std::to_string(v) +
                         " is not a finite number (NaN, infinity, or past the mesh reader's 32-bit float range, 3.4e38); fix the file");
      // Far-away vertices would swamp Bullet's quantised triangle tree and the bounds, so a
      // world is limited to kMaxWorldExtent from its origin in every axis.
      if (q.cwiseAbs().maxCoeff() > kMaxWorldExtent)
        throw InputError(file.string() + ": mesh '" + mname + "' vertex " + std::to_string(v) +
                         " lies beyond the world limit of " + std::to_string(static_cast<long>(kMaxWorldExtent)) +
                         " m from the origin in some axis; fix the file");
      wm.vertices.push_back(q);
    }
    for (size_t fi = 0; fi < part.triangles.size(); ++fi) {
      const auto& tri = part.triangles[fi];
      if (tri[0] >= wm.vertices.size() || tri[1] >= wm.vertices.size() || tri[2] >= wm.vertices.size())
        throw InputError(file.string() + ": mesh '" + mname + "' triangle " + std::to_string(fi) +
                         " refers to a vertex that does not exist (truncated or corrupt file)");
      const Vec3& a = wm.vertices[tri[0]];
      const Vec3& b = wm.vertices[tri[1]];
      const Vec3& c = wm.vertices[tri[2]];
      if (!((b - a).cross(c - a).norm() > 1e-12 * std::max((b - a).squaredNorm(), (c - a).squaredNorm()))) {
        ++*dropped;
        continue;
      }
      wm.indices.insert(wm.indices.end(), {tri[0], tri[1], tri[2]});
    }
    if (!wm.indices.empty()) d->meshes.push_back(std::move(wm));
  }
}

/// Every world mesh passes the same checks, whichever path named it: readable, finite,
/// near the origin, indices in range, and at least one collidable triangle with area.
void load_mesh(const fs::path& obj, WorldDescription* d) {
  int dropped = 0;
  add_meshes(import_mesh_file(obj, "world mesh", kMaxWorldMeshBytes), obj, d, &dropped);
  if (dropped > 0)
    d->notes.push_back(obj.string() + ": dropped " + std::to_string(dropped) + " zero-area triangle" +
                       (dropped == 1 ? "" : "s"));
  const bool collidable = std::any_of(d->meshes.begin(), d->meshes.end(), [&](const WorldMesh& m) {
    return d->materials[static_cast<size_t>(m.material)].kind != SurfaceKind::Decoration;
  });
  if (!collidable)
    throw InputError(obj.string() + ": no collidable triangles with area (empty, truncated, garbage or "
                     "decoration-only mesh)");
}

fs::path resolve_world(const fs::path& root, const std::string& name_or_path) {
  if (is_world_path(name_or_path)) return name_or_path;
  const fs::path p = root / "worlds" / (name_or_path + ".toml");
  if (std::error_code ec; !fs::is_regular_file(p, ec)) {
    std::string names;
    for (const auto& n : world_names(root)) names += (names.empty() ? "" : ", ") + n;
    throw InputError("unknown world '" + name_or_path + "' (allowed: " + names + ", none, or a path to a .toml)");
  }
  return p;
}

/// Every coordinate of a world file lies within the same limit as its mesh's vertices.
const Range kWorldCoordinate{-kMaxWorldExtent, kMaxWorldExtent};

Vec3 vec3(const TomlFile& f, const toml::node& n, std::string_view key) {
  const auto v = f.quantities(n, key, Dimension::Length, 3, &kWorldCoordinate);
  return Vec3(v[0], v[1], v[2]);
}

// A world's own cup sits on its green: a pin over the rough, floating above the green or
// buried under it would make its hole unfinishable.
void check_pin_on_green(const WorldAsset& a, const std::string& where) {
  constexpr double kOnSurface = 0.05;  // m: a cup's rim on the mesh, beyond a modeller's rounding
  const Vec3 p = *a.pin;
  const WorldDescription& d = a.description();
  SurfaceContact hit;
  const std::string at = "pin = [" + std::to_string(p.x()) + " m, " + std::to_string(p.y()) + " m, " +
                         std::to_string(p.z()) + " m]";
  if (!ground_under(*a.world, p.x(), p.z(), d.bounds_max.y(), d.bounds_max.y() - d.bounds_min.y(), &hit))
    throw InputError(where + ": " + at + ": no ground under it (the cup sits on the world's green)");
  const SurfaceKind kind = a.world->material(hit.material).kind;
  if (kind != SurfaceKind::Green)
    throw InputError(where + ": " + at + " lies over " + to_string(kind) + " (the cup sits on the world's green)");
  if (std::abs(p.y() - hit.point.y()) > kOnSurface)
    throw InputError(where + ": " + at + ": the green's surface there is at y = " + std::to_string(hit.point.y()) +
                     " m (the cup sits on it, within 0.05 m)");
}

}  // namespace

std::string ground_extent_text(const WorldDescription& d, const Vec3& relative_to) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const WorldMesh& m : d.meshes)
    for (const Vec3& v : m.vertices) {
      lo = lo.cwiseMin(v - relative_to);
      hi = hi.cwiseMax(v - relative_to);
    }
  if (!(lo.x() <= hi.x())) return "it has no ground";
  const auto m = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return std::string(buf);
  };
  return "its ground spans x " + m(lo.x()) + " to " + m(hi.x()) + " m and z " + m(lo.z()) + " to " + m(hi.z()) + " m";
}

bool is_world_path(const std::string& name_or_path) {
  return name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".toml") ||
         name_or_path.ends_with(".obj") || name_or_path.ends_with(".obj.gz");
}

// ---- 3. the world .toml ----------------------------------------------------------------
WorldAsset load_world_asset(const fs::path& root, const std::string& name_or_path,
                            const std::vector<SurfaceMaterial>& materials, const SportCatalog* sports) {
  const fs::path path = resolve_world(root, name_or_path);
  WorldAsset a;
  a.source = path;
  std::string pin_where;  // file:line of the pin key
  WorldDescription d;
  d.materials = materials;
  if (without_gzip_suffix(path).extension() == ".obj") {
    d.name = without_gzip_suffix(path).stem().string();
    load_mesh(path, &d);
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const auto& m : d.meshes)
      for (const auto& v : m.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
    // The shot starts at the origin, so the box holds it even when the mesh does not (a
    // lone wall); a margin keeps a flat or single-plane mesh from giving an empty box.
    lo = lo.cwiseMin(d.origin);
    hi = hi.cwiseMax(d.origin);
    d.bounds_min = lo - Vec3(10.0, 10.0, 10.0);
    d.bounds_max = hi + Vec3(10.0, 400.0, 10.0);
  } else {
    const TomlFile f = TomlFile::read(path, "world");
    const toml::table& t = f.root();
    f.only_keys(t, "", {"name", "sport", "mesh", "origin", "bounds_min", "bounds_max", "pin", "fence_height",
                        "fence_line"});
    d.name = f.text_or(t, "name", path.stem().string());
    a.sport = f.text_or(t, "sport", "");
    if (sports != nullptr && t.get("sport") != nullptr) {
      const auto known = std::find_if(sports->sports.begin(), sports->sports.end(),
                                       [&](const SportProfile& p) { return p.name == a.sport; });
      if (known == sports->sports.end())
        f.fail(*t.get("sport"), "sport", "unknown sport '" + a.sport + "' (allowed: " + sports->names() + ")");
    }
    const std::string mesh = f.text(f.required(t, "mesh", "the .obj file, relative to the .toml"), "mesh");
    if (const toml::node* n = t.get("origin")) d.origin = vec3(f, *n, "origin");
    if (const toml::node* n = t.get("bounds_min")) d.bounds_min = vec3(f, *n, "bounds_min");
    if (const toml::node* n = t.get("bounds_max")) d.bounds_max = vec3(f, *n, "bounds_max");
    if (const toml::node* n = t.get("pin")) {
      a.pin = vec3(f, *n, "pin");
      pin_where = f.where(*n);
    }
    a.fence_height = f.quantity_or(t, "fence_height", Dimension::Length, 0.0, &WorldAsset::kFenceHeight);
    if (const toml::node* n = t.get("fence_line")) {
      const toml::array* arr = n->as_array();
      if (arr == nullptr || arr->size() < 2) f.fail(*n, "fence_line", "expected [[x, z], ...] with 2 or more points");
      for (const toml::node& p : *arr) {
        const auto xz = f.quantities(p, "fence_line", Dimension::Length, 2, &kWorldCoordinate);
        // A fence point off the world would put a home run where no ball can reach.
        if (xz[0] < d.bounds_min.x() || xz[0] > d.bounds_max.x() || xz[1] < d.bounds_min.z() || xz[1] > d.bounds_max.z())
          f.fail(p, "fence_line", "point " + std::to_string(a.fence_line.size()) +
                                      " lies outside the world's bounds_min .. bounds_max in x or z");
        a.fence_line.emplace_back(xz[0], d.origin.y(), xz[1]);
      }
    }
    // The tee (or home plate) and the cup lie in the world the shot is played in; a fence
    // needs its line, and each of its segments a length.
    const auto inside = [&](const Vec3& q) {
      return (q.array() >= d.bounds_min.array()).all() && (q.array() <= d.bounds_max.array()).all();
    };
    if (t.get("origin") != nullptr && !inside(d.origin))
      f.fail(*t.get("origin"), "origin", "lies outside the world's bounds_min .. bounds_max");
    if (t.get("pin") != nullptr && !inside(*a.pin)) f.fail(*t.get("pin"), "pin", "lies outside the world's bounds_min .. bounds_max");
    if (t.get("fence_height") != nullptr && a.fence_line.empty())
      f.fail(*t.get("fence_height"), "fence_height", "a fence needs its fence_line = [[x, z], ...] too");
    for (size_t i = 1; i < a.fence_line.size(); ++i)
      if ((a.fence_line[i] - a.fence_line[i - 1]).norm() < 0.01)
        f.fail(*t.get("fence_line"), "fence_line", "points " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                                       " coincide (each segment needs a length)");
    load_mesh(path.parent_path() / mesh, &d);
  }
  a.name = d.name;
  if (const std::string why = validate_world(d); !why.empty()) throw InputError(path.string() + ": " + why);
  a.world = std::make_unique<const World>(std::move(d));
  a.trees = tree_crowns(a.description());
  if (a.pin) check_pin_on_green(a, pin_where);
  return a;
}

// ---- 4. names --------------------------------------------------------------------------
std::vector<std::string> world_names(const fs::path& root) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(root / "worlds", ec))
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace sweetspot
