#include "game/modes/replay.hpp"

#include <algorithm>

namespace sweetspot {

void ReplayState::advance(double dt, double duration) {
  if (!playing) return;
  time += dt * speed;
  if (time >= duration) {
    time = duration;
    playing = false;
  }
}

void ReplayState::scrub(double t, double duration) {
  time = std::clamp(t, -pre_roll, std::max(0.0, duration));
}

double duration(const ShotTrajectory& shot) {
  return shot.samples.empty() ? 0.0 : shot.samples.back().t;
}

}  // namespace sweetspot
