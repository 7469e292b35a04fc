// Roots of a scalar function bracketed on [a, b], g(a) > 0 >= g(b): the flight's touch and
// apex times (detail/air_step.cpp), the crater's stopping tilt (ground.cpp) and a fielder's
// throw elevation (game/modes/baseball/throwing.cpp).
#pragma once

#include <cmath>

namespace sweetspot {

/// Root of g on [a, b] with g(a) > 0 >= g(b): Illinois-modified regula falsi, which keeps
/// the bracket and converges superlinearly. Returns an x where |g| < 1e-12, or the bracket's
/// g <= 0 end once the bracket is below 1e-13 (s for a time, rad for an angle).
template <class G>
double find_root(const G& g, double a, double b, double ga, double gb) {
  int side = 0;
  for (int i = 0; i < 80; ++i) {
    double c = (a * gb - b * ga) / (gb - ga);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double gc = g(c);
    if (std::abs(gc) < 1e-12) return c;
    if (gc > 0.0) {
      a = c;
      ga = gc;
      if (side == 1) gb *= 0.5;
      side = 1;
    } else {
      b = c;
      gb = gc;
      if (side == -1) ga *= 0.5;
      side = -1;
    }
    if (b - a < 1e-13) break;
  }
  return b;
}

/// Root of g on [a, b] with g(a) > 0 >= g(b), from the guess x0, for a g whose derivative
/// is at hand: gd(t) returns {g(t), g'(t)}. Newton steps, each kept inside the shrinking
/// bracket (a bisection where one would leave it): two or three evaluations from a good
/// guess where regula falsi takes eight. Same stopping rule as find_root.
template <class GD>
double find_root_newton(const GD& gd, double a, double b, double x0) {
  double x = (x0 > a && x0 < b) ? x0 : 0.5 * (a + b);
  for (int i = 0; i < 80; ++i) {
    const auto [g, dg] = gd(x);
    if (std::abs(g) < 1e-12) return x;
    (g > 0.0 ? a : b) = x;
    if (b - a < 1e-13) break;
    double next = x - g / dg;
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    x = next;
  }
  return b;
}

}  // namespace sweetspot
