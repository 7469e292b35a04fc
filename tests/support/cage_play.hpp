// Playing a batting cage's pitch out in a test: frames of `step` s until the pitch is called
// and any ball in play has come down (at most 20 s of mode time).
#pragma once

#include "game/modes/baseball/cage.hpp"

namespace sweetspot::test {

inline void play_out_pitch(BattingCage& cage, double& now, double step) {
  for (double until = now + 20.0;
       now < until && (cage.stage() == BattingCage::Stage::Pitching || cage.stage() == BattingCage::Stage::Batted);)
    cage.update({}, now += step);
}

}  // namespace sweetspot::test
