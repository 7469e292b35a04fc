#include "game/courses/terrain_heights.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <utility>

namespace sweetspot {
namespace {

// The smoothing disc: its centre and two rings (6 at half the radius, 12 at the radius),
// weighted as a tent (1, 1/2, 1/4 per point, normalised).
std::vector<std::pair<LocalPoint, double>> disc(const LocalPoint& p, double radius) {
  std::vector<std::pair<LocalPoint, double>> out{{p, 1.0}};
  constexpr double kPi = 3.14159265358979323846;
  for (int i = 0; i < 6; ++i) {
    const double a = 2.0 * kPi * i / 6.0;
    out.push_back({{p.x + 0.5 * radius * std::cos(a), p.z + 0.5 * radius * std::sin(a)}, 0.5});
  }
  for (int i = 0; i < 12; ++i) {
    const double a = 2.0 * kPi * (i + 0.5) / 12.0;
    out.push_back({{p.x + radius * std::cos(a), p.z + radius * std::sin(a)}, 0.25});
  }
  return out;
}

double weighted(const std::vector<std::pair<LocalPoint, double>>& d, const std::vector<double>& h, std::size_t from) {
  double s = 0.0, w = 0.0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    s += d[k].second * h[from + k];
    w += d[k].second;
  }
  return s / w;
}

}  // namespace

double smoothed_height(const ElevationModel& dem, const LocalFrame& frame, const LocalPoint& p) {
  const auto d = disc(p, kGreenSmoothing);
  std::vector<LocalPoint> pts;
  for (const auto& [q, w] : d) pts.push_back(q);
  return weighted(d, dem.heights(frame, pts), 0);
}

double green_slope(const ElevationModel& dem, const LocalFrame& frame, const LocalPoint& p) {
  const double e = smoothed_height(dem, frame, {p.x + 1.0, p.z}), w = smoothed_height(dem, frame, {p.x - 1.0, p.z});
  const double s = smoothed_height(dem, frame, {p.x, p.z + 1.0}), n = smoothed_height(dem, frame, {p.x, p.z - 1.0});
  return std::hypot(0.5 * (e - w), 0.5 * (s - n));
}

void shape_heights(SurfaceMesh& mesh, const SurfacePlan& plan, const ElevationModel& dem, const LocalFrame& frame) {
  const std::size_t n = mesh.vertices.size();
  // Which materials touch each vertex.
  std::vector<unsigned> touch(n, 0);
  std::map<std::string, unsigned> bit;
  for (const SurfaceMesh::Group& g : mesh.groups) {
    const unsigned b = 1u << std::min<std::size_t>(bit.size(), 31);
    bit.emplace(g.material, b);
    for (const auto& t : g.triangles)
      for (const std::uint32_t v : t) touch[v] |= bit[g.material];
  }
  const auto only = [&](std::size_t v, const char* m) { return bit.count(m) && touch[v] == bit[m]; };
  const auto on = [&](std::size_t v, const char* m) { return bit.count(m) && (touch[v] & bit[m]) != 0; };
  // One batch of raster look-ups: every vertex, and the discs of the green ones.
  std::vector<LocalPoint> pts;
  pts.reserve(n);
  for (const Vec3& v : mesh.vertices) pts.push_back({v.x(), v.z()});
  std::vector<std::size_t> disc_at(n, 0);
  std::vector<std::vector<std::pair<LocalPoint, double>>> discs;
  for (std::size_t v = 0; v < n; ++v)
    if (on(v, "green")) {
      disc_at[v] = pts.size();
      discs.push_back(disc(pts[v], kGreenSmoothing));
      for (const auto& [q, w] : discs.back()) pts.push_back(q);
    }
  // The banks of each body of water.
  const auto outlines = plan.water_outlines();
  std::vector<std::size_t> bank_at;
  for (const auto& ring : outlines) {
    bank_at.push_back(pts.size());
    pts.insert(pts.end(), ring.begin(), ring.end());
  }
  const std::vector<double> h = dem.heights(frame, pts);
  std::vector<double> water_level;
  for (std::size_t k = 0; k < outlines.size(); ++k) {
    double low = HUGE_VAL;
    for (std::size_t i = 0; i < outlines[k].size(); ++i) low = std::min(low, h[bank_at[k] + i]);
    water_level.push_back(low - kWaterDrop);
  }
  std::size_t d = 0;
  for (std::size_t v = 0; v < n; ++v) {
    double y = h[v];
    if (on(v, "green")) y = weighted(discs[d++], h, disc_at[v]);
    if (only(v, "sand")) y -= std::min(kBunkerDepth, kBunkerFace * plan.depth_inside(pts[v].x, pts[v].z));
    if (only(v, "water")) {
      const int k = plan.water_at(pts[v].x, pts[v].z);
      if (k >= 0) y = std::min(y, water_level[static_cast<std::size_t>(k)]);
    }
    mesh.vertices[v].y() = y;
  }
  conform_hanging_vertices(mesh);
}

void conform_hanging_vertices(SurfaceMesh& mesh) {
  // Edges used by one triangle only.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const SurfaceMesh::Group& g : mesh.groups)
    for (const auto& t : g.triangles)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
        ++uses[{std::min(a, b), std::max(a, b)}];
      }
  // Vertices by their 1 m cell, to find those lying on an edge.
  std::unordered_map<long long, std::vector<std::uint32_t>> cells;
  const auto key = [](double x, double z) { return (static_cast<long long>(std::floor(x)) << 32) ^ (static_cast<long long>(std::floor(z)) & 0xffffffffLL); };
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) cells[key(mesh.vertices[v].x(), mesh.vertices[v].z())].push_back(v);
  for (int pass = 0; pass < 3; ++pass)  // a vertex may hang on an edge whose own end hangs
    for (const auto& [e, count] : uses) {
      if (count != 1) continue;
      const Vec3& a = mesh.vertices[e.first];
      const Vec3& b = mesh.vertices[e.second];
      const double dx = b.x() - a.x(), dz = b.z() - a.z(), len2 = dx * dx + dz * dz;
      if (len2 < 1e-12) continue;
      const int x0 = static_cast<int>(std::floor(std::min(a.x(), b.x()))), x1 = static_cast<int>(std::floor(std::max(a.x(), b.x())));
      const int z0 = static_cast<int>(std::floor(std::min(a.z(), b.z()))), z1 = static_cast<int>(std::floor(std::max(a.z(), b.z())));
      for (int cx = x0; cx <= x1; ++cx)
        for (int cz = z0; cz <= z1; ++cz) {
          const auto it = cells.find(key(cx, cz));
          if (it == cells.end()) continue;
          for (const std::uint32_t v : it->second) {
            if (v == e.first || v == e.second) continue;
            Vec3& p = mesh.vertices[v];
            const double u = ((p.x() - a.x()) * dx + (p.z() - a.z()) * dz) / len2;
            if (u <= 1e-9 || u >= 1.0 - 1e-9) continue;
            const double off = std::abs((p.x() - a.x()) * dz - (p.z() - a.z()) * dx) / std::sqrt(len2);
            if (off < 1e-6) p.y() = a.y() + u * (b.y() - a.y());
          }
        }
    }
}

}  // namespace sweetspot
