// Golf's rules for one shot: where the ball ends decides the play. At rest on a water
// surface: water (a penalty and a drop, game/modes). At rest on an out-of-bounds surface or
// outside the world: out of bounds (stroke and distance). At rest in the cup: holed.
#pragma once

#include "game/rules/shot_rules.hpp"

namespace sweetspot {

class GolfShotRules final : public ShotRules {
 public:
  GolfShotRules(const WorldAsset* world, const ShotModel& model) : world_(world), model_(model) {}
  const ShotModel& model() const override { return model_; }
  bool observe(const ShotState&, const ShotState&, const ShotEvent&) override { return false; }
  ShotEnd outcome(const ShotState& last) const override;

 private:
  const WorldAsset* world_;
  const ShotModel& model_;
};

}  // namespace sweetspot
