// The exact sphere–triangle sweep against closed forms and a brute-force reference: the
// first time the centre's path comes within the radius of the triangle, found by fine
// sampling and bisection on the distance to the closest point.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

#include "physics/detail/sphere_sweep.hpp"

using namespace sweetspot;

namespace {

struct LcgRng {
  std::uint64_t s;
  double uniform() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  }
  double in(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // One draw a statement: a constructor's arguments are evaluated in an unspecified order.
  Vec3 vec(double lo, double hi) {
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = in(lo, hi);
    return v;
  }
};

double distance_to(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return (closest_point_on_triangle(p, a, b, c) - p).norm();
}

/// First fraction where the path is within r: 20000 samples, then bisection.
bool brute_force(const Vec3& from, const Vec3& motion, double r, const Vec3& a, const Vec3& b, const Vec3& c,
                 double* f) {
  const int n = 20000;
  if (distance_to(from, a, b, c) <= r) {
    *f = 0.0;
    return true;
  }
  for (int i = 1; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    if (distance_to(from + t * motion, a, b, c) <= r) {
      double lo = static_cast<double>(i - 1) / n, hi = t;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (distance_to(from + mid * motion, a, b, c) <= r ? hi : lo) = mid;
      }
      *f = hi;
      return true;
    }
  }
  return false;
}

}  // namespace

TEST_CASE("sphere sweep: closed-form face, edge and corner hits", "[world][sweep]") {
  const Vec3 a(0, 0, 0), b(10, 0, 0), c(0, 0, 10);
  const double r = 0.5;
  double f = -1.0;
  // Straight down onto the face from 5.5 m: touches after 5 m of a 10 m drop.
  REQUIRE(sphere_triangle_sweep(Vec3(2, 5.5, 2), Vec3(0, -10, 0), r, a, b, c, &f));
  CHECK(f == Approx(0.5).margin(1e-15));
  // Sliding sideways at height 0.3 into the edge x = 0 from x = -2: the cylinder about the
  // edge is met where the centre is sqrt(r² - 0.3²) = 0.4 m from it.
  REQUIRE(sphere_triangle_sweep(Vec3(-2, 0.3, 5), Vec3(4, 0, 0), r, a, b, c, &f));
  CHECK(f == Approx((2.0 - 0.4) / 4.0).margin(1e-14));
  // Towards the corner a along the diagonal from below-left: meets the corner sphere.
  const Vec3 dir = Vec3(1, 0, 1).normalized();
  REQUIRE(sphere_triangle_sweep(Vec3(0, 0, 0) - 3.0 * dir, 6.0 * dir, r, a, b, c, &f));
  CHECK(f == Approx((3.0 - r) / 6.0).margin(1e-14));
  // Passing by, never within r; and a sphere already touching at the start gives 0.
  CHECK_FALSE(sphere_triangle_sweep(Vec3(-2, 0.6, 5), Vec3(0, 0, 4), r, a, b, c, &f));
  REQUIRE(sphere_triangle_sweep(Vec3(1, 0.4, 1), Vec3(0, 1, 0), r, a, b, c, &f));
  CHECK(f == 0.0);
  // A zero-area triangle has no face; it is still met at its corners if in the way.
  CHECK_FALSE(sphere_triangle_sweep(Vec3(5, 5, 5), Vec3(0, -1, 0), r, a, a, a, &f));
}

TEST_CASE("sphere sweep: agrees with a brute-force reference on random sweeps", "[world][sweep]") {
  LcgRng rng{20261123};
  int hits = 0, face_like = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 a = rng.vec(-2, 2), b = rng.vec(-2, 2), c = rng.vec(-2, 2);
    const Vec3 from = rng.vec(-4, 4);
    // Aim near a random point of the triangle and go somewhere between half and twice as
    // far, so most sweeps touch it (face, edge or corner) and some stop short or miss.
    const double u = rng.uniform(), v = rng.uniform() * (1.0 - u);
    const Vec3 target = a + u * (b - a) + v * (c - a) + rng.vec(-0.5, 0.5);
    const Vec3 motion = rng.in(0.5, 2.0) * (target - from);
    const double r = rng.in(0.02, 0.8);
    double f = -1.0, ref = -1.0;
    const bool got = sphere_triangle_sweep(from, motion, r, a, b, c, &f);
    const bool want = brute_force(from, motion, r, a, b, c, &ref);
    INFO("case " << i);
    // A path that only grazes within the sampling step can be missed by the reference.
    if (got != want) {
      CHECK(got);
      CHECK(distance_to(from + f * motion, a, b, c) == Approx(r).margin(1e-9));
      continue;
    }
    if (!got) continue;
    ++hits;
    if (f > 0.0) ++face_like;
    CHECK(f == Approx(ref).margin(1e-9));
    CHECK(distance_to(from + f * motion, a, b, c) <= r * (1.0 + 1e-9));
  }
  CHECK(hits > 200);       // the set exercises real contacts ...
  CHECK(face_like > 150);  // ... most of them met during the motion, not at its start
}
