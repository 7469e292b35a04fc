// The benchmark's Bullet-dynamics baseline must be a correct baseline: in vacuum it flies
// the closed-form parabola, and aero forces are applied once per substep (not accumulated).
#include <catch2/catch.hpp>

#include <cmath>

#include "game/bench/bullet_baseline.hpp"

using namespace sweetspot;
using namespace sweetspot::bench;

namespace {
BaselineGround flat_ground() {
  BaselineGround g;
  g.positions = {Vec3(-500, 0, -500), Vec3(500, 0, -500), Vec3(500, 0, 500), Vec3(-500, 0, 500)};
  g.indices = {0, 2, 1, 0, 3, 2};
  return g;
}
}  // namespace

TEST_CASE("baseline in vacuum flies the closed-form range", "[bench][baseline]") {
  const double v = 30.0, a = deg_to_rad(45.0);
  BaselineBall ball;
  LaunchState l;
  l.position = Vec3(0, ball.radius, 0);
  l.velocity = v * Vec3(std::cos(a), std::sin(a), 0);
  const auto none = [](const Vec3&, const Vec3&, const Vec3&) { return AeroEffect{}; };
  BaselineOptions opt;
  opt.carry_only = true;
  const auto r = run_bullet_baseline(l, ball, none, flat_ground(), opt);
  REQUIRE(r.landed);
  const double range = v * v * std::sin(2 * a) / kGravity;  // 91.77 m
  // Landing is detected at the first 240 Hz substep in contact: within one substep of travel.
  CHECK(std::abs(r.carry_m - range) < v * std::cos(a) / 240.0 + 0.05);
}

TEST_CASE("baseline applies a constant force once per substep", "[bench][baseline]") {
  // A constant horizontal force F on a ball launched straight up: x = F/(2m) t² at landing.
  BaselineBall ball;
  LaunchState l;
  l.position = Vec3(0, ball.radius, 0);
  l.velocity = Vec3(0, 10, 0);
  const double f = 0.01;
  const auto push = [f](const Vec3&, const Vec3&, const Vec3&) { return AeroEffect{Vec3(f, 0, 0), Vec3::Zero()}; };
  BaselineOptions opt;
  opt.carry_only = true;
  const auto r = run_bullet_baseline(l, ball, push, flat_ground(), opt);
  REQUIRE(r.landed);
  const double t = 2 * 10.0 / kGravity;
  const double expected = 0.5 * f / ball.mass * t * t;  // 0.453 m; 4× that if forces piled up
  CHECK(r.carry_m == Approx(expected).epsilon(0.03));
}
