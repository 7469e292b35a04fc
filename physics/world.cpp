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

}  // namespace

// World::Impl's parts: named (not anonymous) because Impl, a class with linkage, holds them.
namespace world_parts {

struct TriRef {
  int mesh = -1;
  int tri = -1;
};

/// Triangles of one material: one part of the world's single Bullet shape (the part index
/// is the mesh index). Bullet reads the arrays in place, so they must outlive the shape and
/// never reallocate after it is built.
struct CollisionMesh {
  int material = 0;
  std::vector<double> vertices;  // xyz
  std::vector<int> indices;      // 3 per triangle
  std::vector<Vec3> normals;     // unit face normal per triangle
  std::vector<std::array<TriRef, 3>> neighbours;  // across edge k = (corner k, corner k+1), any mesh
  std::vector<std::array<Vec3, 3>> corner_normals;  // per corner: the smooth surface's normal (bounce_normal)
  std::vector<char> twinned;     // per triangle: a copy with the same corners faces the other way

  Vec3 vertex(int tri, int corner) const {
    const auto i = static_cast<size_t>(indices[static_cast<size_t>(3 * tri + corner)]) * 3;
    return Vec3(vertices[i], vertices[i + 1], vertices[i + 2]);
  }
};

struct CellTriangle {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  ///< the triangle's box
  int mesh = 0;
  int tri = 0;
};

}  // namespace world_parts

using world_parts::CellTriangle;
using world_parts::CollisionMesh;
using world_parts::TriRef;

namespace {

/// Sweeps whose boxes cover more grid cells than this walk Bullet's tree instead.
constexpr int kMaxGridCells = 16;
/// A triangle over more cells than this (a big flat quad, a hostile mesh of world-sized
/// triangles) is kept in one list every short sweep tests, not in each cell: the lists
/// stay linear in the triangle count whatever the mesh.
constexpr int kMaxCellsPerTriangle = 64;
/// More such triangles than this and short sweeps walk Bullet's tree too.
constexpr std::size_t kMaxLargeTriangles = 256;

}  // namespace

struct World::Impl {
  WorldDescription desc;
  std::vector<CollisionMesh> meshes;
  /// All meshes as the parts of one Bullet BVH: a query walks one tree, not one per
  /// material (six trees on golf_hole would make the sweeps a third of a shot's cost).
  std::unique_ptr<btTriangleIndexVertexArray> array;
  std::unique_ptr<btBvhTriangleMeshShape> shape;
  std::unique_ptr<btCollisionObject> object;
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
  double inv_cell = 0.25;  // 1/cell
  double gx0 = 0.0, gz0 = 0.0;
  int nx = 0, nz = 0;
  /// Per cell (compressed rows: cell c's entries are [cell_start[c], cell_start[c + 1])) the
  /// collidable triangles whose boxes overlap it, with their boxes: a short sweep tests
  /// these instead of walking Bullet's tree (a walk costs ~5k instructions on golf_hole's
  /// 21k triangles, a cell's list ~10 box tests). Exact either way: a triangle
  /// whose box misses the sweep's box (which holds the whole swept sphere) cannot be hit.
  std::vector<int> cell_start;
  std::vector<CellTriangle> cell_triangles;
  std::vector<CellTriangle> large_triangles;  // over more than kMaxCellsPerTriangle cells
  bool grid_sweeps = true;                     // false: too many large triangles, walk the tree
  std::vector<double> top;        // -inf where empty
  std::vector<double> steep_top;  // -inf where no steep triangle
  double top_max = -std::numeric_limits<double>::infinity();    // max of top
  double steep_max = -std::numeric_limits<double>::infinity();  // max of steep_top

  /// floor(x) as a cell index, clamped far outside any grid (a grid has at most 513 cells a
  /// side) so the conversion is always defined. Without SSE4.1 std::floor is a libm call: a
  /// truncation and one correction are exact and ~10 times cheaper (four per query).
  static int floor_index(double x) {
    constexpr double kFar = 1e6;
    if (!(x > -kFar)) return -static_cast<int>(kFar);  // also NaN: off the grid
    if (x > kFar) return static_cast<int>(kFar);
    const int i = static_cast<int>(x);
    return static_cast<double>(i) > x ? i - 1 : i;
  }

