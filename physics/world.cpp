// World: Bullet collision queries over triangle meshes, plus a coarse height grid that lets
// the flight skip sweeps while the ball is far above everything (most of a shot).
#include "physics/world.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <limits>
#include <sstream>

#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <btBulletCollisionCommon.h>

#include "physics/error.hpp"
#include "physics/detail/sphere_sweep.hpp"

namespace sweetspot {
namespace {

btVector3 bt(const Vec3& v) { return btVector3(v.x(), v.y(), v.z()); }

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

struct TriRef {
  int mesh = -1;
  int tri = -1;
};

/// Triangles of one material handed to Bullet. Bullet reads the arrays in place, so they
/// must outlive the shape and never reallocate after it is built.
struct CollisionMesh {
  int material = 0;
  std::vector<double> vertices;  // xyz
  std::vector<int> indices;      // 3 per triangle
  std::vector<Vec3> normals;     // unit face normal per triangle
  std::vector<std::array<TriRef, 3>> neighbours;  // across edge k = (corner k, corner k+1), any mesh
  std::unique_ptr<btTriangleIndexVertexArray> array;
  std::unique_ptr<btBvhTriangleMeshShape> shape;
  std::unique_ptr<btCollisionObject> object;

  Vec3 vertex(int tri, int corner) const {
    const auto i = static_cast<size_t>(indices[static_cast<size_t>(3 * tri + corner)]) * 3;
    return Vec3(vertices[i], vertices[i + 1], vertices[i + 2]);
  }
};

}  // namespace

struct World::Impl {
  WorldDescription desc;
  std::vector<CollisionMesh> meshes;
  int triangles = 0;
  /// m: below this no collidable triangle (nor the tee) can be reached again, so a ball
  /// under it has left the world whatever bounds the file declared (see inside()).
  double floor_y = -1e300;
  double follow_cos = std::cos(kFollowAngle);
  SweepMethod method = SweepMethod::BvhExact;

  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &config};
  mutable btSphereShape sphere{0.02};  // SweepMethod::BulletConvexSweep only

  // Height grid over the xz extent of the collision triangles: per cell the highest point
  // of any triangle overlapping it, and of any steep (wall) triangle.
  double cell = 4.0;
  double gx0 = 0.0, gz0 = 0.0;
  int nx = 0, nz = 0;
  std::vector<double> top;        // -inf where empty
  std::vector<double> steep_top;  // -inf where no steep triangle

  /// Cell range covering [x0, x1] × [z0, z1]; false when it misses the grid entirely.
  bool cells(double x0, double x1, double z0, double z1, int* i0, int* i1, int* k0, int* k1) const {
    *i0 = static_cast<int>(std::floor((x0 - gx0) / cell));
    *i1 = static_cast<int>(std::floor((x1 - gx0) / cell));
    *k0 = static_cast<int>(std::floor((z0 - gz0) / cell));
    *k1 = static_cast<int>(std::floor((z1 - gz0) / cell));
    if (*i1 < 0 || *k1 < 0 || *i0 >= nx || *k0 >= nz) return false;
    *i0 = std::max(*i0, 0);
    *k0 = std::max(*k0, 0);
    *i1 = std::min(*i1, nx - 1);
    *k1 = std::min(*k1, nz - 1);
    return true;
  }

  double highest(const std::vector<double>& grid, const Vec3& a, const Vec3& b, double r) const {
    int i0, i1, k0, k1;
    if (!cells(std::min(a.x(), b.x()) - r, std::max(a.x(), b.x()) + r, std::min(a.z(), b.z()) - r,
               std::max(a.z(), b.z()) + r, &i0, &i1, &k0, &k1))
      return -std::numeric_limits<double>::infinity();
    double h = -std::numeric_limits<double>::infinity();
    for (int k = k0; k <= k1; ++k)
      for (int i = i0; i <= i1; ++i) h = std::max(h, grid[static_cast<size_t>(k * nx + i)]);
    return h;
  }

