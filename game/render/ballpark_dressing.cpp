#include "game/render/ballpark_dressing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "game/render/mesh_import.hpp"

namespace sweetspot {
namespace {

constexpr double kFoot = 0.3048;
constexpr double kInch = 0.0254;
// Official Baseball Rules 2.01 / diagram 2, as scripts/gen_worlds.py builds the surfaces.
constexpr double kBasePath = 90.0 * kFoot;          // home to first, first to second, ...
constexpr double kRubber = 60.5 * kFoot;            // plate's back point to the rubber's front edge
constexpr double kSkinArc = 29.0;                   // m, the infield skin's 95 ft arc about the rubber
constexpr double kHomeCircle = 4.0;                 // m, the dirt circle about the plate (13 ft)
constexpr double kMoundCircle = 2.74;               // m, the mound's 18 ft diameter
constexpr double kGrassInset = 3.5;                 // m, the infield grass starts this far inside the base lines
constexpr double kTrack = 15.0 * kFoot;             // warning track width
constexpr double kBase = 18.0 * kInch;              // bag side (2023 rule; 15 in before)
constexpr double kChalk = 3.0 * kInch;              // chalk line width
// Foul poles are decoration: 0.4 m thick and 20 m tall so they read above the wall from
// the far cameras.
constexpr double kPoleSide = 0.4, kPoleHeight = 20.0;

struct Paint {
  Eigen::Vector3f color;
  float look;
};

// The palette's colour and look for a surface it names (every name used here is in it).
Paint paint(const char* material) {
  const PaletteEntry p = palette_color(material).value();
  return {p.color, p.pattern};
}

void vertex(MeshData& m, const Vec3& p, const Paint& c, const Vec3& normal = Vec3::UnitY()) {
  Vertex v;
  v.position = p.cast<float>();
  v.normal = normal.cast<float>();
  v.color = c.color;
  v.pattern = c.look;
  m.vertices.push_back(v);
}

// A fan of triangles from `centre` over the closed or open ring `ring`.
void fan(MeshData& m, const Vec3& centre, const std::vector<Vec3>& ring, const Paint& c, bool closed) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  vertex(m, centre, c);
  for (const Vec3& p : ring) vertex(m, p, c);
  const auto n = static_cast<std::uint32_t>(ring.size());
  for (std::uint32_t i = 0; i + 1 < n + (closed ? 1u : 0u); ++i) {
    m.indices.insert(m.indices.end(), {base, base + 1 + i, base + 1 + (i + 1) % n});
  }
}

void quad(MeshData& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Paint& p,
          const Vec3& normal = Vec3::UnitY()) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (const Vec3* q : {&a, &b, &c, &d}) vertex(m, *q, p, normal);
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

Vec3 lift(const Vec3& p, double dy) { return Vec3(p.x(), p.y() + dy, p.z()); }

void disc(MeshData& m, const Vec3& centre, double r, const Paint& c) {
  std::vector<Vec3> ring;
  for (int i = 0; i < 48; ++i) {
    const double a = 2.0 * kPi * i / 48;
    ring.push_back(centre + r * Vec3(std::cos(a), 0.0, std::sin(a)));
  }
  fan(m, centre, ring, c, true);
}

// An outline rectangle of chalk: x in [x0, x1], z in [z0, z1] (home frame).
void chalk_box(MeshData& m, const Vec3& home, double x0, double x1, double z0, double z1, const Paint& c) {
  auto at = [&](double x, double z) { return Vec3(home + Vec3(x, 0.0, z)); };
  const double w = kChalk;
  quad(m, at(x0, z0), at(x1, z0), at(x1, z0 + w), at(x0, z0 + w), c);
  quad(m, at(x0, z1 - w), at(x1, z1 - w), at(x1, z1), at(x0, z1), c);
  quad(m, at(x0, z0), at(x0 + w, z0), at(x0 + w, z1), at(x0, z1), c);
  quad(m, at(x1 - w, z0), at(x1, z0), at(x1, z1), at(x1 - w, z1), c);
}

// Distance from home along the horizontal direction at spray angle phi to the fence line;
// past the poles, the nearer pole's distance.
double fence_distance(const Vec3& home, const std::vector<Vec3>& fence, double phi) {
  if (const auto d = ray_polyline(home, Vec3(std::cos(phi), 0.0, std::sin(phi)), fence)) return *d;
  const Vec3& end = phi < 0.0 ? fence.front() : fence.back();
  return std::hypot(end.x() - home.x(), end.z() - home.z());
}

}  // namespace

