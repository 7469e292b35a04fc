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
    case EndReason::LeftWorld: return "left_world";
    case EndReason::StepLimit: return "step_limit";
    case EndReason::InCup: return "in_cup";
  }
  return "?";
}

}  // namespace sweetspot
