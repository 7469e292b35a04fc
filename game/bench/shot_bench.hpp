// Whole-shot benchmarks (DESIGN §8): driver and baseball shots launch to rest on the asset
// worlds with our integrator + Bullet collision world, the same launches through the
// Bullet-dynamics baseline (ground built once), and both carry errors against a
// tight-tolerance reference. `sweetspot bench` calls these.
#pragma once

#include "physics/launch.hpp"

namespace sweetspot::bench {

struct ShotBenchResult {
  int shots = 0;               ///< shots simulated
  double seconds = 0.0;        ///< wall time spent simulating them
  double us_per_shot = 0.0;    ///< µs per whole shot (launch to rest)
  double shots_per_second = 0.0;
  double mean_total_m = 0.0;   ///< keeps the work observable; also a sanity figure
};

/// TrackMan PGA driver (167 mph, 10.9°, 2686 rpm) on golf_hole, samples off, for at least
/// `min_seconds`. The world is loaded and built once, outside the timing.
ShotBenchResult bench_golf_shots(double min_seconds);
/// 103 mph, 28°, 2000 rpm on the ballpark (a home run: flight to the field-level landing).
ShotBenchResult bench_baseball_shots(double min_seconds);
/// The driver launch through the Bullet-dynamics baseline on golf_hole's ground, to rest.
ShotBenchResult bench_baseline_golf_shots(double min_seconds);

/// Driver carry on golf_hole: reference (our integrator at rel_tol 1e-13), ours at the
/// default tolerance, and the 240 Hz baseline, with the absolute errors (m).
struct CarryErrors {
  double reference_m = 0.0;
  double ours_m = 0.0;
  double baseline_m = 0.0;
  double ours_error_m = 0.0;
  double baseline_error_m = 0.0;
};
CarryErrors golf_carry_errors();

/// The driver launch the golf benchmarks use.
LaunchState bench_driver_launch();

}  // namespace sweetspot::bench