std::optional<double> ray_polyline(const Vec3& origin, const Vec3& dir, const std::vector<Vec3>& line) {
  std::optional<double> best;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const double sx = line[i + 1].x() - line[i].x(), sz = line[i + 1].z() - line[i].z();
    const double den = dir.x() * sz - dir.z() * sx;
    if (std::abs(den) < 1e-12) continue;
    const double qx = line[i].x() - origin.x(), qz = line[i].z() - origin.z();
    const double t = (qx * sz - qz * sx) / den;
    const double u = (qx * dir.z() - qz * dir.x()) / den;
    if (t > 0 && u >= -1e-9 && u <= 1 + 1e-9 && (!best || t < *best)) best = t;
  }
  return best;
}

BallparkDressing ballpark_dressing(const Vec3& home, const std::vector<Vec3>& fence_line, double fence_height) {
  BallparkDressing out;
  if (fence_line.size() < 2) return out;
  const Paint grass = paint("grass"), dirt = paint("dirt"), track = paint("warning_track"), pole = paint("foul_pole");
  const Paint chalk{{0.95f, 0.95f, 0.92f}, surface_look::kPlain};
  const double quarter = kPi / 4;
  auto ray = [&](double phi, double r) { return Vec3(home + r * Vec3(std::cos(phi), 0.0, std::sin(phi))); };

  // Layer 0: the outfield grass out to the track (15 deg past each foul line, so the skin's
  // and the track's cell staircases are covered), a grass disc about the plate (its cells'
  // staircase reaches one cell diagonal, 3.5 m, past the 4 m circle), and the track itself.
  MeshData field;
  disc(field, home, kHomeCircle + 3.6, grass);
  std::vector<Vec3> edge;
  for (int k = -60; k <= 60; ++k) {
    const double phi = deg_to_rad(k);
    edge.push_back(ray(phi, fence_distance(home, fence_line, std::clamp(phi, -quarter, quarter)) - kTrack));
  }
  fan(field, home, edge, grass, false);
  for (int k = -45; k < 45; ++k) {
    const double a = deg_to_rad(k), b = deg_to_rad(k + 1);
    const double ra = fence_distance(home, fence_line, a), rb = fence_distance(home, fence_line, b);
    quad(field, ray(a, ra - kTrack), ray(b, rb - kTrack), ray(b, rb), ray(a, ra), track);
  }
  out.layers.push_back(std::move(field));

  // Layer 1: the infield skin, fair territory within the arc about the rubber.
  MeshData skin;
  std::vector<Vec3> arc;
  const double c = kRubber;  // the arc's centre on the x axis
  for (int k = -45; k <= 45; ++k) {
    const double phi = deg_to_rad(k);
    // |t d - C| = R along the ray: t = d.C + sqrt((d.C)^2 - |C|^2 + R^2).
    const double dc = c * std::cos(phi);
    arc.push_back(ray(phi, dc + std::sqrt(dc * dc - c * c + kSkinArc * kSkinArc)));
  }
  fan(skin, home, arc, dirt, false);
  out.layers.push_back(std::move(skin));

  // Layer 2: the infield grass inside the base lines.
  const Vec3 first_dir(std::cos(quarter), 0.0, std::sin(quarter)), third_dir(std::cos(quarter), 0.0, -std::sin(quarter));
  auto diamond = [&](double u, double w) { return Vec3(home + u * first_dir + w * third_dir); };
  MeshData infield;
  const double lo = kGrassInset, hi = kBasePath - kGrassInset;
  quad(infield, diamond(lo, lo), diamond(hi, lo), diamond(hi, hi), diamond(lo, hi), grass);
  out.layers.push_back(std::move(infield));

  // Layer 3: the dirt circles about the plate and the mound.
  MeshData circles;
  disc(circles, home, kHomeCircle, dirt);
  disc(circles, home + Vec3(kRubber, 0.0, 0.0), kMoundCircle, dirt);
  out.layers.push_back(std::move(circles));

  // Layer 4: white: the plate, the bases, the rubber, the batter's boxes.
  MeshData white;
  {
    // Home plate: 17 in across the front, 8.5 in sides, 12 in edges meeting at the back point.
    const double s = 12.0 * kInch / std::sqrt(2.0), front = s + 8.5 * kInch, half = 8.5 * kInch;
    const std::vector<Vec3> plate = {home + Vec3(s, 0, -half), home + Vec3(front, 0, -half), home + Vec3(front, 0, half),
                                     home + Vec3(s, 0, half)};
    fan(white, home, plate, chalk, false);
    // First and third bags lie wholly in fair territory, a corner on the line at 90 ft;
    // second is centred on its point.
    quad(white, diamond(kBasePath - kBase, 0), diamond(kBasePath, 0), diamond(kBasePath, kBase),
         diamond(kBasePath - kBase, kBase), chalk);
    quad(white, diamond(0, kBasePath - kBase), diamond(kBase, kBasePath - kBase), diamond(kBase, kBasePath),
         diamond(0, kBasePath), chalk);
    const double h = 0.5 * kBase;
    quad(white, diamond(kBasePath - h, kBasePath - h), diamond(kBasePath + h, kBasePath - h),
         diamond(kBasePath + h, kBasePath + h), diamond(kBasePath - h, kBasePath + h), chalk);
    // The rubber: 24 x 6 in, its front edge 60.5 ft from the plate's back point.
    quad(white, home + Vec3(kRubber, 0, -12 * kInch), home + Vec3(kRubber + 6 * kInch, 0, -12 * kInch),
         home + Vec3(kRubber + 6 * kInch, 0, 12 * kInch), home + Vec3(kRubber, 0, 12 * kInch), chalk);
    // Batter's boxes: 4 x 6 ft, 6 in from the plate, centred on its middle.
    const double mid = 0.5 * front, inner = half + 6 * kInch, outer = inner + 4 * kFoot;
    chalk_box(white, home, mid - 3 * kFoot, mid + 3 * kFoot, inner, outer, chalk);
    chalk_box(white, home, mid - 3 * kFoot, mid + 3 * kFoot, -outer, -inner, chalk);
    // The foul lines from the plate to the poles, 10 cm wide as the world's own chalk.
    for (const Vec3& end : {fence_line.front(), fence_line.back()}) {
      Vec3 d(end.x() - home.x(), 0.0, end.z() - home.z());
      const Vec3 side = 0.05 * Vec3(-d.z(), 0.0, d.x()).normalized();
      const Vec3 tip = home + d;
      quad(white, home - side, tip - side, tip + side, home + side, chalk);
    }
  }
  out.layers.push_back(std::move(white));

  // The foul poles at the fence's two ends: a square column, four lit sides.
  for (const Vec3& foot : {fence_line.front(), fence_line.back()}) {
    const Vec3 b(foot.x(), home.y(), foot.z());
    const double r = 0.5 * kPoleSide, top = std::max(kPoleHeight, fence_height + 5.0);
    const Vec3 corners[4] = {b + Vec3(-r, 0, -r), b + Vec3(r, 0, -r), b + Vec3(r, 0, r), b + Vec3(-r, 0, r)};
    for (int i = 0; i < 4; ++i) {
      const Vec3& a = corners[i];
      const Vec3& e = corners[(i + 1) % 4];
      const Vec3 n = (e - a).cross(Vec3::UnitY()).normalized();
      quad(out.poles, a, e, e + Vec3(0, top, 0), a + Vec3(0, top, 0), pole, n);
    }
  }
  // The stands: raked rows of seats beyond the outfield wall (but for the batter's eye) and
  // behind the foul ground along each line, rising 0.9 m every 1.6 m row (a ~30° rake, as
  // major-league upper decks are built at most 35°: ESTIMATE of a typical lower bowl), their
  // front rows just above the wall. Decoration only: the physics' stands are the flat ground
  // out of bounds beyond the wall.
  {
    const Paint seat_a{Eigen::Vector3f(0.16f, 0.22f, 0.42f), 0.0f}, seat_b{Eigen::Vector3f(0.36f, 0.38f, 0.44f), 0.0f};
    constexpr int kRows = 12;
    constexpr double kRow = 1.6, kRise = 0.9;
    const double eye_half = std::atan2(10.0, fence_distance(home, fence_line, 0.0));
    for (int k = -45; k < 45; ++k) {
      const double a = deg_to_rad(k), b = deg_to_rad(k + 1);
      if (std::max(std::abs(a), std::abs(b)) < eye_half + deg_to_rad(1.0)) continue;
      const double ra = fence_distance(home, fence_line, a) + 2.0, rb = fence_distance(home, fence_line, b) + 2.0;
      for (int row = 0; row < kRows; ++row) {
        const double y0 = fence_height + 0.3 + kRise * row, y1 = y0 + kRise;
        const double d0 = kRow * row, d1 = d0 + kRow;
        const Paint& c = row % 2 == 0 ? seat_a : seat_b;
        const Vec3 inward(-std::cos(0.5 * (a + b)), 0.0, -std::sin(0.5 * (a + b)));
        const Vec3 a0 = lift(ray(a, ra + d0), y0), b0 = lift(ray(b, rb + d0), y0);
        const Vec3 a1 = lift(ray(a, ra + d0), y1), b1 = lift(ray(b, rb + d0), y1);
        const Vec3 a2 = lift(ray(a, ra + d1), y1), b2 = lift(ray(b, rb + d1), y1);
        quad(out.stands, a0, b0, b1, a1, c, inward);
        quad(out.stands, a1, b1, b2, a2, c);
      }
    }
    // Along each foul line, from 20 m out to the pole: 60 ft of foul ground (Rule 2.01), then
    // the rows, rising from a 4 ft front wall.
    constexpr double kFoul = 60.0 * kFoot, kFrontWall = 4.0 * kFoot;
    for (const Vec3& pole_foot : {fence_line.front(), fence_line.back()}) {
      Vec3 along(pole_foot.x() - home.x(), 0.0, pole_foot.z() - home.z());
      const double reach = along.norm();
      if (reach < 25.0) continue;
      along /= reach;
      Vec3 out_dir(-along.z(), 0.0, along.x());  // away from fair territory
      if (out_dir.dot(Vec3(0.0, 0.0, pole_foot.z() - home.z())) < 0.0) out_dir = -out_dir;
      for (double s0 = 20.0; s0 < reach - 1.0; s0 += 6.0) {
        const double s1 = std::min(s0 + 6.0, reach);
        for (int row = 0; row < kRows; ++row) {
          const double y0 = home.y() + kFrontWall + kRise * row, y1 = y0 + kRise;
          const double o0 = kFoul + kRow * row, o1 = o0 + kRow;
          const Paint& c = row % 2 == 0 ? seat_a : seat_b;
          const auto at = [&](double s, double o, double y) {
            return Vec3(home.x() + s * along.x() + o * out_dir.x(), y, home.z() + s * along.z() + o * out_dir.z());
          };
          const Vec3 facing(-out_dir.x(), 0.0, -out_dir.z());
          const Vec3 p0 = at(s0, o0, y0), p1 = at(s1, o0, y0), p2 = at(s1, o0, y1), p3 = at(s0, o0, y1);
          const Vec3 p4 = at(s1, o1, y1), p5 = at(s0, o1, y1);
          quad(out.stands, p0, p1, p2, p3, c, facing);
          quad(out.stands, p3, p2, p4, p5, c);
        }
      }
    }
  }
  // The batter's eye: a dark, plain backdrop beyond the centre-field wall against which a
  // batter picks up the pitch out of the pitcher's hand (every major-league park has one).
  // ESTIMATES of a typical one: 18 m (~60 ft) wide, 12 m (~40 ft) tall, 3 m behind the wall.
  {
    const Paint eye{Eigen::Vector3f(0.05f, 0.17f, 0.08f), 0.0f};
    const double d = fence_distance(home, fence_line, 0.0) + 3.0, half = 9.0, high = 12.0, deep = 1.5;
    const double x0 = home.x() + d, x1 = x0 + deep, y0 = home.y();
    const std::array<Vec3, 4> foot{Vec3(x0, y0, home.z() - half), Vec3(x0, y0, home.z() + half), Vec3(x1, y0, home.z() + half),
                                   Vec3(x1, y0, home.z() - half)};
    for (std::size_t i = 0; i < 4; ++i) {
      const Vec3& a = foot[i];
      const Vec3& e = foot[(i + 1) % 4];
      const Vec3 n = (e - a).cross(Vec3::UnitY()).normalized();
      quad(out.stands, a, e, lift(e, high), lift(a, high), eye, n);
    }
    quad(out.stands, lift(foot[0], high), lift(foot[1], high), lift(foot[2], high), lift(foot[3], high), eye, Vec3::UnitY());
  }
  return out;
}

}  // namespace sweetspot
