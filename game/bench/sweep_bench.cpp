#include "game/bench/sweep_bench.hpp"

#include <chrono>

#include "game/tuning/sweep.hpp"

namespace sweetspot {

SweepThroughput measure_sweep(const Assets& assets, int threads, int points_per_axis) {
  const Scenario base = load_scenario(assets, "golf/driver", {});
  SweepOptions o;
  o.e = GridAxis{0.70, 0.86, points_per_axis};
  o.mu = GridAxis{0.20, 0.60, points_per_axis};
  o.threads = threads;
  // The world is built once per process and shared by the workers: build it before the
  // clock starts so every thread count measures the same work.
  SweepOptions warm = o;
  warm.e.count = 1;
  warm.mu.count = 1;
  run_sweep(base, warm);
  const auto t0 = std::chrono::steady_clock::now();
  const auto points = run_sweep(base, o);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  SweepThroughput r;
  r.threads = threads;
  r.shots = static_cast<int>(points.size());
  r.shots_per_s = s > 0.0 ? static_cast<double>(points.size()) / s : 0.0;
  return r;
}

}  // namespace sweetspot
