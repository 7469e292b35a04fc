// run_shot(): delivery -> impact -> launch -> step() until the sport's rules end the play
// -> ShotResult (DESIGN §1's one data path). Deterministic and safe to call from many
// threads on one Assets.
#pragma once

#include <string>

#include "game/content/resolve.hpp"
#include "game/content/scenario.hpp"
#include "game/core/shot_result.hpp"

namespace sweetspot {

struct RunOptions {
  bool fly = true;             ///< false: delivery and launch only (fit, fast sweeps)
  bool record_samples = true;  ///< false: summary only (sweeps, benchmarks)
};

/// Delivery -> impact -> launch -> flight on the shot's world under its sport's rules.
/// `name` labels the result (the scenario's name). Throws InputError when the impact
/// launches a ball the flight model refuses (named, with the scenario).
ShotResult run_shot(const ResolvedShot& shot, const std::string& name, const RunOptions& options = {});

/// The launch state (world frame) and impact of `shot`, without flying: what run_shot
/// flies. Exposed for `fit` and tests.
ShotResult launch_shot(const ResolvedShot& shot, const std::string& name);

/// Delivery -> impact -> launch, then the ball over endless flat ground of `surface` at the
/// level it was struck from, to rest: how far the stroke goes on a flat green of that speed
/// (m, horizontal). The putting preview's distances come from this same physics.
double flat_roll_distance(const ResolvedShot& shot, const SurfaceMaterial& surface);

/// run_shot(scenario.resolved, scenario.name, options).
ShotResult run_scenario(const Scenario& s, const RunOptions& options = {});

}  // namespace sweetspot
