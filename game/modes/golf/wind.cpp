#include "game/modes/golf/wind.hpp"

#include <algorithm>
#include <cmath>

#include "game/util/rng.hpp"
#include "physics/math.hpp"

namespace sweetspot {

std::vector<HoleWind> round_winds(const Course& course, std::uint64_t seed) {
  // A stream of its own: the bots' generators start from the same seed.
  Rng rng(seed ^ 0x57494E44ULL);  // "WIND"
  // Rayleigh: the mean is sigma·sqrt(pi/2); a draw is sigma·sqrt(-2 ln(1 - u)).
  const double sigma = kMeanWind / std::sqrt(kPi / 2.0);
  std::vector<HoleWind> out;
  for (const CourseHole& h : course.holes) {
    const double u = rng.uniform(), dir = rng.uniform();
    HoleWind w;
    if (h.wind_speed) {
      w.speed = *h.wind_speed;
      w.toward = h.wind_toward;
    } else {
      w.speed = std::min(sigma * std::sqrt(-2.0 * std::log(1.0 - u)), kMaxDrawnWind);
      w.toward = std::remainder(2.0 * kPi * dir, 2.0 * kPi);
    }
    out.push_back(w);
  }
  return out;
}

}  // namespace sweetspot
