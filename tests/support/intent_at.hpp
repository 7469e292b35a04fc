// A player's intent of kind `k` at time `t` (s), as the window hands it to a mode's model.
#pragma once

#include "game/modes/intent.hpp"

namespace sweetspot::test {

inline Intent at(IntentKind k, double t) {
  Intent in;
  in.kind = k;
  in.time = t;
  return in;
}

}  // namespace sweetspot::test
