#include "game/bench/sweep_bench.hpp"

#include <chrono>
#include <exception>
#include <thread>
#include <vector>

#include "game/scenario/sweep.hpp"

namespace sweetspot {

SweepThroughput measure_sweep(int threads, int points_per_axis) {
  const Scenario base = load_scenario("golf/driver", {});
  SweepOptions o;
  o.e = GridAxis{0.70, 0.86, points_per_axis};
  o.mu = GridAxis{0.20, 0.60, points_per_axis};
  o.threads = threads;
  // Every worker builds its own collision world on first use (tens of ms) and keeps it per
  // thread. Running the sweep from a fresh thread makes every thread count pay that, as a
  // `sweetspot sweep` process does, instead of the 1-thread run reusing this thread's world.
  std::vector<SweepPoint> points;
  std::exception_ptr error;
  double s = 0.0;
  std::thread runner([&] {
    try {
      const auto t0 = std::chrono::steady_clock::now();
      points = run_sweep(base, o);
      s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    } catch (...) {
      error = std::current_exception();
    }
  });
  runner.join();
  if (error) std::rethrow_exception(error);
  SweepThroughput r;
  r.threads = threads;
  r.shots = static_cast<int>(points.size());
  r.shots_per_s = s > 0.0 ? static_cast<double>(points.size()) / s : 0.0;
  return r;
}

}  // namespace sweetspot
