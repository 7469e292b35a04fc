#include "game/modes/baseball/throwing.hpp"

#include <cmath>
#include <string>

#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/ground.hpp"
#include "physics/launch.hpp"
#include "physics/root_find.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

// Release 1.8 m up (an overhand release at shoulder height, ESTIMATE) and a glove 1.0 m up at
// the bag (ESTIMATE): the same flight as a launch 0.8 m above a ball's resting height that
// ends on flat ground.
constexpr double kDrop = 0.8;
// A four-seam grip spins the ball backward with the hand's speed: the league's four-seamer
// spins 2283 rpm at 94.19 mph (Statcast via TJStats, pitches.toml), 24.2 rpm per mph of
// release speed; an overhand throw is taken to spin the same per unit of speed.
constexpr double kBackspinPerSpeed = 2283.0 / 94.19;  // rpm per mph
// The elevations searched: a throw on a line down to the highest useful arc. Past ~35° a
// baseball's carry against drag stops growing (its longest throws leave at 30–35°).
constexpr double kLowest = -10.0 * kPi / 180.0, kHighest = 35.0 * kPi / 180.0;
constexpr double kLineToss = 5.0;  // m: a throw this short is a toss on a line

}  // namespace

Thrower::Thrower(const AeroModel& aero, const Environment& env, double arm_speed, double relay_transfer)
    : arm_speed_(arm_speed), relay_transfer_(relay_transfer) {
  if (!(arm_speed > 0.0 && arm_speed <= 60.0))
    throw InputError("throw: arm speed " + std::to_string(arm_speed) + " m/s (allowed (0, 60])");
  if (!(relay_transfer >= 0.0 && relay_transfer <= 10.0))
    throw InputError("throw: relay transfer " + std::to_string(relay_transfer) + " s (allowed [0, 10])");
  // The air's density from the day's weather; no wind: a throw goes any way across the
  // field, and the flight model here flies it along +x.
  Environment calm = env;
  calm.wind_speed = 0.0;
  model_ = make_shot_model(baseball_properties(), aero, calm, nullptr);
  lowest_ = fly(kLowest);
  highest_ = fly(kHighest);
}

Thrower::Flown Thrower::fly(double elevation) const {
  const double radius = baseball_properties().radius;
  const LaunchState launch =
      launch_from_metrics(arm_speed_, elevation, 0.0, rpm_to_radps(kBackspinPerSpeed * mps_to_mph(arm_speed_)), 0.0,
                          Vec3(0.0, radius + kDrop, 0.0));
  ShotState s = start_state(launch);
  while (!s.ended) {
    const ShotEvent e = step(model_, s);
    if (e.kind == ShotEventKind::Landing) break;
  }
  return {std::hypot(s.position().x(), s.position().z()), s.t};
}

Throw Thrower::to(double distance) const {
  if (!(distance >= 0.0 && distance <= 1000.0))
    throw InputError("throw: distance " + std::to_string(distance) + " m (allowed [0, 1000])");
  if (distance < kLineToss) return {distance / arm_speed_, 0.0};
  // A cutoff man halfway who relays it: the only way past the arm's reach in the air, and
  // quicker than a high lob just inside it.
  const auto relay = [&] {
    const Throw half = to(0.5 * distance);
    return Throw{2.0 * half.time + relay_transfer_, half.elevation};
  };
  if (distance > highest_.carry) return relay();
  // A line drive thrown down from the release reaches ~4.5 m: every throw longer than a toss
  // is past it, which keeps the root finder's bracket; the guard only protects that.
  if (distance <= lowest_.carry) return {lowest_.time * distance / lowest_.carry, kLowest};
  // Carry rises with elevation on [kLowest, kHighest]: the elevation where the throw carries
  // `distance` (to the flight integrator's own resolution, ~0.1 mm), then its time.
  const double elevation = find_root([&](double e) { return distance - fly(e).carry; }, kLowest, kHighest,
                                     distance - lowest_.carry, distance - highest_.carry);
  const Throw direct{fly(elevation).time, elevation};
  if (distance < 2.0 * kLineToss) return direct;
  const Throw relayed = relay();
  return relayed.time < direct.time ? relayed : direct;
}

Throw throw_to(const AeroModel& aero, const Environment& env, double arm_speed, double distance,
               double relay_transfer) {
  return Thrower(aero, env, arm_speed, relay_transfer).to(distance);
}

}  // namespace sweetspot
