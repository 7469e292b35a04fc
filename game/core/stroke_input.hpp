// What a golfer's swing input is, as plain data: the three-click meter's result and the
// stroke it plays (club, aim). Made by the window's meter, the bots, a swings file and the
// tests alike; the mapping to a club delivery is game/modes/golf/swing_meter.
#pragma once

#include <string>

#include "physics/range.hpp"
#include "physics/math.hpp"

namespace sweetspot {

struct MeterInput {
  double power = 1.0;          ///< fraction of a full swing; 1 = full, up to 1.1 over-swung
  static constexpr Range kPower{0.0, 1.1, true};  ///< (0, 110 %]
  /// ms the accuracy click missed the mark; + late (face open: push and slice for a
  /// right-hander), − early (closed: pull and hook). A good player is within ~10 ms.
  double accuracy_ms = 0.0;
  static constexpr Range kAccuracy{-200.0, 200.0};
};

struct StrokeInput {
  std::string club;           ///< a club of golf_bag()
  double aim = 0.0;           ///< rad, + right of the line from the ball to the cup
  static constexpr Range kAim{-kPi / 2, kPi / 2};
  MeterInput meter;
};

/// Throws InputError naming meter.power / meter.accuracy and the range.
void validate_meter(const MeterInput& m);

}  // namespace sweetspot
