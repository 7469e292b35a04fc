// What a simulated shot produces after launch: the sampled path with its phase, and the
// summary numbers of DESIGN §6 `flight`. The renderer and reports read this; they never
// own physics state.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/math.hpp"

namespace sweetspot {

enum class Phase : std::uint8_t { Flight, Bounce, Roll, Rest };

/// Why the physics stopped a shot. Game outcomes (home run, water, out of bounds by the
/// course's stakes, holed) are decided by game/rules from the events and the final state.
enum class EndReason : std::uint8_t {
  Rest,       ///< came to rest (on the ground, in the cup, or sunk where it touched water)
  LeftWorld,  ///< left the world's bounds, or rolled off the edge of its ground
  StepLimit,  ///< hit the time or step bound (should not happen for sane input)
  InCup,      ///< dropped into the hole (physics/cup.hpp)
};

const char* to_string(Phase p);
const char* to_string(EndReason r);

/// One sample of the ball's path. Phase tells the renderer how to colour the trail.
struct TrajectorySample {
  double t = 0.0;               ///< s since launch
  Vec3 position = Vec3::Zero(); ///< m, ball centre
  Vec3 velocity = Vec3::Zero(); ///< m/s
  Vec3 spin = Vec3::Zero();     ///< rad/s
  Phase phase = Phase::Flight;
};

/// Summary of a shot, SI. Distances are measured in the horizontal plane from the launch
/// point; lateral is + to the right (z).
struct FlightSummary {
  double carry_m = 0.0;            ///< to the first landing (baseball: batted-ball distance)
  double total_m = 0.0;            ///< to the rest (or end) position
  double apex_m = 0.0;             ///< max height above the launch point
  double landing_angle_deg = 0.0;  ///< descent angle below horizontal at first landing
  double hang_time_s = 0.0;        ///< launch to first landing
  double lateral_m = 0.0;          ///< z at the first landing (world axis; the report measures from the aim line)
  double total_time_s = 0.0;       ///< launch to end
  Vec3 landing_position = Vec3::Zero();
  Vec3 rest_position = Vec3::Zero();
  EndReason end = EndReason::Rest;
  int bounces = 0;
  /// It never left the ground (a putt; its skid's first instants are no flight): its apex
  /// stays within 5 cm of the launch point.
  bool rolled_only() const { return apex_m < 0.05; }
};

/// Work counters of one simulated shot (benchmarks, tests, the step budget).
struct FlightStats {
  int flight_steps = 0;     ///< accepted integrator steps
  int rejected_steps = 0;   ///< rejected integrator trials
  int sweeps = 0;           ///< terrain sweeps issued
  int roll_steps = 0;
};

struct ShotTrajectory {
  std::vector<TrajectorySample> samples;  ///< time-ordered, first = launch, last = end
  FlightSummary summary;
  FlightStats stats;                      ///< the work it took
};

}  // namespace sweetspot
