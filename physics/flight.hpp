// The shot after launch: flight under gravity, drag, Magnus lift and spin decay (DESIGN §4),
// then bounces and roll on the ground (DESIGN §5) until the ball rests or leaves play.
//
// The ball is moved by our own Dormand–Prince 5(4) integrator; the landing instant is the
// root of the ball's distance to the contact plane on the step's dense output, so carry
// converges to micrometres at the default tolerance instead of depending on a frame rate.
#pragma once

#include <string>

#include "physics/aero.hpp"
#include "physics/atmosphere.hpp"
#include "physics/ground.hpp"
#include "physics/launch.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

/// Integration and termination settings. Defaults give carry converged to ~1e-6 m.
struct FlightSettings {
  double rel_tol = 1e-8;         ///< integrator relative tolerance per step
  double abs_tol = 1e-9;         ///< integrator absolute tolerance (m, m/s, rad/s)
  /// Relative tolerance once the ball has landed (the hops after the carry); the carry
  /// itself always uses rel_tol. The bounces' own model error (turf e, µ) is ~1e-2.
  double bounce_rel_tol = 1e-6;
  double max_time = 60.0;        ///< s; a shot that has not ended by then ends with StepLimit
  int max_steps = 200000;        ///< integrator + roll steps bound
  bool record_samples = true;    ///< fill ShotTrajectory::samples (off for benchmarks)
  double sample_interval = 1.0 / 60.0;  ///< s between flight samples (rendering)
  double roll_speed = 0.25;      ///< m/s; a bounce leaving slower than this along the normal starts the roll
  double rest_speed = 0.02;      ///< m/s; below it a ball that the slope cannot move is at rest
};

struct FlightInput {
  LaunchState launch;                 ///< ball state at separation (world frame, SI)
  BallProperties ball;                ///< golf ball by default
  Environment environment;            ///< air and wind
  const AeroModel* aero = nullptr;    ///< required: aero_model("ferguson2022"), ...
  FlightSettings settings;
};

/// Work counters of one simulated shot (benchmarks, tests).
struct FlightStats {
  int flight_steps = 0;     ///< accepted integrator steps
  int rejected_steps = 0;   ///< rejected integrator trials
  int sweeps = 0;           ///< terrain sweeps issued
  int roll_steps = 0;
};

/// Empty when `in` is valid, otherwise a message naming the field and its allowed range.
std::string validate_flight_input(const FlightInput& in);

/// Flies, bounces and rolls the ball to the end. `terrain` == nullptr is an infinite flat
/// fairway at y = 0 (so flight works without a world); pass a World (physics/world.hpp)
/// for a course or ballpark. Throws InputError on invalid input; deterministic.
ShotTrajectory simulate_shot(const FlightInput& in, const Terrain* terrain, FlightStats* stats = nullptr);

}  // namespace sweetspot
