// The e × µ grid behind `sweetspot sweep`: every point is the scenario with a constant
// restitution e and friction µ, run on all cores. Results are stored by grid index, so the
// output order (e outer, µ inner, both ascending) never depends on thread timing.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/scenario.hpp"
#include "game/core/shot_result.hpp"

namespace sweetspot {

/// One axis "A:B:N": N ≥ 1 evenly spaced values from A to B inclusive (N = 1 -> A only).
struct GridAxis {
  double from = 0.0;
  double to = 0.0;
  int count = 1;
  double at(int i) const { return count == 1 ? from : from + (to - from) * i / (count - 1); }
};

/// Parses "A:B:N" for `flag` ("--e"); values must lie in [lo, hi] and N in [1, 100000].
/// Throws InputError naming the flag, the text and the allowed range.
GridAxis parse_grid_axis(std::string_view text, std::string_view flag, const Range& allowed);

/// The largest grid a sweep accepts; bigger grids are refused before any work starts.
inline constexpr std::size_t kMaxSweepPoints = 100000;

struct SweepPoint {
  double e = 0.0;
  double mu = 0.0;
  ShotResult shot;  ///< launch, impact and flight summary (no trajectory samples)
};

struct SweepOptions {
  GridAxis e, mu;
  int threads = 0;      ///< 0 = all hardware threads
  bool fly = true;      ///< false: launch numbers only (much faster)
  bool grip = true;     ///< find µ_grip for each e of the grid (game/modes/lab/grip.hpp; ~16 launches per e)
  /// Called from the calling thread about every 100 ms with (points done, total).
  std::function<void(std::size_t, std::size_t)> progress;
};

/// Runs the grid. Throws InputError when the grid exceeds kMaxSweepPoints or a point is
/// rejected by the physics (naming e and µ). Deterministic for any thread count.
std::vector<SweepPoint> run_sweep(const Scenario& base, const SweepOptions& options);

/// CSV with a header: e, mu, launch numbers, contact, mu_grip and grips (µ ≥ µ_grip: the
/// launch no longer changes with µ), flight summary (SI).
std::string sweep_csv(const std::vector<SweepPoint>& points);

}  // namespace sweetspot
