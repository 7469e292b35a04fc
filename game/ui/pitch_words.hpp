// A pitch in the batter's words, beside Statcast's: where it crossed the plate for him (the
// zone in thirds, or which way it missed it) and which way it ran.
#pragma once

#include <string>

#include "physics/math.hpp"

namespace sweetspot {

/// "For you: crossed low and away, out of the zone; ran 7 in away from you". `plate`: where
/// the ball's centre crossed the plate's front (m; y up, z + toward first base), `r` the ball's
/// radius, `toward`: its run was toward the batter, `run_in` its size (in).
std::string pitch_for_batter(const Vec3& plate, double r, bool batter_left, bool toward, double run_in);

}  // namespace sweetspot
