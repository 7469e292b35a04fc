// Baseball's rules for one batted ball. A ball that crosses the outfield fence line going
// out, in the air and above the fence, is a home run: it flies on over field level to give
// the batted-ball distance, and the play ends where it lands. Crossing is decided on each
// step's path before anything else happens in that step (a ball that crosses and lands
// beyond in the same step is still a home run). A ball that first lands on a surface
// marked out of bounds (the stands) is dead there, and so is one that bounces or
// rolls into them. Leaving the world is out of bounds.
#pragma once

#include <optional>

#include "game/rules/shot_rules.hpp"
#include "physics/ground.hpp"

namespace sweetspot {

class BaseballShotRules final : public ShotRules {
 public:
  BaseballShotRules(const WorldAsset* world, const ShotModel& model);
  const ShotModel& model() const override { return home_run_ ? field_model_ : model_; }
  bool observe(const ShotState& before, const ShotState& after, const ShotEvent& event) override;
  ShotEnd outcome(const ShotState& last) const override;

  /// Where the path from `before` to `after` (one airborne step, `v_end` its velocity at
  /// `after`) crosses the fence line going out, with the ball's height there; nothing when
  /// it does not. Exposed for tests.
  std::optional<Vec3> fence_crossing(const ShotState& before, const ShotState& after, const Vec3& v_end) const;

 private:
  const WorldAsset* world_;
  const ShotModel& model_;
  FlatGround field_level_;
  ShotModel field_model_;
  bool home_run_ = false;
  bool dead_ball_ = false;
};

}  // namespace sweetspot
