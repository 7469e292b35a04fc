// A sport's rules watching one shot (DESIGN §1: rules outside physics). Physics steps the
// ball and reports events; the rules read them with the world's marked features (fence
// line, pin, surfaces) and decide how the play ends: a home run, a ball in the stands, out
// of bounds, water, holed. They may also end the play before the ball rests (a home run
// is decided once it lands beyond the fence) or change what the ball flies over.
#pragma once

#include <memory>
#include <string>

#include "game/content/world_asset.hpp"
#include "game/core/shot_result.hpp"
#include "game/core/sport.hpp"
#include "physics/flight.hpp"

namespace sweetspot {

class ShotRules {
 public:
  virtual ~ShotRules() = default;
  /// The model to take the next step with (the rules may swap the ground under a ball that
  /// has left the field).
  virtual const ShotModel& model() const = 0;
  /// After each physics step: the state before it, after it, and its event. Returns true
  /// when the play is over now, before the physics ends it.
  virtual bool observe(const ShotState& before, const ShotState& after, const ShotEvent& event) = 0;
  /// How the play ended, given the last state.
  virtual ShotEnd outcome(const ShotState& last) const = 0;
};

/// The rules named by a sport's profile ("golf", "baseball") for a shot on `world`
/// (nullptr: the flat ground) flown with `model`. The model and world must outlive them.
std::unique_ptr<ShotRules> make_shot_rules(const SportProfile& sport, const WorldAsset* world, const ShotModel& model);

}  // namespace sweetspot