  void build_grid() {
    double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
    for (const auto& m : meshes)
      for (size_t i = 0; i < m.vertices.size(); i += 3) {
        x0 = std::min(x0, m.vertices[i]);
        x1 = std::max(x1, m.vertices[i]);
        z0 = std::min(z0, m.vertices[i + 2]);
        z1 = std::max(z1, m.vertices[i + 2]);
      }
    if (x0 > x1) return;  // no collision geometry: nothing can ever be touched
    cell = std::max({4.0, (x1 - x0) / 512.0, (z1 - z0) / 512.0});
    gx0 = x0;
    gz0 = z0;
    nx = static_cast<int>(std::floor((x1 - x0) / cell)) + 1;
    nz = static_cast<int>(std::floor((z1 - z0) / cell)) + 1;
    const double empty = -std::numeric_limits<double>::infinity();
    top.assign(static_cast<size_t>(nx * nz), empty);
    steep_top.assign(static_cast<size_t>(nx * nz), empty);
    for (const auto& m : meshes) {
      const int n = static_cast<int>(m.indices.size() / 3);
      for (int t = 0; t < n; ++t) {
        const Vec3 a = m.vertex(t, 0), b = m.vertex(t, 1), c = m.vertex(t, 2);
        const double ytop = std::max({a.y(), b.y(), c.y()});
        const bool steep = m.normals[static_cast<size_t>(t)].y() < follow_cos;
        int i0, i1, k0, k1;
        if (!cells(std::min({a.x(), b.x(), c.x()}), std::max({a.x(), b.x(), c.x()}),
                   std::min({a.z(), b.z(), c.z()}), std::max({a.z(), b.z(), c.z()}), &i0, &i1, &k0, &k1))
          continue;
        for (int k = k0; k <= k1; ++k)
          for (int i = i0; i <= i1; ++i) {
            const auto idx = static_cast<size_t>(k * nx + i);
            top[idx] = std::max(top[idx], ytop);
            if (steep) steep_top[idx] = std::max(steep_top[idx], ytop);
          }
      }
    }
  }

  /// Edge adjacency across all meshes (edges matched by their end points), so a rolling
  /// ball that leaves its triangle usually finds the next one without a Bullet query.
  void build_adjacency() {
    using Key = std::array<double, 6>;
    std::map<Key, std::vector<std::pair<TriRef, int>>> edges;
    for (size_t mi = 0; mi < meshes.size(); ++mi) {
      CollisionMesh& m = meshes[mi];
      const int n = static_cast<int>(m.indices.size() / 3);
      m.neighbours.assign(static_cast<size_t>(n), {});
      for (int t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
          Vec3 a = m.vertex(t, k), b = m.vertex(t, (k + 1) % 3);
          if (std::lexicographical_compare(b.data(), b.data() + 3, a.data(), a.data() + 3)) std::swap(a, b);
          edges[Key{a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}].push_back({TriRef{static_cast<int>(mi), t}, k});
        }
    }
    for (const auto& [key, list] : edges) {
      if (list.size() != 2) continue;  // boundary or non-manifold edge: leave it to the ray
      for (int s = 0; s < 2; ++s) {
        const auto& [self, k] = list[static_cast<size_t>(s)];
        meshes[static_cast<size_t>(self.mesh)].neighbours[static_cast<size_t>(self.tri)][static_cast<size_t>(k)] =
            list[static_cast<size_t>(1 - s)].first;
      }
    }
  }

  void fill(SurfaceContact* hit, int mesh, int tri, const Vec3& centre, double fraction) const {
    const CollisionMesh& m = meshes[static_cast<size_t>(mesh)];
    const Vec3& n = m.normals[static_cast<size_t>(tri)];
    hit->fraction = fraction;
    hit->normal = n;
    hit->point = centre - n * n.dot(centre - m.vertex(tri, 0));  // foot of the centre on the plane
    hit->material = m.material;
    hit->mesh = mesh;
    hit->triangle = tri;
  }

  /// Whether the foot of `centre` on the triangle's plane lies inside the triangle.
  bool over_triangle(int mesh, int tri, const Vec3& centre) const {
    const CollisionMesh& m = meshes[static_cast<size_t>(mesh)];
    const Vec3 a = m.vertex(tri, 0), b = m.vertex(tri, 1), c = m.vertex(tri, 2);
    const Vec3& n = m.normals[static_cast<size_t>(tri)];
    const Vec3 p = centre - n * n.dot(centre - a);
    constexpr double eps = -1e-12;
    return n.dot((b - a).cross(p - a)) >= eps && n.dot((c - b).cross(p - b)) >= eps &&
           n.dot((a - c).cross(p - c)) >= eps;
  }
};

