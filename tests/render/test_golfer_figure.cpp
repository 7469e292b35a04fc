// The golfer (game/render/golfer_figure.hpp): his hands on the club, his stance beside the
// ball, his shoulders turning with the hands.
#include <cmath>

#include <catch2/catch.hpp>

#include "game/render/golfer_figure.hpp"

using namespace sweetspot;

namespace {
using G = GolferBody;
double deg(double r) { return r * 180.0 / 3.14159265358979; }
}  // namespace

TEST_CASE("the golfer holds the grip, beside the ball, square at address", "[golfer]") {
  // The shot goes along +x; a right-hander stands on the -z side, facing the ball (+z).
  const Vec3 grip0(-0.05, 0.75, -0.45);
  const G b = golfer_body(grip0, grip0, Vec3::UnitX(), 0.0);
  CHECK((b.joint[G::kHands] - grip0).norm() < 1e-12);
  for (G::Joint f : {G::kLeadFoot, G::kTrailFoot}) {
    CHECK(b.joint[f].y() == Approx(0.0));
    CHECK(b.joint[f].z() < grip0.z());  // farther from the ball than his hands
  }
  CHECK(b.joint[G::kLeadFoot].x() > b.joint[G::kTrailFoot].x());  // the lead foot toward the target
  CHECK(b.joint[G::kHead].y() > 1.4);
  // Square: the shoulder line runs along the target line, the lead shoulder toward it.
  const Vec3 line = b.joint[G::kLeadShoulder] - b.joint[G::kTrailShoulder];
  CHECK(line.x() > 0.0);
  CHECK(std::abs(line.z()) < 1e-9);
  // Arms reach the hands: no arm longer than a man's (~0.65 m shoulder to hands).
  CHECK((b.joint[G::kLeadShoulder] - grip0).norm() < 0.75);
  CHECK((b.joint[G::kTrailShoulder] - grip0).norm() < 0.75);
}

TEST_CASE("at the top of the backswing his shoulders have turned with his hands", "[golfer]") {
  const Vec3 grip0(-0.05, 0.75, -0.45);
  const Vec3 top(-0.55, 1.75, -0.85);  // hands up and back, behind his head
  const G b = golfer_body(top, grip0, Vec3::UnitX(), 0.0);
  const Vec3 line = b.joint[G::kLeadShoulder] - b.joint[G::kTrailShoulder];
  const double turn = deg(std::atan2(line.z(), line.x()));  // 0 square; + lead shoulder toward the ball
  CHECK(turn > 60.0);
  CHECK(turn < 120.0);
  // His stance does not move with his hands.
  const G address = golfer_body(grip0, grip0, Vec3::UnitX(), 0.0);
  CHECK((b.joint[G::kLeadFoot] - address.joint[G::kLeadFoot]).norm() < 1e-12);
  CHECK((b.joint[G::kPelvis] - address.joint[G::kPelvis]).norm() < 1e-12);
}

TEST_CASE("a limb is a closed box with its faces lit outward", "[golfer]") {
  MeshData m;
  const Vec3 a(0.0, 0.0, 0.0), b(0.0, 1.0, 0.0);
  append_limb(m, a, b, 0.1, Eigen::Vector3f(1.0f, 0.0f, 0.0f));
  REQUIRE(m.vertices.size() == 24);
  REQUIRE(m.indices.size() == 36);
  const Vec3 mid = 0.5 * (a + b);
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const Eigen::Vector3f p = m.vertices[m.indices[3 * t]].position, n = m.vertices[m.indices[3 * t]].normal;
    CHECK(n.dot(p - mid.cast<float>()) > 0.0f);  // each face's normal points away from the centre
  }
  MeshData none;
  append_limb(none, a, a, 0.1, Eigen::Vector3f::Ones());
  CHECK(none.vertices.empty());
}
