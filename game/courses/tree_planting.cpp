#include "game/courses/tree_planting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace sweetspot {
namespace {

constexpr int kSides = 6;  // a trunk's and a crown's sides

// A stable 64-bit hash (FNV-1a then splitmix64's finaliser): the same trees on every build.
std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}
std::uint64_t hash_text(const std::string& s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const char c : s) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return h;
}
// A share in [0, 1) from (seed, i, j).
double unit(std::uint64_t seed, long long i, long long j, int k) {
  const std::uint64_t h = mix(seed ^ mix(static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ULL ^
                                         mix(static_cast<std::uint64_t>(j) + 0x632be59bd9b4e019ULL * static_cast<std::uint64_t>(k + 1))));
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

// Even-odd: inside the outer ring and none of its holes.
bool ring_holds(const std::vector<LocalPoint>& ring, double x, double z) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const LocalPoint& a = ring[i];
    const LocalPoint& b = ring[j];
    if ((a.z > z) != (b.z > z) && x < (b.x - a.x) * (z - a.z) / (b.z - a.z) + a.x) in = !in;
  }
  return in;
}

struct LocalPolygon {
  std::vector<LocalPoint> outer;
  std::vector<std::vector<LocalPoint>> inners;
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, z0 = HUGE_VAL, z1 = -HUGE_VAL;  ///< the outer ring's box
  void take_box() {
    for (const LocalPoint& q : outer) {
      x0 = std::min(x0, q.x);
      x1 = std::max(x1, q.x);
      z0 = std::min(z0, q.z);
      z1 = std::max(z1, q.z);
    }
  }
  bool holds(double x, double z) const {
    if (outer.size() < 3 || !ring_holds(outer, x, z)) return false;
    for (const auto& h : inners)
      if (h.size() >= 3 && ring_holds(h, x, z)) return false;
    return true;
  }
};

double polygon_area(const std::vector<LocalPoint>& r) {
  double a = 0.0;
  for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) a += r[j].x * r[i].z - r[i].x * r[j].z;
  return 0.5 * std::abs(a);
}

bool plantable(const SurfacePlan& plan, double x, double z) {
  const std::string m = plan.material_at(x, z);
  return m == "rough" || m == "out_of_bounds";
}

}  // namespace

TreePlanting plant_trees(const GolfMap& map, const LocalFrame& frame, const SurfacePlan& plan) {
  TreePlanting out;
  // Only the plan's rectangle can hold a tree: rows and woods are walked inside it alone (a
  // row or a forest drawn across the country costs no more than the course).
  const LocalPoint lo = plan.min(), hi = plan.max();
  const auto inside = [&](const LocalPoint& p) { return p.x >= lo.x && p.x <= hi.x && p.z >= lo.z && p.z <= hi.z; };
  const auto plant = [&](const LocalPoint& p, double height, std::size_t* tally) {
    if (out.trees.size() >= kMaxTrees) {
      ++out.over_limit;
      return;
    }
    if (!inside(p) || !plantable(plan, p.x, p.z)) {
      ++out.left_out;
      return;
    }
    out.trees.push_back({p, height});
    ++*tally;
  };
  for (const MapTrees& t : map.trees) {
    const double h = t.height.value_or(kDefaultTreeHeight);
    if (t.line.size() == 1) {
      plant(frame.to_local(t.line.front()), h, &out.mapped);
      continue;
    }
    // A row: a tree at its start and one each kTreeSpacing along it.
    double carry = 0.0;  // m along the row since the last tree
    LocalPoint prev = frame.to_local(t.line.front());
    plant(prev, h, &out.in_rows);
    for (std::size_t i = 1; i < t.line.size(); ++i) {
      const LocalPoint next = frame.to_local(t.line[i]);
      const double len = std::hypot(next.x - prev.x, next.z - prev.z);
      // The part of the segment inside the plan's rectangle (Liang-Barsky): its trees keep
      // their places along the whole row.
      double u0 = 0.0, u1 = 1.0;
      const double d[2] = {next.x - prev.x, next.z - prev.z}, p0[2] = {prev.x, prev.z};
      const double lo_[2] = {lo.x, lo.z}, hi_[2] = {hi.x, hi.z};
      for (int a = 0; a < 2 && u0 <= u1; ++a) {
        if (std::abs(d[a]) < 1e-12) {
          if (p0[a] < lo_[a] || p0[a] > hi_[a]) u1 = -1.0;
          continue;
        }
        const double t0 = (lo_[a] - p0[a]) / d[a], t1 = (hi_[a] - p0[a]) / d[a];
        u0 = std::max(u0, std::min(t0, t1));
        u1 = std::min(u1, std::max(t0, t1));
      }
      if (len > 0.0 && u0 <= u1) {
        double s = kTreeSpacing - carry;  // m along the segment of its next tree
        if (s < u0 * len) s += std::ceil((u0 * len - s) / kTreeSpacing) * kTreeSpacing;
        for (; s <= u1 * len; s += kTreeSpacing)
          plant({prev.x + (next.x - prev.x) * s / len, prev.z + (next.z - prev.z) * s / len}, h, &out.in_rows);
      }
      carry = std::fmod(carry + len, kTreeSpacing);
      prev = next;
    }
  }
  // Woods: sparser when their area at kTreeSpacing would pass kMaxTrees.
  std::vector<std::pair<const MapArea*, LocalPolygon>> woods;
  double wood_area = 0.0;
  for (const MapArea& a : map.woods)
    for (const MapPolygon& p : a.polygons) {
      LocalPolygon lp;
      for (const GeoPoint& g : p.outer) lp.outer.push_back(frame.to_local(g));
      for (const auto& inner : p.inners) {
        lp.inners.emplace_back();
        for (const GeoPoint& g : inner) lp.inners.back().push_back(frame.to_local(g));
      }
      // Its area within the plan's rectangle, holes out (clearings are common: a course cut
      // through a forest), taken as its box's share inside the rectangle.
      lp.take_box();
      const double box = (lp.x1 - lp.x0) * (lp.z1 - lp.z0);
      const double kept = std::max(0.0, std::min(lp.x1, hi.x) - std::max(lp.x0, lo.x)) *
                          std::max(0.0, std::min(lp.z1, hi.z) - std::max(lp.z0, lo.z));
      if (!(kept > 0.0)) continue;  // wholly off the course's ground
      double area = polygon_area(lp.outer);
      for (const auto& h : lp.inners) area -= polygon_area(h);
      wood_area += std::max(0.0, area) * kept / box;
      woods.emplace_back(&a, std::move(lp));
    }
  const std::size_t room = kMaxTrees > out.trees.size() ? kMaxTrees - out.trees.size() : 0;
  if (wood_area > 0.0 && room > 0) {
    out.wood_spacing = std::max(kTreeSpacing, std::sqrt(wood_area / static_cast<double>(room)));
    const double g = out.wood_spacing;
    std::size_t cells = 0;  // grid cells tried, all woods together
    for (const auto& [area, poly] : woods) {
      const double x0 = std::max(poly.x0, lo.x), x1 = std::min(poly.x1, hi.x);
      const double z0 = std::max(poly.z0, lo.z), z1 = std::min(poly.z1, hi.z);
      const std::uint64_t seed = hash_text(area->element);
      // Grid cells on a world-fixed lattice, each tree jittered within its cell by up to a
      // third of the spacing either way: a wood, not an orchard.
      for (long long i = static_cast<long long>(std::floor(x0 / g)); i * g <= x1 && out.trees.size() < kMaxTrees; ++i)
        for (long long j = static_cast<long long>(std::floor(z0 / g)); j * g <= z1; ++j) {
          if (out.trees.size() >= kMaxTrees || ++cells > kMaxWoodCells) break;
          const double x = (static_cast<double>(i) + 0.5 + (unit(seed, i, j, 0) - 0.5) * 0.67) * g;
          const double z = (static_cast<double>(j) + 0.5 + (unit(seed, i, j, 1) - 0.5) * 0.67) * g;
          if (!poly.holds(x, z)) continue;
          // Heights vary ±20 % about the default (ESTIMATE of a wood's spread).
          plant({x, z}, kDefaultTreeHeight * (0.8 + 0.4 * unit(seed, i, j, 2)), &out.in_woods);
        }
    }
  }
  return out;
}