namespace {

/// Bullet's BVH hands over the triangles whose boxes overlap the sweep's box; each is tested
/// exactly (sphere_triangle_sweep) and the earliest face the ball moves into is kept.
struct SweepCallback final : btTriangleCallback {
  const CollisionMesh* mesh = nullptr;
  Vec3 from = Vec3::Zero();
  Vec3 motion = Vec3::Zero();
  Vec3 direction = Vec3::Zero();
  double radius = 0.0;
  const Vec3* follow = nullptr;
  double follow_cos = 1.0;
  double best = 1.0;
  int triangle = -1;

  void processTriangle(btVector3* /*corners*/, int /*part*/, int t) override {
    const Vec3& n = mesh->normals[static_cast<size_t>(t)];
    // Only faces the ball moves into; edge or corner normals are ignored on purpose.
    if (n.dot(direction) >= -1e-9) return;
    if (follow != nullptr && n.dot(*follow) >= follow_cos) return;
    double f = 0.0;
    if (sphere_triangle_sweep(from, motion, radius, mesh->vertex(t, 0), mesh->vertex(t, 1), mesh->vertex(t, 2), &f) &&
        (triangle < 0 ? f <= best : f < best)) {
      best = f;
      triangle = t;
    }
  }
};

struct ConvexSweepCallback final : btCollisionWorld::ConvexResultCallback {
  const std::vector<CollisionMesh>* meshes = nullptr;
  Vec3 direction = Vec3::Zero();
  const Vec3* follow = nullptr;
  double follow_cos = 1.0;
  int mesh = -1;
  int triangle = -1;

  btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool /*normal_in_world*/) override {
    if (r.m_localShapeInfo == nullptr) return m_closestHitFraction;
    const int m = r.m_hitCollisionObject->getUserIndex2();
    const int t = r.m_localShapeInfo->m_triangleIndex;
    const Vec3& n = (*meshes)[static_cast<size_t>(m)].normals[static_cast<size_t>(t)];
    // Same filter as SweepCallback: faces the ball moves into, Bullet's own normal ignored.
    if (n.dot(direction) >= -1e-9) return m_closestHitFraction;
    if (follow != nullptr && n.dot(*follow) >= follow_cos) return m_closestHitFraction;
    if (r.m_hitFraction < m_closestHitFraction) {
      m_closestHitFraction = r.m_hitFraction;
      mesh = m;
      triangle = t;
    }
    return m_closestHitFraction;
  }
};

/// Bullet's per-shape ray cast (the BVH walk and the ray-triangle test are Bullet's); only
/// faces that look up count as ground. Reads the shape only, so queries may run in parallel.
struct RayCallback final : btTriangleRaycastCallback {
  const CollisionMesh* mesh = nullptr;
  int triangle = -1;

  RayCallback(const btVector3& from, const btVector3& to, double best) : btTriangleRaycastCallback(from, to) {
    m_hitFraction = best;
  }

  btScalar reportHit(const btVector3& /*normal*/, btScalar fraction, int /*part*/, int t) override {
    // Ground only: a face that looks up (walls are met by sweeps, not stood on).
    if (mesh->normals[static_cast<size_t>(t)].y() <= 0.1) return m_hitFraction;
    if (fraction < m_hitFraction) triangle = t;
    return std::min(fraction, m_hitFraction);
  }
};

}  // namespace