  /// Cell range covering [x0, x1] × [z0, z1]; false when it misses the grid entirely.
  bool cells(double x0, double x1, double z0, double z1, int* i0, int* i1, int* k0, int* k1) const {
    // One reciprocal for the four: x·(1/cell) is monotonic in x like x/cell, so the grid's
    // build and every query still agree on which cells a box covers.
    *i0 = floor_index((x0 - gx0) * inv_cell);
    *i1 = floor_index((x1 - gx0) * inv_cell);
    *k0 = floor_index((z0 - gz0) * inv_cell);
    *k1 = floor_index((z1 - gz0) * inv_cell);
    if (*i1 < 0 || *k1 < 0 || *i0 >= nx || *k0 >= nz) return false;
    *i0 = std::max(*i0, 0);
    *k0 = std::max(*k0, 0);
    *i1 = std::min(*i1, nx - 1);
    *k1 = std::min(*k1, nz - 1);
    return true;
  }

  double highest(const std::vector<double>& grid, const Vec3& a, const Vec3& b, double r) const {
    // Most airborne chords pass above everything: one comparison instead of a cell walk.
    const double grid_top = &grid == &top ? top_max : steep_max;
    if (std::min(a.y(), b.y()) - r > grid_top) return grid_top;
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
    inv_cell = 1.0 / cell;
    gx0 = x0;
    gz0 = z0;
    nx = static_cast<int>(std::floor((x1 - x0) / cell)) + 1;
    nz = static_cast<int>(std::floor((z1 - z0) / cell)) + 1;
    const double empty = -std::numeric_limits<double>::infinity();
    top.assign(static_cast<size_t>(nx * nz), empty);
    steep_top.assign(static_cast<size_t>(nx * nz), empty);
    // Two passes over the triangles: count the entries per cell, then fill them.
    cell_start.assign(static_cast<size_t>(nx * nz) + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill;
      if (pass == 1) {
        for (size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
        cell_triangles.resize(static_cast<size_t>(cell_start.back()));
        fill.assign(cell_start.begin(), cell_start.end() - 1);
      }
      for (size_t mi = 0; mi < meshes.size(); ++mi) {
        const CollisionMesh& m = meshes[mi];
        const int n = static_cast<int>(m.indices.size() / 3);
        for (int t = 0; t < n; ++t) {
          const Vec3 a = m.vertex(t, 0), b = m.vertex(t, 1), c = m.vertex(t, 2);
          const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
          const bool steep = m.normals[static_cast<size_t>(t)].y() < follow_cos;
          int i0, i1, k0, k1;
          if (!cells(lo.x(), hi.x(), lo.z(), hi.z(), &i0, &i1, &k0, &k1)) continue;
          const bool large = (i1 - i0 + 1) * (k1 - k0 + 1) > kMaxCellsPerTriangle;
          if (large && pass == 1) large_triangles.push_back(CellTriangle{lo, hi, static_cast<int>(mi), t});
          for (int k = k0; k <= k1; ++k)
            for (int i = i0; i <= i1; ++i) {
              const auto idx = static_cast<size_t>(k * nx + i);
              if (pass == 0) {
                top[idx] = std::max(top[idx], hi.y());
                if (steep) steep_top[idx] = std::max(steep_top[idx], hi.y());
                if (!large) ++cell_start[idx + 1];
              } else if (!large) {
                cell_triangles[static_cast<size_t>(fill[idx]++)] = CellTriangle{lo, hi, static_cast<int>(mi), t};
              }
            }
        }
      }
    }
    grid_sweeps = large_triangles.size() <= kMaxLargeTriangles;
    for (const double h : top) top_max = std::max(top_max, h);
    for (const double h : steep_top) steep_max = std::max(steep_max, h);
  }

  /// Edge adjacency across all meshes (edges matched by their end points), so a rolling
  /// ball that leaves its triangle usually finds the next one without a Bullet query.
  /// Corner normals for bounce_normal: at each corner, the faces (any mesh) sharing that
  /// vertex position and within kSmoothAngle of the corner's own face, weighted by their
  /// angle at the vertex (the usual weighting: independent of how a face is split). Facets
  /// of gently rolling ground differ by a degree or two (golf_hole: under 3°); a bend of
  /// more than 10° is a feature the ball should meet as modelled (a bank, a lip, a ditch).
  static constexpr double kSmoothCos = 0.98480775301220802;  // cos 10°
  void build_corner_normals() {
    using Key = std::array<double, 3>;
    std::map<Key, std::vector<std::pair<Vec3, double>>> at;  // face normal, corner angle
    const auto angle_at = [](const CollisionMesh& m, int t, int k) {
      const Vec3 p = m.vertex(t, k);
      const Vec3 a = (m.vertex(t, (k + 1) % 3) - p).normalized(), b = (m.vertex(t, (k + 2) % 3) - p).normalized();
      return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
    };
    for (const CollisionMesh& m : meshes) {
      const int n = static_cast<int>(m.indices.size() / 3);
      for (int t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
          const Vec3 p = m.vertex(t, k);
          at[Key{p.x(), p.y(), p.z()}].push_back({m.normals[static_cast<size_t>(t)], angle_at(m, t, k)});
        }
    }
    for (CollisionMesh& m : meshes) {
      const int n = static_cast<int>(m.indices.size() / 3);
      m.corner_normals.assign(static_cast<size_t>(n), {});
      for (int t = 0; t < n; ++t) {
        const Vec3& own = m.normals[static_cast<size_t>(t)];
        for (int k = 0; k < 3; ++k) {
          const Vec3 p = m.vertex(t, k);
          Vec3 sum = Vec3::Zero();
          for (const auto& [normal, angle] : at[Key{p.x(), p.y(), p.z()}])
            if (normal.dot(own) >= kSmoothCos) sum += angle * normal;
          m.corner_normals[static_cast<size_t>(t)][static_cast<size_t>(k)] = sum.norm() > 0.0 ? Vec3(sum.normalized()) : own;
        }
      }
    }
  }

  /// A two-sided sheet is modelled as two triangles on the same corners, facing opposite
  /// ways. Faces are one-sided (a ball meets a face it moves into), so a ball resting on
  /// the sheet and lifting off moves into the back copy while touching it and would be
  /// stopped dead (a two-sided ground would end every drive at the tee).
  /// Such twins are marked; a sweep meets a twin only from its front (SweepCallback).
  void build_twins() {
    using Key = std::array<double, 9>;  // the three corners, sorted
    std::map<Key, std::vector<TriRef>> by_corners;
    for (size_t mi = 0; mi < meshes.size(); ++mi) {
      CollisionMesh& m = meshes[mi];
      const int n = static_cast<int>(m.indices.size() / 3);
      m.twinned.assign(static_cast<size_t>(n), 0);
      for (int t = 0; t < n; ++t) {
        std::array<std::array<double, 3>, 3> c;
        for (int k = 0; k < 3; ++k) {
          const Vec3 p = m.vertex(t, k);
          c[static_cast<size_t>(k)] = {p.x(), p.y(), p.z()};
        }
        std::sort(c.begin(), c.end());
        by_corners[Key{c[0][0], c[0][1], c[0][2], c[1][0], c[1][1], c[1][2], c[2][0], c[2][1], c[2][2]}].push_back(
            TriRef{static_cast<int>(mi), t});
      }
    }
    for (const auto& [key, list] : by_corners)
      for (size_t i = 0; i < list.size(); ++i)
        for (size_t j = i + 1; j < list.size(); ++j) {
          CollisionMesh& a = meshes[static_cast<size_t>(list[i].mesh)];
          CollisionMesh& b = meshes[static_cast<size_t>(list[j].mesh)];
          if (a.normals[static_cast<size_t>(list[i].tri)].dot(b.normals[static_cast<size_t>(list[j].tri)]) < 0.0) {
            a.twinned[static_cast<size_t>(list[i].tri)] = 1;
            b.twinned[static_cast<size_t>(list[j].tri)] = 1;
          }
        }
  }

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

  /// At a concave edge a rising face can already cut into the ball while the foot of its
  /// centre is still on the support triangle (*mesh, *tri): in the random-world soak, rolling
  /// centres would sink 1-9 cm inside the ground, and a ball whose V's far face meets the
  /// support at a corner only (no shared edge) would roll on under it and out of the world.
  /// Every triangle near the ball (the grid's cells under its box; the support's edge
  /// neighbours when the grid is off) that rises from the support's plane and cuts the ball
  /// deeper than the support becomes the support; the roll then steps onto it or strikes it.
  /// Concave only: a face beyond a ridge lies below the support's plane and never lifts the
  /// ball.
  void deepest_rising_floor(const Vec3& centre, double radius, int* mesh, int* tri) const {
    const CollisionMesh& cm = meshes[static_cast<size_t>(*mesh)];
    const Vec3 n0 = cm.normals[static_cast<size_t>(*tri)];
    const Vec3 c0 = (cm.vertex(*tri, 0) + cm.vertex(*tri, 1) + cm.vertex(*tri, 2)) / 3.0;
    double deepest = n0.dot(centre - cm.vertex(*tri, 0)) - radius;
    int best_mesh = *mesh, best_tri = *tri;
    const auto consider = [&](int nb_mesh, int nb_tri) {
      if (nb_mesh < 0 || (nb_mesh == best_mesh && nb_tri == best_tri)) return;
      const CollisionMesh& nm = meshes[static_cast<size_t>(nb_mesh)];
      const Vec3& nn = nm.normals[static_cast<size_t>(nb_tri)];
      if (nn.y() <= 0.1) return;  // a wall or an overhang is struck, never stood on
      const Vec3 a = nm.vertex(nb_tri, 0);
      const double g = nn.dot(centre - a) - radius;
      if (!(g < deepest)) return;  // its plane cuts the ball no deeper: it cannot win (cheap test first)
      const Vec3 b = nm.vertex(nb_tri, 1), c = nm.vertex(nb_tri, 2);
      if (n0.dot((a + b + c) / 3.0 - c0) <= 0.0) return;  // not rising from the support
      if ((closest_point_on_triangle(centre, a, b, c) - centre).squaredNorm() >= radius * radius) return;
      deepest = g;
      best_mesh = nb_mesh;
      best_tri = nb_tri;
    };
    const Vec3 lo = centre - Vec3::Constant(radius), hi = centre + Vec3::Constant(radius);
    int i0, i1, k0, k1;
    if (grid_sweeps && cells(lo.x(), hi.x(), lo.z(), hi.z(), &i0, &i1, &k0, &k1)) {
      for (const CellTriangle& c : large_triangles)
        if ((c.lo.array() <= hi.array()).all() && (c.hi.array() >= lo.array()).all()) consider(c.mesh, c.tri);
      for (int k = k0; k <= k1; ++k)
        for (int i = i0; i <= i1; ++i) {
          const auto cell = static_cast<size_t>(k * nx + i);
          for (int e = cell_start[cell]; e < cell_start[cell + 1]; ++e) {
            const CellTriangle& c = cell_triangles[static_cast<size_t>(e)];
            if ((c.lo.array() <= hi.array()).all() && (c.hi.array() >= lo.array()).all()) consider(c.mesh, c.tri);
          }
        }
    } else {
      for (const TriRef& nb : cm.neighbours[static_cast<size_t>(*tri)]) consider(nb.mesh, nb.tri);
    }
    *mesh = best_mesh;
    *tri = best_tri;
  }
};

namespace {

/// Bullet's BVH hands over the triangles whose boxes overlap the sweep's box; each is tested
/// exactly (sphere_triangle_sweep) and the earliest face the ball moves into is kept. Ties
/// (a shared edge met exactly) go to the lowest (mesh, triangle), whatever the walk's order.
struct SweepCallback final : btTriangleCallback {
  const std::vector<CollisionMesh>* meshes = nullptr;
  Vec3 from = Vec3::Zero();
  Vec3 motion = Vec3::Zero();
  Vec3 direction = Vec3::Zero();
  double radius = 0.0;
  const Vec3* follow = nullptr;
  double follow_cos = 1.0;
  double best = 1.0;
  int mesh = -1;
  int triangle = -1;

