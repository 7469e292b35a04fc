// Micro-benchmark of the impulse solver (DESIGN §8: `sweetspot bench` impact solves/s).
#pragma once

#include <vector>

#include "game/content/equipment_file.hpp"
#include "physics/impact.hpp"

namespace sweetspot {

/// A varied set of realistic impacts: every club of the default bag at tour speeds with
/// centre and off-centre strikes and face/path variations, and both bats along the barrel
/// with undercut and overcut. Deterministic; built through the real delivery code.
std::vector<ImpactInput> realistic_impacts(const EquipmentCatalog& equipment);

/// Times solve_impact() on realistic_impacts(), repeated until at least `min_seconds` of
/// wall time have passed (one thread). Returns solves per second. Every result feeds a
/// checksum that is written to a volatile, so the compiler cannot drop the work.
double measure_impact_solves_per_s(const EquipmentCatalog& equipment, double min_seconds);

}  // namespace sweetspot
