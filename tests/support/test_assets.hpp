// Test fixtures shared by the suites: the shipped Assets context (one per test process,
// loaded lazily like the program's own) and short-hands for the models tests fly with.
#pragma once

#include "game/content/assets.hpp"
#include "game/content/course_file.hpp"
#include "game/core/shot_spec.hpp"
#include "physics/flight.hpp"

namespace sweetspot::test {

/// The assets folder of the source tree, loaded on first use.
const Assets& assets();
/// The built-in Sweetspot Links course, loaded on first use.
const Course& links();

/// A golf ball with the golf sport's default aero model (tour_fit) in the default environment over `terrain`
/// (nullptr = the flat fairway).
ShotModel golf_model(const Terrain* terrain = nullptr, const Environment& env = {}, const FlightSettings& settings = {});
/// A baseball with Nathan's model.
ShotModel baseball_model(const Terrain* terrain = nullptr, const Environment& env = {},
                         const FlightSettings& settings = {});

/// A launch with everything it flies through, as the tests write it: a ShotModel's inputs
/// plus the launch state. fly() makes the model and simulates.
struct FlightCase {
  LaunchState launch;
  BallProperties ball;                 ///< golf ball by default
  Environment environment;
  const AeroModel* aero = nullptr;     ///< nullptr = golf's default (tour_fit)
  FlightSettings settings;
  bool record_samples = true;
};
/// simulate_shot(make_shot_model(...), c.launch, c.record_samples) over `terrain`.
ShotTrajectory fly(const FlightCase& c, const Terrain* terrain = nullptr);
/// A launch-monitor shot for the one way in (resolve -> run_shot): the sport's default ball,
/// world and rules, from ball speed (mph), launch angle (deg), spin (rpm) and direction (deg).
ShotSpec launch_spec(const char* sport, double mph, double launch_deg, double rpm, double direction_deg = 0.0);

/// A golf launch from launch-monitor numbers at the origin tee (ball on the ground).
FlightCase golf_launch(double mph, double launch_deg, double rpm, const char* model = "tour_fit");

}  // namespace sweetspot::test
