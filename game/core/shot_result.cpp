#include "game/core/shot_result.hpp"

#include <cmath>

namespace sweetspot {

const char* to_string(ShotEnd e) {
  switch (e) {
    case ShotEnd::Rest: return "rest";
    case ShotEnd::Holed: return "holed";
    case ShotEnd::Water: return "water";
    case ShotEnd::OutOfBounds: return "out_of_bounds";
    case ShotEnd::HomeRun: return "home_run";
    case ShotEnd::StepLimit: return "step_limit";
  }
  return "?";
}

double side_of_aim(const ShotResult& r, const Vec3& p) {
  const Vec3 right(-std::sin(r.aim), 0.0, std::cos(r.aim));
  return (p - r.launch_state.position).dot(right);
}

}  // namespace sweetspot