std::string validate_world(const WorldDescription& d) {
  std::ostringstream s;
  const std::string w = "world '" + d.name + "': ";
  if (d.materials.empty()) return w + "no materials";
  for (const auto& m : d.materials) {
    const std::string why = validate_surface_material(m);
    if (!why.empty()) return w + why;
  }
  for (size_t i = 0; i < d.meshes.size(); ++i) {
    const WorldMesh& m = d.meshes[i];
    if (m.material < 0 || static_cast<size_t>(m.material) >= d.materials.size()) {
      s << w << "mesh " << i << " has material " << m.material << " (allowed 0.." << d.materials.size() - 1 << ")";
      return s.str();
    }
    if (m.indices.size() % 3 != 0) {
      s << w << "mesh " << i << " has " << m.indices.size() << " indices (not a multiple of 3)";
      return s.str();
    }
    for (size_t v = 0; v < m.vertices.size(); ++v)
      if (!finite(m.vertices[v])) {
        s << w << "mesh " << i << " (" << d.materials[static_cast<size_t>(m.material)].name << ") vertex " << v
          << " is not a finite number";
        return s.str();
      }
    for (size_t k = 0; k < m.indices.size(); ++k)
      if (m.indices[k] >= m.vertices.size()) {
        s << w << "mesh " << i << " index " << k << " = " << m.indices[k] << " is out of range (allowed 0.."
          << (m.vertices.empty() ? 0 : m.vertices.size() - 1) << ")";
        return s.str();
      }
  }
  if (!finite(d.origin) || !finite(d.bounds_min) || !finite(d.bounds_max) ||
      !(d.bounds_min.array() < d.bounds_max.array()).all())
    return w + "bounds must be finite with bounds_min < bounds_max";
  return {};
}

World::World(WorldDescription description, SweepMethod method) : impl_(std::make_unique<Impl>()) {
  impl_->method = method;
  const std::string why = validate_world(description);
  if (!why.empty()) throw InputError(why);
  Impl& w = *impl_;
  w.desc = std::move(description);
  const WorldDescription& d = w.desc;

  // Merge meshes per material, dropping decorations and zero-area triangles.
  std::vector<int> slot(d.materials.size(), -1);
  int dropped = 0;
  for (const WorldMesh& src : d.meshes) {
    const SurfaceMaterial& mat = d.materials[static_cast<size_t>(src.material)];
    if (mat.kind == SurfaceKind::Decoration) continue;
    int& s = slot[static_cast<size_t>(src.material)];
    if (s < 0) {
      s = static_cast<int>(w.meshes.size());
      w.meshes.emplace_back();
      w.meshes.back().material = src.material;
    }
    CollisionMesh& dst = w.meshes[static_cast<size_t>(s)];
    const int base = static_cast<int>(dst.vertices.size() / 3);
    for (const Vec3& v : src.vertices) {
      dst.vertices.push_back(v.x());
      dst.vertices.push_back(v.y());
      dst.vertices.push_back(v.z());
    }
    for (size_t k = 0; k + 2 < src.indices.size(); k += 3) {
      const Vec3& a = src.vertices[src.indices[k]];
      const Vec3& b = src.vertices[src.indices[k + 1]];
      const Vec3& c = src.vertices[src.indices[k + 2]];
      const Vec3 cross = (b - a).cross(c - a);
      const double scale = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), 1e-300});
      if (!(cross.norm() > 1e-12 * scale)) {
        ++dropped;  // zero-area (or needle) triangle: no normal, skip it
        continue;
      }
      dst.indices.push_back(base + static_cast<int>(src.indices[k]));
      dst.indices.push_back(base + static_cast<int>(src.indices[k + 1]));
      dst.indices.push_back(base + static_cast<int>(src.indices[k + 2]));
      dst.normals.push_back(cross.normalized());
    }
  }
  if (dropped > 0) {
    std::ostringstream s;
    s << "dropped " << dropped << " zero-area triangle" << (dropped == 1 ? "" : "s");
    w.desc.notes.push_back(s.str());
  }
  w.meshes.erase(std::remove_if(w.meshes.begin(), w.meshes.end(),
                                [](const CollisionMesh& m) { return m.indices.empty(); }),
                 w.meshes.end());
  // The floor: 1 m (many ball diameters) under the lowest collidable vertex and the origin.
  // A ball that falls past the edge of the ground would otherwise fall to the declared
  // bounds (±10 km by default) and run into the step limit (a fuzz_world finding).
  double lowest = d.origin.y();
  for (const CollisionMesh& m : w.meshes)
    for (size_t k = 1; k < m.vertices.size(); k += 3) lowest = std::min(lowest, m.vertices[k]);
  w.floor_y = lowest - 1.0;

  for (size_t i = 0; i < w.meshes.size(); ++i) {
    CollisionMesh& m = w.meshes[i];
    btIndexedMesh im;
    im.m_numTriangles = static_cast<int>(m.indices.size() / 3);
    im.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(m.indices.data());
    im.m_triangleIndexStride = 3 * static_cast<int>(sizeof(int));
    im.m_numVertices = static_cast<int>(m.vertices.size() / 3);
    im.m_vertexBase = reinterpret_cast<const unsigned char*>(m.vertices.data());
    im.m_vertexStride = 3 * static_cast<int>(sizeof(double));
    im.m_indexType = PHY_INTEGER;
    im.m_vertexType = PHY_DOUBLE;
    m.array = std::make_unique<btTriangleIndexVertexArray>();
    m.array->addIndexedMesh(im, PHY_INTEGER);
    m.shape = std::make_unique<btBvhTriangleMeshShape>(m.array.get(), true, true);
    m.object = std::make_unique<btCollisionObject>();
    m.object->setCollisionShape(m.shape.get());
    m.object->setUserIndex(m.material);
    m.object->setUserIndex2(static_cast<int>(i));
    w.world.addCollisionObject(m.object.get());
    w.triangles += im.m_numTriangles;
  }
  w.world.updateAabbs();
  w.build_grid();
  w.build_adjacency();
}

