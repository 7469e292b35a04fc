// Base running after a ball in play (DESIGN §9): who scores, who is out, who stands where.
// Each runner takes the bases the hit gives him, and one more when he would reach it with
// time to spare before the fielder's throw; on a ground out the forced runners run and the
// others go only when the throw to their base cannot beat them; on a caught fly they tag up,
// and a runner caught off his base is doubled off. Every such decision is made on the
// estimate, and the throw as it comes (kThrowSpread: its line, its hop, the tag) decides the
// play, so some runners who are sent are thrown out.
#pragma once

#include <string>
#include <vector>

#include "game/modes/baseball/ball_game.hpp"
#include "game/util/rng.hpp"

namespace sweetspot {

/// A half-inning's base runners and outs.
struct HalfInning {
  const AeroModel* aero = nullptr;
  Environment environment;
  Bases bases{-1, -1, -1};
  int outs = 0;
  /// Runs that would win the game now (a walk-off), 0 when none would: once they score no
  /// one is put out.
  int runs_to_win = 0;

  /// The runners' part of a ball in play (the batter's is `pa`'s result). Runs scored push
  /// the runner to `scored`; `outs_made` counts the batter's out and the runners'; the
  /// runners' outs are added to `description`. `throws` draws the throws as they come.
  void advance(const PlateAppearance& pa, const Team& batting, const Team& fielding, Rng& throws, std::vector<int>& scored,
               int& outs_made, std::string& description);
};

/// Seconds a runner with top speed `top_speed` m/s takes over `distance` m starting at
/// `start_speed` m/s: he closes on his top speed as a sprinter does, v(t) = v_max − (v_max −
/// v0)·e^(−t/τ) (τ 0.4 s, from MLB's steal times), so once up to speed he trails a runner at
/// top speed all the way by τ(1 − v0/v_max).
double sprint_time(double top_speed, double distance, double start_speed);

/// How many of the bases have a runner on them.
int runners_on(const Bases& b);

/// A half-inning's start: bases empty, no outs, in the sport's air (assets' baseball
/// defaults), which the throws fly through.
HalfInning empty_half_inning(const Assets& assets);

}  // namespace sweetspot
