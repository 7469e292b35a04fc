// Dormand–Prince 5(4) with adaptive step size and 4th-order dense output (Hairer, Nørsett &
// Wanner, "Solving ODEs I", DOPRI5). The flight uses the dense output to find the ground
// contact and the apex by root finding inside a step instead of stepping past them.
//
// Header-only template over a fixed-size Eigen state so the hot loop never allocates.
// Deterministic: no data-dependent branching besides accept/reject on the error norm.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <Eigen/Core>

namespace sweetspot {

/// The continuous extension of one accepted step: y(t) for t in [t0, t0 + h].
template <int N>
struct DenseSegment {
  using State = Eigen::Matrix<double, N, 1>;
  double t0 = 0.0;
  double h = 0.0;
  State r1, r2, r3, r4, r5;

  double t1() const { return t0 + h; }
  State at(double t) const {
    const double th = (t - t0) / h;
    const double th1 = 1.0 - th;
    return r1 + th * (r2 + th1 * (r3 + th * (r4 + th1 * r5)));
  }
  /// One component only (cheap, for root finding on a scalar event).
  double component(double t, int i) const {
    const double th = (t - t0) / h;
    const double th1 = 1.0 - th;
    return r1[i] + th * (r2[i] + th1 * (r3[i] + th * (r4[i] + th1 * r5[i])));
  }
};

struct IntegratorTolerances {
  double rel_tol = 1e-8;  ///< relative error per step
  double abs_tol = 1e-9;  ///< absolute error per step, in the state's units
  double h_min = 1e-10;   ///< s; below this the step is forced through
  double h_max = 1.0;     ///< s
  /// s; 0: every component's error is judged against rel_tol × its own size. > 0: the state
  /// starts with a position (components 0–2) followed by its rate (3–5), and the position's
  /// error is judged against rel_tol × |rate| × this time instead: a position's size depends
  /// on where the origin is, its rate does not, so the steps (and the results) do not change
  /// when the whole problem is translated.
  double position_time = 0.0;
};

/// What one trajectory carries from step to step: the next trial step size and the
/// derivative at the current point (DOPRI5 is "first same as last": the last stage of a
/// step is the first of the next). Plain data, so a shot's state can hold it and a replay
/// from a saved state continues bit for bit.
template <int N>
struct DopriCarry {
  double h = 1e-3;                                  ///< s, next trial step
  Eigen::Matrix<double, N, 1> k1 = Eigen::Matrix<double, N, 1>::Zero();  ///< f(t, y) when have_k1
  bool have_k1 = false;                             ///< false after a discontinuity (a bounce)