World::~World() {
  for (auto& m : impl_->meshes) impl_->world.removeCollisionObject(m.object.get());
}

const WorldDescription& World::description() const { return impl_->desc; }
int World::collision_triangles() const { return impl_->triangles; }

bool World::sweep(const Vec3& from, const Vec3& to, double radius, SurfaceContact* hit,
                  const Vec3* follow) const {
  const Vec3 motion = to - from;
  const double len = motion.norm();
  if (!(len > 0.0)) return false;
  const Impl& w = *impl_;
  if (w.method == SweepMethod::BulletConvexSweep) {
    w.sphere.setUnscaledRadius(radius);
    ConvexSweepCallback cb;
    cb.meshes = &w.meshes;
    cb.direction = motion / len;
    cb.follow = follow;
    cb.follow_cos = w.follow_cos;
    btTransform a, b;
    a.setIdentity();
    b.setIdentity();
    a.setOrigin(bt(from));
    b.setOrigin(bt(to));
    w.world.convexSweepTest(&w.sphere, a, b, cb, 0.0);
    if (cb.mesh < 0) return false;
    const double f = cb.m_closestHitFraction;
    w.fill(hit, cb.mesh, cb.triangle, from + f * motion, f);
    return true;
  }
  const Vec3 lo = from.cwiseMin(to) - Vec3::Constant(radius + 1e-6);
  const Vec3 hi = from.cwiseMax(to) + Vec3::Constant(radius + 1e-6);
  int best_mesh = -1, best_tri = -1;
  double best = 1.0;
  for (size_t i = 0; i < w.meshes.size(); ++i) {
    SweepCallback cb;
    cb.mesh = &w.meshes[i];
    cb.from = from;
    cb.motion = motion;
    cb.direction = motion / len;
    cb.radius = radius;
    cb.follow = follow;
    cb.follow_cos = w.follow_cos;
    cb.best = best;
    w.meshes[i].shape->processAllTriangles(&cb, bt(lo), bt(hi));
    if (cb.triangle >= 0 && (best_mesh < 0 || cb.best < best)) {
      best = cb.best;
      best_mesh = static_cast<int>(i);
      best_tri = cb.triangle;
    }
  }
  if (best_mesh < 0) return false;
  w.fill(hit, best_mesh, best_tri, from + best * motion, best);
  return true;
}

