#include "game/rules/golf_rules.hpp"

namespace sweetspot {

ShotEnd GolfShotRules::outcome(const ShotState& last) const {
  if (!last.ended) return ShotEnd::Rest;
  switch (last.end) {
    case EndReason::StepLimit: return ShotEnd::StepLimit;
    case EndReason::LeftWorld: return ShotEnd::OutOfBounds;
    case EndReason::InCup: return ShotEnd::Holed;
    case EndReason::Rest: break;
  }
  const SurfaceKind kind = model_.terrain->material(last.support.material).kind;
  if (kind == SurfaceKind::Water) return ShotEnd::Water;
  if (kind == SurfaceKind::OutOfBounds) return ShotEnd::OutOfBounds;
  (void)world_;
  return ShotEnd::Rest;
}

}  // namespace sweetspot
