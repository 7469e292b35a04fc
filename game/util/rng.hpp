// A small seeded random number generator for bots and soak-style play: SplitMix64, and
// normal draws by Box–Muller. Same seed, same sequence, on every platform (no std::
// distributions, whose output the standard leaves to the library).
#pragma once

#include <cmath>
#include <cstdint>

namespace sweetspot {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Normal with mean 0 and standard deviation `sd`.
  double normal(double sd) {
    const double u1 = 1.0 - uniform(), u2 = uniform();
    return sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  std::uint64_t s_;
};

}  // namespace sweetspot