bool World::support(const Vec3& centre, double radius, double reach, SurfaceContact* hit) const {
  const Impl& w = *impl_;
  int mesh = -1, tri = -1;
  if (hit->mesh >= 0 && hit->triangle >= 0 && static_cast<size_t>(hit->mesh) < w.meshes.size()) {
    if (w.over_triangle(hit->mesh, hit->triangle, centre)) {
      mesh = hit->mesh;  // still over the same triangle: no Bullet query
      tri = hit->triangle;
      // At a concave edge a rising neighbour can already cut into the ball while the contact
      // point is still on this triangle (a random-world soak finding: rolling centres 1-9 cm
      // inside the ground). The neighbour the ball overlaps most becomes the support; the
      // roll then steps onto it or strikes it. Concave only: a neighbour beyond a ridge lies
      // below this plane and never lifts the ball.
      const CollisionMesh& cm = w.meshes[static_cast<size_t>(mesh)];
      const Vec3 n0 = cm.normals[static_cast<size_t>(tri)];
      const Vec3 c0 = (cm.vertex(tri, 0) + cm.vertex(tri, 1) + cm.vertex(tri, 2)) / 3.0;
      double deepest = n0.dot(centre - cm.vertex(tri, 0)) - radius;
      const auto neighbours = cm.neighbours[static_cast<size_t>(tri)];
      for (const TriRef& nb : neighbours) {
        if (nb.mesh < 0) continue;
        const CollisionMesh& nm = w.meshes[static_cast<size_t>(nb.mesh)];
        const Vec3& nn = nm.normals[static_cast<size_t>(nb.tri)];
        const Vec3 a = nm.vertex(nb.tri, 0), b = nm.vertex(nb.tri, 1), c = nm.vertex(nb.tri, 2);
        if (nn.y() <= 0.1 || n0.dot((a + b + c) / 3.0 - c0) <= 0.0) continue;  // not a rising floor
        if ((closest_point_on_triangle(centre, a, b, c) - centre).squaredNorm() >= radius * radius) continue;
        const double g = nn.dot(centre - a) - radius;
        if (g < deepest) {
          deepest = g;
          mesh = nb.mesh;
          tri = nb.tri;
        }
      }
    } else {
      for (const TriRef& nb : w.meshes[static_cast<size_t>(hit->mesh)].neighbours[static_cast<size_t>(hit->triangle)]) {
        if (nb.mesh >= 0 && w.meshes[static_cast<size_t>(nb.mesh)].normals[static_cast<size_t>(nb.tri)].y() > 0.1 &&
            w.over_triangle(nb.mesh, nb.tri, centre)) {
          mesh = nb.mesh;  // rolled onto a neighbour
          tri = nb.tri;
          break;
        }
      }
    }
  }
  if (mesh < 0) {
    // Straight down far enough to find a 60° slope under the ball.
    const btVector3 top = bt(centre + Vec3(0.0, radius, 0.0));
    const btVector3 bottom = bt(centre - Vec3(0.0, 2.0 * radius + reach + 0.05, 0.0));
    double best = 1.0;
    for (size_t i = 0; i < w.meshes.size(); ++i) {
      RayCallback cb(top, bottom, best);
      cb.mesh = &w.meshes[i];
      w.meshes[i].shape->performRaycast(&cb, top, bottom);
      if (cb.triangle >= 0) {
        best = cb.m_hitFraction;
        mesh = static_cast<int>(i);
        tri = cb.triangle;
      }
    }
    if (mesh < 0) return false;
  }
  const CollisionMesh& m = w.meshes[static_cast<size_t>(mesh)];
  const double gap = m.normals[static_cast<size_t>(tri)].dot(centre - m.vertex(tri, 0)) - radius;
  if (gap > reach) return false;
  w.fill(hit, mesh, tri, centre, 0.0);
  return true;
}

bool World::may_touch(const Vec3& from, const Vec3& to, double radius) const {
  return std::min(from.y(), to.y()) - radius <= impl_->highest(impl_->top, from, to, radius);
}

bool World::may_touch_steep(const Vec3& from, const Vec3& to, double radius) const {
  return std::min(from.y(), to.y()) - radius <= impl_->highest(impl_->steep_top, from, to, radius);
}

const SurfaceMaterial& World::material(int index) const {
  return impl_->desc.materials[static_cast<size_t>(index)];
}

bool World::inside(const Vec3& c) const {
  const WorldDescription& d = impl_->desc;
  return (c.array() >= d.bounds_min.array()).all() && (c.array() <= d.bounds_max.array()).all() &&
         c.y() >= impl_->floor_y;
}

double World::reference_height() const { return impl_->desc.origin.y(); }

}  // namespace sweetspot