void add_tree_meshes(SurfaceMesh& mesh, const std::vector<PlantedTree>& trees, const std::vector<double>& base) {
  const auto group = [&](const char* name) -> SurfaceMesh::Group& {
    for (SurfaceMesh::Group& g : mesh.groups)
      if (g.material == name) return g;
    mesh.groups.push_back({name, {}});
    return mesh.groups.back();
  };
  group("trunk");
  group("tree");
  // Both groups exist now: no push_back moves them after this.
  SurfaceMesh::Group* trunk = &group("trunk");
  SurfaceMesh::Group* crown = &group("tree");
  // A triangle with its face turned away from `inside`.
  const auto face = [&](SurfaceMesh::Group& g, std::uint32_t a, std::uint32_t b, std::uint32_t c, const Vec3& inside) {
    const Vec3& A = mesh.vertices[a];
    const Vec3 n = (mesh.vertices[b] - A).cross(mesh.vertices[c] - A);
    if (n.dot((A + mesh.vertices[b] + mesh.vertices[c]) / 3.0 - inside) < 0.0) std::swap(b, c);
    g.triangles.push_back({a, b, c});
  };
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const PlantedTree& tree = trees[t];
    const double y0 = base[t], h = tree.height;
    const double crown_low = y0 + kCrownBase * h, crown_mid = y0 + 0.5 * (1.0 + kCrownBase) * h, top = y0 + h;
    const double r = kCrownRadius * h;
    const auto at = [&](double angle, double radius, double y) {
      mesh.vertices.emplace_back(tree.at.x + radius * std::cos(angle), y, tree.at.z + radius * std::sin(angle));
      return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    };
    // The trunk: a tube from half a metre in the ground to the crown's middle.
    std::uint32_t low[kSides], high[kSides], ring[kSides];
    for (int k = 0; k < kSides; ++k) {
      const double a = 2.0 * kPi * k / kSides;
      low[k] = at(a, kTrunkRadius, y0 - 0.5);
      high[k] = at(a, kTrunkRadius, crown_mid);
    }
    const Vec3 axis_low(tree.at.x, y0, tree.at.z), axis_mid(tree.at.x, crown_mid, tree.at.z);
    for (int k = 0; k < kSides; ++k) {
      const int n = (k + 1) % kSides;
      face(*trunk, low[k], low[n], high[n], axis_low);
      face(*trunk, low[k], high[n], high[k], axis_low);
    }
    // The crown: six faces up to its top and six down to its foot round the middle ring,
    // turned half a side from the trunk's.
    for (int k = 0; k < kSides; ++k) ring[k] = at(2.0 * kPi * (k + 0.5) / kSides, r, crown_mid);
    const std::uint32_t apex = at(0.0, 0.0, top), foot = at(0.0, 0.0, crown_low);
    for (int k = 0; k < kSides; ++k) {
      const int n = (k + 1) % kSides;
      face(*crown, ring[k], ring[n], apex, axis_mid);
      face(*crown, ring[k], ring[n], foot, axis_mid);
    }
  }
}

}  // namespace sweetspot