  void processTriangle(btVector3* /*corners*/, int part, int t) override {
    const CollisionMesh& m = (*meshes)[static_cast<size_t>(part)];
    const Vec3& n = m.normals[static_cast<size_t>(t)];
    // Only faces the ball moves into; edge or corner normals are ignored on purpose.
    if (n.dot(direction) >= -1e-9) return;
    if (follow != nullptr && n.dot(*follow) >= follow_cos) return;
    // One side of a two-sided sheet: met only by a ball whose centre is in front of it.
    if (m.twinned[static_cast<size_t>(t)] != 0 && n.dot(from - m.vertex(t, 0)) < 0.0) return;
    double f = 0.0;
    if (sphere_triangle_sweep(from, motion, radius, m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2), &f) &&
        (mesh < 0 || f < best || (f == best && std::make_pair(part, t) < std::make_pair(mesh, triangle)))) {
      best = f;
      mesh = part;
      triangle = t;
    }
  }
};

struct ConvexSweepCallback final : btCollisionWorld::ConvexResultCallback {
  const std::vector<CollisionMesh>* meshes = nullptr;
  Vec3 from = Vec3::Zero();
  Vec3 direction = Vec3::Zero();
  const Vec3* follow = nullptr;
  double follow_cos = 1.0;
  int mesh = -1;
  int triangle = -1;

  btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool /*normal_in_world*/) override {
    if (r.m_localShapeInfo == nullptr) return m_closestHitFraction;
    const int m = r.m_localShapeInfo->m_shapePart;
    const int t = r.m_localShapeInfo->m_triangleIndex;
    const Vec3& n = (*meshes)[static_cast<size_t>(m)].normals[static_cast<size_t>(t)];
    // Same filter as SweepCallback: faces the ball moves into, Bullet's own normal ignored.
    const CollisionMesh& cm = (*meshes)[static_cast<size_t>(m)];
    if (n.dot(direction) >= -1e-9) return m_closestHitFraction;
    if (follow != nullptr && n.dot(*follow) >= follow_cos) return m_closestHitFraction;
    if (cm.twinned[static_cast<size_t>(t)] != 0 && n.dot(from - cm.vertex(t, 0)) < 0.0) return m_closestHitFraction;
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
  const std::vector<CollisionMesh>* meshes = nullptr;
  int mesh = -1;
  int triangle = -1;

  RayCallback(const btVector3& from, const btVector3& to, double best) : btTriangleRaycastCallback(from, to) {
    m_hitFraction = best;
  }

  btScalar reportHit(const btVector3& /*normal*/, btScalar fraction, int part, int t) override {
    // Ground only: a face that looks up (walls are met by sweeps, not stood on).
    if ((*meshes)[static_cast<size_t>(part)].normals[static_cast<size_t>(t)].y() <= 0.1) return m_hitFraction;
    if (fraction < m_hitFraction) {
      mesh = part;
      triangle = t;
    }
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
  // bounds (±10 km by default) and run into the step limit.
  double lowest = d.origin.y();
  for (const CollisionMesh& m : w.meshes)
    for (size_t k = 1; k < m.vertices.size(); k += 3) lowest = std::min(lowest, m.vertices[k]);
  w.floor_y = lowest - 1.0;

  w.array = std::make_unique<btTriangleIndexVertexArray>();
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
    w.array->addIndexedMesh(im, PHY_INTEGER);  // part i
    w.triangles += im.m_numTriangles;
  }
  if (!w.meshes.empty()) {
    w.shape = std::make_unique<btBvhTriangleMeshShape>(w.array.get(), true, true);
    w.object = std::make_unique<btCollisionObject>();
    w.object->setCollisionShape(w.shape.get());
    w.world.addCollisionObject(w.object.get());
  }
  w.world.updateAabbs();
  w.build_grid();
  w.build_adjacency();
  w.build_corner_normals();
  w.build_twins();
}

World::~World() {
  if (impl_->object) impl_->world.removeCollisionObject(impl_->object.get());
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
    cb.from = from;
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
  if (!w.shape) return false;
  SweepCallback cb;
  cb.meshes = &w.meshes;
  cb.from = from;
  cb.motion = motion;
  cb.direction = motion / len;
  cb.radius = radius;
  cb.follow = follow;
  cb.follow_cos = w.follow_cos;
  int i0, i1, k0, k1;
  if (!w.cells(lo.x(), hi.x(), lo.z(), hi.z(), &i0, &i1, &k0, &k1)) return false;  // off the grid: no triangle
  if (!w.grid_sweeps || (i1 - i0 + 1) * (k1 - k0 + 1) > kMaxGridCells) {
    w.shape->processAllTriangles(&cb, bt(lo), bt(hi));  // a long sweep: Bullet's tree walk
  } else {
    for (const CellTriangle& c : w.large_triangles)
      if ((c.lo.array() <= hi.array()).all() && (c.hi.array() >= lo.array()).all()) cb.processTriangle(nullptr, c.mesh, c.tri);
    // A short sweep (every sweep near the ground): the triangles listed in the cells under
    // its box, each box-tested first. A triangle in two cells is tested twice, harmlessly
    // (same f; SweepCallback keeps the first of equals by index).
    for (int k = k0; k <= k1; ++k)
      for (int i = i0; i <= i1; ++i) {
        const auto cell = static_cast<size_t>(k * w.nx + i);
        for (int e = w.cell_start[cell]; e < w.cell_start[cell + 1]; ++e) {
          const CellTriangle& c = w.cell_triangles[static_cast<size_t>(e)];
          if ((c.lo.array() <= hi.array()).all() && (c.hi.array() >= lo.array()).all())
            cb.processTriangle(nullptr, c.mesh, c.tri);
        }
      }
  }
  if (cb.mesh < 0) return false;
  w.fill(hit, cb.mesh, cb.triangle, from + cb.best * motion, cb.best);
  return true;
}

bool World::support(const Vec3& centre, double radius, double reach, SurfaceContact* hit) const {
  const Impl& w = *impl_;
  int mesh = -1, tri = -1;
  if (hit->mesh >= 0 && hit->triangle >= 0 && static_cast<size_t>(hit->mesh) < w.meshes.size()) {
    if (w.over_triangle(hit->mesh, hit->triangle, centre)) {
      mesh = hit->mesh;  // still over the same triangle: no Bullet query
      tri = hit->triangle;
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
    if (!w.shape) return false;
    RayCallback cb(top, bottom, 1.0);
    cb.meshes = &w.meshes;
    w.shape->performRaycast(&cb, top, bottom);
    if (cb.mesh < 0) return false;
    mesh = cb.mesh;
    tri = cb.triangle;
  }
  w.deepest_rising_floor(centre, radius, &mesh, &tri);
  const CollisionMesh& m = w.meshes[static_cast<size_t>(mesh)];
  const double gap = m.normals[static_cast<size_t>(tri)].dot(centre - m.vertex(tri, 0)) - radius;
  if (gap > reach) return false;
  w.fill(hit, mesh, tri, centre, 0.0);
  return true;
}

bool World::may_touch(const Vec3& from, const Vec3& to, double radius) const {
  return std::min(from.y(), to.y()) - radius <= top_under(from, to, radius);
}

double World::top_under(const Vec3& from, const Vec3& to, double radius) const {
  return impl_->highest(impl_->top, from, to, radius);
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

void World::refine_contact(const Vec3& centre, SurfaceContact* c) const {
  const Impl& w = *impl_;
  if (c->mesh < 0 || c->triangle < 0 || static_cast<size_t>(c->mesh) >= w.meshes.size()) return;
  if (w.over_triangle(c->mesh, c->triangle, centre)) return;
  // Only a neighbour within the smoothing angle: the same surface across a seam, not a bank
  // or a wall the ball may be touching at their edge.
  for (const TriRef& nb : w.meshes[static_cast<size_t>(c->mesh)].neighbours[static_cast<size_t>(c->triangle)]) {
    if (nb.mesh < 0) continue;
    const Vec3& nn = w.meshes[static_cast<size_t>(nb.mesh)].normals[static_cast<size_t>(nb.tri)];
    if (nn.dot(c->normal) < Impl::kSmoothCos || !w.over_triangle(nb.mesh, nb.tri, centre)) continue;
    w.fill(c, nb.mesh, nb.tri, centre, c->fraction);
    return;
  }
}

Vec3 World::bounce_normal(const SurfaceContact& c) const {
  const Impl& w = *impl_;
  if (c.mesh < 0 || c.triangle < 0 || static_cast<size_t>(c.mesh) >= w.meshes.size()) return c.normal;
  const CollisionMesh& m = w.meshes[static_cast<size_t>(c.mesh)];
  const Vec3 a = m.vertex(c.triangle, 0), b = m.vertex(c.triangle, 1), d = m.vertex(c.triangle, 2);
  // Barycentric weights of the contact point (clamped: a sweep can meet an edge's outside),
  // each scaled by the same 2·area·|n|: the blend is normalised below, so the scale (and the
  // six divisions it would take to remove it) does not matter.
  const Vec3 n = (b - a).cross(d - a);
  const double wa = std::max(0.0, n.dot((b - c.point).cross(d - c.point)));
  const double wb = std::max(0.0, n.dot((d - c.point).cross(a - c.point)));
  const double wd = std::max(0.0, n.dot((a - c.point).cross(b - c.point)));
  if (!(wa + wb + wd > 0.0)) return c.normal;
  const auto& cn = m.corner_normals[static_cast<size_t>(c.triangle)];
  const Vec3 smooth = wa * cn[0] + wb * cn[1] + wd * cn[2];
  return smooth.norm() > 0.0 ? Vec3(smooth.normalized()) : c.normal;
}

}  // namespace sweetspot
