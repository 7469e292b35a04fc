// Sweep throughput at a given thread count (DESIGN §8: `sweep` scales with threads).
#pragma once

#include "game/content/assets.hpp"

namespace sweetspot {

struct SweepThroughput {
  int threads = 1;
  double shots_per_s = 0.0;  ///< whole shots (delivery, impact, flight to rest) per second
  int shots = 0;             ///< grid points run
};

/// Runs the e × µ grid of golf/driver (`points_per_axis`² shots, flight to rest on the golf
/// hole, no trajectory samples) with `threads` workers and times it. The same grid at every
/// thread count, so the ratio is the scaling. The shared world is built before timing.
SweepThroughput measure_sweep(const Assets& assets, int threads, int points_per_axis);

}  // namespace sweetspot
