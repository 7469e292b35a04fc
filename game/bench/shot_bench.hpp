// Whole-shot benchmarks (DESIGN §8): tour golf launches and a baseball shot launch to rest on the asset
// worlds with our integrator + Bullet collision world, the same launches through the
// Bullet-dynamics baseline (ground built once), and both carry errors against a
// tight-tolerance reference. `sweetspot bench` calls these.
#pragma once

#include <vector>

#include "physics/launch.hpp"
#include "game/content/assets.hpp"
#include "physics/world.hpp"

namespace sweetspot::bench {

struct ShotBenchResult {
  int shots = 0;               ///< shots simulated
  double seconds = 0.0;        ///< wall time spent simulating them
  double us_per_shot = 0.0;    ///< µs per whole shot (launch to rest)
  double shots_per_second = 0.0;
  double mean_total_m = 0.0;   ///< keeps the work observable; also a sanity figure
};

/// A named launch of the fixed golf set.
struct BenchLaunch {
  const char* name;
  LaunchState launch;
};
/// The fixed set of tour launches the golf benchmarks cycle through: TrackMan PGA driver
/// (167 mph, 10.9°, 2686 rpm), 7-iron (120 mph, 16.3°, 7097 rpm), PW (102 mph, 24.2°, 9304 rpm).
std::vector<BenchLaunch> bench_tour_launches();

/// The tour launches in turn on golf_hole, launch to rest, samples off, for at least
/// `min_seconds`. The world is loaded and built once, outside the timing. `method` picks the
/// world's sweep narrow phase (BulletConvexSweep is DESIGN §5's convexSweepTest).
ShotBenchResult bench_golf_shots(const Assets& assets, double min_seconds, SweepMethod method = SweepMethod::BvhExact);
/// The same launches from the 1st tee of the bundled 18-hole course (assets/courses/national,
/// an imported map and raster: ~236 000 triangles against golf_hole's few thousand).
ShotBenchResult bench_course_shots(const Assets& assets, double min_seconds);
/// The same launches over the flat default fairway (no world): what the terrain costs.
ShotBenchResult bench_golf_shots_flat(const Assets& assets, double min_seconds);
/// The same launches on golf_hole at the reference tolerance (rel 1e-13, as
/// golf_carry_errors' reference): what the default tolerances save.
ShotBenchResult bench_golf_shots_tight(const Assets& assets, double min_seconds);
/// 103 mph, 28°, 2000 rpm on the ballpark (a home run: flight to the field-level landing).
ShotBenchResult bench_baseball_shots(const Assets& assets, double min_seconds);
/// The same tour launches through the Bullet-dynamics baseline on golf_hole's ground, to rest.
ShotBenchResult bench_baseline_golf_shots(const Assets& assets, double min_seconds);

/// One launch's carry on golf_hole (m): reference (our integrator at rel_tol 1e-13), ours
/// at the default tolerance, and the 240 Hz baseline, with the absolute errors.
struct CarryError {
  const char* name = "";
  double reference_m = 0.0;
  double ours_m = 0.0;
  double baseline_m = 0.0;
  double ours_error_m = 0.0;
  double baseline_error_m = 0.0;
};
/// Every tour launch's carry error; the headline errors are the worst over the set (m).
struct CarryErrors {
  std::vector<CarryError> shots;
  double ours_error_m = 0.0;
  double baseline_error_m = 0.0;
};
CarryErrors golf_carry_errors(const Assets& assets);

}  // namespace sweetspot::bench
