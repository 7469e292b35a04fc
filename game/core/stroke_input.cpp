#include "game/core/stroke_input.hpp"

#include "physics/error.hpp"

namespace sweetspot {

void validate_meter(const MeterInput& m) {
  check_range("meter.power", m.power, MeterInput::kPower, "");
  check_range("meter.accuracy", m.accuracy_ms, MeterInput::kAccuracy, "ms");
}

}  // namespace sweetspot