  /// Starts a new trajectory segment with trial step `h0` (s): call after any
  /// discontinuity so the derivative is recomputed.
  void restart(double h0) {
    h = h0;
    have_k1 = false;
  }
};

/// The step controller's growth factor 0.9·norm^(−1/5), clamped to [0.2, 5]. The clamp holds
/// outside norm ∈ [(0.9/5)^5, (0.9/0.2)^5] ≈ [1.9e-4, 1845]; inside, x^(−1/5) from a first
/// guess read off the exponent bits (the power applied to the bits of a double, Blinn's
/// trick) and four Newton steps on y⁵x = 1 (y ← y(6 − xy⁵)/5, the error about squared each
/// time): within 2e-11 of std::pow over the range (test_integrator.cpp). `std::pow` is a
/// libm call of ~125 instructions a step, 2 % of a golf shot; the factor is a
/// heuristic, so it only has to be a deterministic, smooth function of the norm.
inline double step_growth(double norm) {
  constexpr double kLow = 1.8895680e-4, kHigh = 1845.28125;  // (0.9/5)^5, (0.9/0.2)^5
  if (std::isnan(norm)) return norm;  // the caller sees the step size turn non-finite and stops
  if (norm <= kLow) return 5.0;
  if (norm >= kHigh) return 0.2;
  std::uint64_t bits;
  std::memcpy(&bits, &norm, sizeof bits);
  // bits(x^p) ≈ p·bits(x) + (1 − p)·bits(1.0) for p = −1/5.
  constexpr std::uint64_t kOne = 0x3FF0000000000000ULL;
  const std::uint64_t guess_bits = kOne + kOne / 5 - bits / 5;
  double y;
  std::memcpy(&y, &guess_bits, sizeof y);
  for (int i = 0; i < 4; ++i) {
    const double y2 = y * y;
    y = y * (6.0 - norm * y2 * y2 * y) * 0.2;
  }
  return std::clamp(0.9 * y, 0.2, 5.0);
}

/// Advances (t, y) by one accepted step of at most t_end - t; fills `dense` for the step.
/// f(t, y) -> dy/dt. Returns the number of rejected trials (for statistics). Stateless:
/// everything a trajectory carries between steps is in `carry`.
template <int N, class F>
int dopri_step(const F& f, const IntegratorTolerances& tol, DopriCarry<N>& carry, double& t,
               Eigen::Matrix<double, N, 1>& y, double t_end, DenseSegment<N>& dense) {
  using State = Eigen::Matrix<double, N, 1>;
  // Butcher tableau of DOPRI5.
  constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784,
                   a76 = 11.0 / 84;
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                   e6 = 22.0 / 525, e7 = -1.0 / 40;
  // Dense output coefficients (Shampine's 4th-order interpolant as in Hairer's contd5).
  constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                   d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                   d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

  State& k1 = carry.k1;
  if (!carry.have_k1) {
    k1 = f(t, y);
    carry.have_k1 = true;
  }
  int rejected = 0;
  for (;;) {
    const double h = std::min(carry.h, t_end - t);
    const bool last = h >= t_end - t;
    const State k2 = f(t + c2 * h, State(y + h * (a21 * k1)));
    const State k3 = f(t + c3 * h, State(y + h * (a31 * k1 + a32 * k2)));
    const State k4 = f(t + c4 * h, State(y + h * (a41 * k1 + a42 * k2 + a43 * k3)));
    const State k5 = f(t + c5 * h, State(y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4)));
    const State k6 = f(t + h, State(y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5)));
    const State y1 = y + h * (a71 * k1 + a73 * k3 + a74 * k4 + a75 * k5 + a76 * k6);
    const State k7 = f(t + h, y1);
    const State err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    // The scaled error, as one array expression: Eigen divides two components at a time.
    auto sc = (tol.abs_tol + tol.rel_tol * y.array().abs().max(y1.array().abs())).eval();
    if constexpr (N >= 6) {
      if (tol.position_time > 0.0) {
        const double rate = std::max(y.template segment<3>(3).norm(), y1.template segment<3>(3).norm());
        sc.template head<3>().setConstant(tol.abs_tol + tol.rel_tol * tol.position_time * rate);
      }
    }
    const double norm = std::sqrt((err.array() / sc).square().sum() / N);
    // Standard controller: safety 0.9, growth limited to [0.2, 5].
    // A NaN norm is a trial whose stages overflowed (a step far too long for a stiff drag,
    // e.g. a 10 g ball of 20 cm at 40 m/s): rejected with the smallest factor like any huge
    // error. At h_min it is accepted, so the caller sees the non-finite state and refuses it
    // instead of rejecting forever.
    const double factor = std::isnan(norm) ? 0.2 : step_growth(norm);
    if (norm <= 1.0 || h <= tol.h_min) {
      dense.t0 = t;
      dense.h = h;
      dense.r1 = y;
      dense.r2 = y1 - y;
      dense.r3 = h * k1 - dense.r2;
      dense.r4 = dense.r2 - h * k7 - dense.r3;
      dense.r5 = h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);
      t = last ? t_end : t + h;
      y = y1;
      k1 = k7;
      // After a step truncated at t_end keep the larger of the old and new proposals.
      carry.h = std::min(last ? std::max(carry.h, h * factor) : h * factor, tol.h_max);
      return rejected;
    }
    ++rejected;
    carry.h = std::max(h * factor, tol.h_min);
  }
}

}  // namespace sweetspot
