// The soaks' random numbers: SplitMix64, tiny, portable and identical on every compiler (the
// std distributions are not), so a soak's "shot i" or "world i" is the same everywhere.
#pragma once

#include <cstdint>
#include <limits>

namespace sweetspot::soak {

struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
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
