// The air part of a scenario: Environment from the `environment.*` keys and the aero model
// from `aero.model` (default per sport). Shared by full scenarios and launch-only ones.
#pragma once

#include "game/scenario/scenario_doc.hpp"
#include "physics/aero.hpp"
#include "physics/atmosphere.hpp"

namespace sweetspot {

/// Environment from a checked scenario; validated (throws InputError naming the origin).
Environment environment_from(const CheckedDoc& doc);

/// aero.model, or the sport's default (ferguson2022 / nathan). Unknown name -> InputError
/// naming the origin and listing the models.
const AeroModel& aero_from(const CheckedDoc& doc);

}  // namespace sweetspot
