#include "game/ui/pitch_words.hpp"

#include <cstdio>

#include "game/modes/baseball/pitcher.hpp"

namespace sweetspot {

// The zone in thirds (low, at the belt, high; in, over the middle, away from his side);
// outside it, the same words say which way it missed.
std::string pitch_for_batter(const Vec3& plate, double r, bool batter_left, bool toward, double run_in) {
  const double third_h = (StrikeZone::kHigh - StrikeZone::kLow) / 3.0, third_w = 2.0 * StrikeZone::kHalfWidth / 3.0;
  const double y = plate.y();
  // + toward the batter: a right-hander stands on the third-base side (z < 0).
  const double in = batter_left ? plate.z() : -plate.z();
  const char* height = y < StrikeZone::kLow + third_h ? "low" : y > StrikeZone::kHigh - third_h ? "high" : "";
  const char* side = in > third_w / 2.0 ? "in" : in < -third_w / 2.0 ? "away" : "";
  std::string where = *height && *side ? std::string(height) + " and " + side : *height ? height : *side ? side : "down the middle";
  const bool zone = StrikeZone::contains(plate, r);
  char text[160];
  std::snprintf(text, sizeof text, "For you: crossed %s, %s; ran %.0f in %s", where.c_str(), zone ? "in the zone" : "out of the zone",
                run_in, toward ? "toward you" : "away from you");
  return text;
}

}  // namespace sweetspot
