// The sounds of the world around the play (issue 44): a holed ball dropping into the cup and
// rattling in its liner, and the ambience of a golf course (wind in the open, birds) and of a
// ballpark (a crowd's murmur). Synthesised like the strike (impact_sound.hpp), deterministic.
#pragma once

#include <vector>

#include "game/report/impact_sound.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

/// How a cup's plastic liner rings when the ball strikes it.
const Ring& cup_ring();

/// One strike of the ball on the cup: when (s after it drops in) and how.
struct CupStrike {
  double at = 0.0;
  ImpactSoundInput impact;
};

/// The ball's strikes in the cup: on the far wall at `entry_speed` (m/s, across the cup; none
/// below 0.05 m/s), then on the bottom after its 4 in fall, bouncing lower each time until it
/// rests. In time order, each softer than the last.
std::vector<CupStrike> cup_strikes(double entry_speed);

/// How fast a holed ball came in (m/s, horizontal): its speed at the last sample that still
/// moves. 0 for a trajectory without one.
double cup_entry_speed(const ShotTrajectory& holed);

/// The rattle: cup_strikes as sound, mono in [−1, 1] at `sample_rate` Hz.
std::vector<float> synthesize_cup_drop(double entry_speed, int sample_rate = kImpactSampleRate);

enum class Ambience { None, Course, Ballpark };

/// A loop of the ambience `kind` (`wind_speed` m/s for a course), `seconds` long, whose end
/// runs into its start without a click. Empty for Ambience::None.
std::vector<float> synthesize_ambience(Ambience kind, double wind_speed, int sample_rate = kImpactSampleRate,
                                       double seconds = 8.0);

}  // namespace sweetspot
