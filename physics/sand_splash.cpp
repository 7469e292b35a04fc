#include "physics/sand_splash.hpp"

#include <algorithm>

namespace sweetspot {

double club_speed_after_sand(double speed, double head_mass, double cut_width, double entry, double density,
                             double depth) {
  // The sand swept up: the channel's cross-section times its length; its momentum comes from
  // the head (perfectly plastic: the sand leaves at the head's speed, its energy spent).
  const double swept = density * std::max(cut_width, 0.0) * std::max(depth, 0.0) * std::max(entry, 0.0);
  return speed * head_mass / (head_mass + swept);
}

}  // namespace sweetspot
