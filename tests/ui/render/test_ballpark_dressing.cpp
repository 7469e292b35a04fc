// The ballpark's diamond against the rule book (Official Baseball Rules 2.01, diagram 2;
// the 18 in bases adopted in 2023): bases 90 ft apart, the rubber's front edge 60 ft 6 in
// from the plate's back point, home plate 17 in across, the foul poles where the fence meets
// the foul lines.
#include <cmath>

#include <catch2/catch.hpp>

#include "game/render/ballpark_dressing.hpp"

using namespace sweetspot;

namespace {

constexpr double kFt = 0.3048, kIn = 0.0254;

// A fence like the shipped park's: 330 ft at the poles, 400 ft to centre.
std::vector<Vec3> fence() {
  std::vector<Vec3> line;
  for (int a = -45; a <= 45; ++a) {
    const double p = a / 45.0, r = (400.0 - 70.0 * p * p) * kFt;
    line.emplace_back(r * std::cos(deg_to_rad(a)), 0.0, r * std::sin(deg_to_rad(a)));
  }
  return line;
}

bool has_vertex(const MeshData& m, const Vec3& p, double tol = 1e-3) {
  for (const Vertex& v : m.vertices)
    if ((v.position.cast<double>() - p).norm() < tol) return true;
  return false;
}

}  // namespace

TEST_CASE("the ballpark's diamond has the rule book's dimensions", "[render][unit]") {
  const BallparkDressing d = ballpark_dressing(Vec3::Zero(), fence(), 3.048);
  REQUIRE(d.layers.size() == 5);
  const MeshData& white = d.layers.back();
  const double base = 90 * kFt, bag = 18 * kIn, s45 = std::sqrt(0.5);
  // First base: a corner on the first-base line (+z side) at 90 ft; the bag in fair territory.
  CHECK(has_vertex(white, Vec3(base * s45, 0, base * s45)));
  CHECK(has_vertex(white, Vec3((base - bag) * s45, 0, (base - bag) * s45)));
  // Third base mirrored; second base centred 127 ft 3 3/8 in from the plate's point.
  CHECK(has_vertex(white, Vec3(base * s45, 0, -base * s45)));
  const double second = base * std::sqrt(2.0);
  CHECK(second / kFt == Approx(127.28).margin(0.01));
  // Its corners toward home and centre field lie on the x axis, half a diagonal off centre.
  CHECK(has_vertex(white, Vec3(second - bag / std::sqrt(2.0), 0, 0)));
  CHECK(has_vertex(white, Vec3(second + bag / std::sqrt(2.0), 0, 0)));
  // The rubber's front edge 60 ft 6 in out, 24 in wide.
  CHECK(has_vertex(white, Vec3(60.5 * kFt, 0, -12 * kIn)));
  CHECK(has_vertex(white, Vec3(60.5 * kFt, 0, 12 * kIn)));
  // Home plate: 17 in across its front edge, at 17 in from its back point.
  const double front = 12 * kIn / std::sqrt(2.0) + 8.5 * kIn;
  CHECK(has_vertex(white, Vec3(front, 0, -8.5 * kIn)));
  CHECK(has_vertex(white, Vec3(front, 0, 8.5 * kIn)));
  CHECK(front / kIn == Approx(17.0).margin(0.02));
  // The skin's arc: 29 m (95 ft) about the rubber, straight out to centre field.
  CHECK(has_vertex(d.layers[1], Vec3(60.5 * kFt + 29.0, 0, 0), 1e-2));
  // Foul poles stand at the fence's two ends, taller than the fence.
  const auto f = fence();
  double lo_x = 1e9, top = 0;
  for (const Vertex& v : d.poles.vertices) {
    lo_x = std::min<double>(lo_x, v.position.x());
    top = std::max<double>(top, v.position.y());
  }
  CHECK(lo_x == Approx(f.front().x() - 0.2).margin(1e-3));
  CHECK(top > 3.048 + 5.0);
  // The stands rise from just above the wall behind the outfield, and the batter's eye stands
  // dark beyond centre field, clear of the field of play.
  double near_cf = 1e9;
  for (const Vertex& v : d.stands.vertices) {
    CHECK(std::hypot(v.position.x(), v.position.z()) >= 60.0 * kFt - 1e-3);  // beyond the foul ground at least
    if (std::abs(v.position.z()) < 1.0) near_cf = std::min<double>(near_cf, v.position.x());
  }
  CHECK(!d.stands.indices.empty());
  CHECK(near_cf > 400.0 * kFt + 2.0);  // the test fence is 400 ft to centre
  // Everything but the poles lies flat on the field.
  for (const MeshData& layer : d.layers)
    for (const Vertex& v : layer.vertices) CHECK(v.position.y() == 0.0f);
  // No fence, no park: nothing drawn.
  CHECK(ballpark_dressing(Vec3::Zero(), {}, 3.0).layers.empty());
}
