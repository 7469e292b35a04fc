// The soaks' random numbers: the game's SplitMix64 (game/util/rng.hpp: identical on every
// compiler, unlike the std distributions), so a soak's "shot i" or "world i" is the same
// everywhere, plus the draws the soaks need on top of it.
#pragma once

#include <cstdint>
#include <limits>

#include "game/util/rng.hpp"

namespace sweetspot::soak {

struct Rng {
  sweetspot::Rng g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  std::uint64_t next() { return g.next(); }
  double uniform() { return g.uniform(); }
  double in(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
  // Just outside [lo, hi]: up to 20 % of the span beyond either end, or a non-finite value.
  double outside(double lo, double hi) {
    const int k = below(8);
    if (k == 0) return std::numeric_limits<double>::quiet_NaN();
    if (k == 1) return std::numeric_limits<double>::infinity();
    const double d = (hi - lo) * in(1e-6, 0.2);
    return (k % 2 == 0) ? lo - d : hi + d;
  }
};

}  // namespace sweetspot::soak
