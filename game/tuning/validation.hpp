// `sweetspot validate`: every published reference of the library (game/content/
// validation_file) run through the one shot path (scenario -> ShotSpec -> run_shot) or the
// pitch path (throw_pitch), and compared with what was published.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "game/content/assets.hpp"
#include "game/content/validation_file.hpp"

namespace sweetspot {

struct ValidationOutcome {
  const ValidationCase* c = nullptr;
  double got = 0.0;      ///< SI; for a case with a baseline, the change from it
  bool passed = false;
  /// (got - published) / tolerance: how far out, in the case's own tolerances; |x| <= 1 passes.
  double error_in_tolerances() const;
};

/// The library's folder: <assets root>/validation.
std::filesystem::path validation_dir(const Assets& assets);

/// Runs one case. A condition the schema refuses -> InputError naming the case's file:line.
ValidationOutcome run_validation_case(const Assets& assets, const ValidationCase& c);

/// Runs the cases whose tags include `filter` (all when empty), on all cores; results in
/// library order, identical to running them one by one.
std::vector<ValidationOutcome> run_validation(const Assets& assets, const ValidationLibrary& lib,
                                              const std::string& filter = {});

}  // namespace sweetspot
