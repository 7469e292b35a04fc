// Dormand–Prince 5(4): the order of convergence on a problem with a closed form, and the
// dense output's accuracy between the steps.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/detail/integrator.hpp"

using namespace sweetspot;

namespace {

using State2 = Eigen::Matrix<double, 2, 1>;

// Harmonic oscillator x'' = -x: x = cos t, v = -sin t.
struct Oscillator {
  State2 operator()(double, const State2& y) const { return State2(y[1], -y[0]); }
};

// Global error at t = 2π with fixed steps of size h (tolerances so loose every trial passes).
double global_error(double h, double* dense_error) {
  const IntegratorTolerances loose{1e3, 1e3, h, h};
  DopriCarry<2> carry;
  carry.h = h;
  double t = 0.0;
  State2 y(1.0, 0.0);
  DenseSegment<2> seg;
  double worst_dense = 0.0;
  const double end = 2.0 * 3.14159265358979323846;
  while (t < end - 1e-12) {
    carry.h = h;
    dopri_step(Oscillator{}, loose, carry, t, y, end, seg);
    const double mid = seg.t0 + 0.37 * seg.h;
    worst_dense = std::max(worst_dense, std::abs(seg.at(mid)[0] - std::cos(mid)));
  }
  if (dense_error) *dense_error = worst_dense;
  return std::hypot(y[0] - 1.0, y[1] - 0.0);
}

}  // namespace

TEST_CASE("DOPRI5 converges at fifth order; its dense output at fourth", "[integrator][convergence]") {
  double d1 = 0.0, d2 = 0.0;
  const double e1 = global_error(0.2, &d1);
  const double e2 = global_error(0.1, &d2);
  // Halving the step divides a 5th-order global error by 2^5 = 32 (allow 26..40).
  CHECK(e1 / e2 > 26.0);
  CHECK(e1 / e2 < 40.0);
  CHECK(e2 < 1e-6);
  // Shampine's interpolant is 4th order: the in-step error falls by ~2^5 locally too (the
  // local error of a 4th-order interpolant is O(h^5)); at least 16x.
  CHECK(d1 / d2 > 16.0);
}

TEST_CASE("the step controller meets its tolerance and never stalls on NaN", "[integrator]") {
  const IntegratorTolerances tol{1e-10, 1e-12, 1e-10, 1.0};
  DopriCarry<2> carry;
  carry.h = 0.5;
  double t = 0.0;
  State2 y(1.0, 0.0);
  DenseSegment<2> seg;
  const double end = 10.0;
  while (t < end) dopri_step(Oscillator{}, tol, carry, t, y, end, seg);
  CHECK(std::abs(y[0] - std::cos(10.0)) < 1e-8);
  // A derivative that is NaN at every step size is rejected down to h_min, then accepted
  // (the caller refuses the state) rather than shrinking the step forever: from h = 1 s by
  // factors of 5 to 1e-10 s, at most 15 rejections.
  struct Poison {
    State2 operator()(double, const State2&) const { return State2(std::nan(""), 0.0); }
  };
  DopriCarry<2> c2;
  c2.h = 1.0;
  double t2 = 0.0;
  State2 y2(1.0, 0.0);
  CHECK(dopri_step(Poison{}, tol, c2, t2, y2, 1.0, seg) <= 15);
  CHECK(std::isnan(y2[0]));
}

TEST_CASE("a trial step whose stages overflow is taken again shorter, not accepted", "[integrator]") {
  // y' = -k y|y| (quadratic drag) from y = 1: y = 1 / (1 + k t). A first trial of 1 s with
  // k = 1e6 overflows the explicit stages to inf and NaN (a 10 g ball of radius 20 cm
  // launched at 42 m/s did this); the step is rejected like any huge error and the solution
  // goes on finite and accurate.
  struct Drag {
    State2 operator()(double, const State2& y) const { return State2(-1e6 * y[0] * std::abs(y[0]), 0.0); }
  };
  const IntegratorTolerances tol{1e-8, 1e-12, 1e-10, 1.0};
  DopriCarry<2> c;
  c.h = 1.0;
  double t = 0.0;
  State2 y(1.0, 0.0);
  DenseSegment<2> seg;
  CHECK(dopri_step(Drag{}, tol, c, t, y, 1.0, seg) > 0);
  REQUIRE(std::isfinite(y[0]));
  while (t < 1e-3) dopri_step(Drag{}, tol, c, t, y, 1e-3, seg);
  CHECK(y[0] == Approx(1.0 / (1.0 + 1e6 * 1e-3)).epsilon(1e-6));
}

TEST_CASE("the step controller's growth factor is 0.9 norm^-1/5 clamped to [0.2, 5]", "[integrator]") {
  for (double x = 1e-6; x < 1e4; x *= 1.0007) {
    const double expected = std::clamp(0.9 * std::pow(x, -0.2), 0.2, 5.0);
    INFO("norm " << x);
    CHECK(std::abs(step_growth(x) - expected) <= 1e-10 * expected);
  }
  CHECK(step_growth(0.0) == 5.0);
  CHECK(step_growth(std::numeric_limits<double>::infinity()) == 0.2);
  CHECK(std::isnan(step_growth(std::numeric_limits<double>::quiet_NaN())));  // a broken state is seen, not hidden
}
