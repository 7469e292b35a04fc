// A pitch in the batter's words (game/ui/pitch_words.hpp): where it crossed for him, and
// which way it ran.
#include <catch2/catch.hpp>

#include "game/modes/baseball/pitcher.hpp"
#include "game/ui/pitch_words.hpp"

using namespace sweetspot;

TEST_CASE("where a pitch crossed is said from the batter's side of the plate", "[pitch_words]") {
  constexpr double r = 0.0366;
  const double knees = StrikeZone::kLow + 0.05, belt = 0.5 * (StrikeZone::kLow + StrikeZone::kHigh);
  // A right-hander stands on the third-base side (z < 0): a pitch toward first base is away.
  CHECK(pitch_for_batter(Vec3(0, knees, 0.15), r, false, false, 7.0) ==
        "For you: crossed low and away, in the zone; ran 7 in away from you");
  // The same pitch to a left-hander is low and in.
  CHECK(pitch_for_batter(Vec3(0, knees, 0.15), r, true, true, 7.0) == "For you: crossed low and in, in the zone; ran 7 in toward you");
  CHECK(pitch_for_batter(Vec3(0, belt, 0.0), r, false, true, 15.0) ==
        "For you: crossed down the middle, in the zone; ran 15 in toward you");
  // Outside the zone the same words say which way it missed.
  CHECK(pitch_for_batter(Vec3(0, StrikeZone::kHigh + 0.2, 0.0), r, false, false, 2.0) ==
        "For you: crossed high, out of the zone; ran 2 in away from you");
  CHECK(pitch_for_batter(Vec3(0, belt, -0.45), r, false, false, 2.0) == "For you: crossed in, out of the zone; ran 2 in away from you");
}
