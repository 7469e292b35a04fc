#include "physics/trajectory.hpp"

namespace sweetspot {

const char* to_string(Phase p) {
  switch (p) {
    case Phase::Flight: return "flight";
    case Phase::Bounce: return "bounce";
    case Phase::Roll: return "roll";
    case Phase::Rest: return "rest";
  }
  return "?";
}

const char* to_string(EndReason r) {
  switch (r) {
    case EndReason::Rest: return "rest";
    case EndReason::OutOfBounds: return "out_of_bounds";
    case EndReason::Water: return "water";
    case EndReason::HomeRun: return "home_run";
    case EndReason::Fence: return "fence";
    case EndReason::StepLimit: return "step_limit";
  }
  return "?";
}

}  // namespace sweetspot
