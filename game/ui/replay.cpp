#include "game/ui/replay.hpp"

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
  time = std::clamp(t, 0.0, std::max(0.0, duration));
}

double duration(const ShotTrajectory& shot) {
  return shot.samples.empty() ? 0.0 : shot.samples.back().t;
}

TrajectorySample sample_at(const ShotTrajectory& shot, double t) {
  const auto& s = shot.samples;
  if (s.empty()) return {};
  if (t <= s.front().t) return s.front();
  if (t >= s.back().t) return s.back();
  // First sample with time > t; samples are time-ordered.
  const auto hi = std::upper_bound(s.begin(), s.end(), t,
                                   [](double v, const TrajectorySample& x) { return v < x.t; });
  const auto lo = hi - 1;
  const double span = hi->t - lo->t;
  const double a = span > 0.0 ? (t - lo->t) / span : 1.0;
  TrajectorySample out;
  out.t = t;
  out.position = lo->position + a * (hi->position - lo->position);
  out.velocity = lo->velocity + a * (hi->velocity - lo->velocity);
  out.spin = lo->spin + a * (hi->spin - lo->spin);
  out.phase = hi->phase;
  return out;
}

}  // namespace sweetspot
