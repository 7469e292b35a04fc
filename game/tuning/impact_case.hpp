// Impact regression cases (`case = "impact"` files in tests/regression): two bodies, a
// normal and a material, solved once by the impulse solver. They hold the textbook's
// worked examples (DESIGN §3) to the solver through the same harness as the shots.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "game/content/scenario_doc.hpp"
#include "physics/impact.hpp"

namespace sweetspot {

/// The ImpactInput a checked impact-case document describes. A scalar inertia I gives the
/// tensor I·1; `impactor.fixed = true` makes the impactor immovable (the ground). The
/// normal is normalised. Throws InputError (origin, key) when the solver would reject it.
ImpactInput impact_input_from(const CheckedDoc& doc);

/// What an impact case can check, SI, keyed by the expect names of
/// impact_case_expectations(): ball_velocity, impactor_velocity, ball_spin (3 values),
/// ball_speed, ball_direction (atan2(v_y, v_x)), ball_tangential_velocity and
/// contact_tangential_velocity (signed along the tangential direction of the approach),
/// energy_ratio (kinetic energy after / before).
struct ImpactMeasurements {
  std::map<std::string, std::vector<double>> values;
  std::string contact;  ///< "grip", "slip" or "none"
};

ImpactMeasurements measure_impact(const ImpactInput& in, const ImpactResult& out);

}  // namespace sweetspot
