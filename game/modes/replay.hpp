// Replay clock for a computed shot: the ball flies the sampled trajectory in real time (or
// at the chosen speed), and can be paused, scrubbed and restarted. Pure logic, no window,
// so the UI behaviour is unit-tested.
#pragma once

#include "physics/trajectory.hpp"

// The ball at replay time t: sample_at() in game/render/camera.hpp.

namespace sweetspot {

struct ReplayState {
  double time = 0.0;    ///< s since launch; -pre_roll .. duration
  double speed = 1.0;   ///< playback rate; the UI offers 0.1 .. 4 (1 = real time)
  bool playing = true;  ///< false = paused (also set when the end is reached)
  /// s before launch a replay starts: the club's or bat's downswing (ShotScene::pre_roll,
  /// 0.25 s for a club); 0 = start at launch.
  double pre_roll = 0.0;

  /// R / Space: back to the start of the pre-roll (launch without one) and playing.
  void restart() {
    time = -pre_roll;
    playing = true;
  }
  /// Advances by wall-clock `dt` seconds scaled by `speed`; stops (paused) at `duration`.
  void advance(double dt, double duration);
  /// Scrub to `t`, held inside [-pre_roll, duration]. The UI's slider cannot exceed the range, so
  /// holding it here is a bound, not a silent correction of user input.
  void scrub(double t, double duration);
};

/// Time of the last sample (0 for an empty trajectory).
double duration(const ShotTrajectory& shot);

}  // namespace sweetspot
