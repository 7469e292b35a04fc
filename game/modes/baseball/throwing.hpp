// A fielder's throw through the air (the fielding model of batting.hpp): how long the ball
// takes to reach a base, flown by the same flight model as every baseball, so a long throw
// pays for its drag and the arc it needs instead of crossing at a fixed fraction of its
// release speed.
#pragma once

#include "physics/aero.hpp"
#include "physics/atmosphere.hpp"
#include "physics/flight.hpp"

namespace sweetspot {

/// The flattest throw from release to a glove at the base.
struct Throw {
  double time = 0.0;       ///< s in the air
  double elevation = 0.0;  ///< rad above horizontal at release
};

/// The quickest throw that covers `distance` (m, horizontal) at release speed `arm_speed`
/// (m/s; Statcast's outfield arm strength 86–90 mph = 38–40 m/s) with the backspin of a
/// four-seam grip, released 1.8 m up and caught 1.0 m up: the flattest arc that carries that
/// far in the air (its elevation solved on the rising branch), or a relay through a cutoff
/// man halfway (two throws of half the distance with `relay_transfer` seconds between them)
/// when that is quicker: always past the arm's reach in the air (~105 m at 86 mph), and for a
/// high lob just inside it. A throw under 5 m is a toss on a line: distance / speed.
/// The air is `env`'s (altitude, temperature, humidity) without its wind. Deterministic.
/// Throws InputError unless `arm_speed` is in (0, 60] m/s, `distance` in [0, 1000] m and
/// `relay_transfer` in [0, 10] s.
Throw throw_to(const AeroModel& aero, const Environment& env, double arm_speed, double distance,
               double relay_transfer);

/// throw_to() for one fielder's arm and several distances (the bases he might throw to):
/// the air and the arm's reach in it are worked out once. Same results as throw_to().
class Thrower {
 public:
  /// Throws InputError unless `arm_speed` is in (0, 60] m/s and `relay_transfer` in [0, 10] s.
  Thrower(const AeroModel& aero, const Environment& env, double arm_speed, double relay_transfer);
  /// Throws InputError unless `distance` is in [0, 1000] m.
  Throw to(double distance) const;

 private:
  struct Flown {
    double carry = 0.0, time = 0.0;  ///< m, s
  };
  Flown fly(double elevation) const;

  ShotModel model_;
  double arm_speed_, relay_transfer_;
  Flown lowest_, highest_;  ///< the throws on a line down and at the highest useful arc
};

}  // namespace sweetspot
