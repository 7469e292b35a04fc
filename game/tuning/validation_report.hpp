// What `sweetspot validate` prints: the scorecard for people (by tag, with and without the
// fitted references, the worst cases in tolerance units), the JSON for scripts
// (docs/validation.md) and JUnit XML for CI.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/tuning/validation.hpp"

namespace sweetspot {

struct ValidationTally {
  int passed = 0, failed = 0;
  int total() const { return passed + failed; }
  double percent() const { return total() ? 100.0 * passed / total() : 100.0; }
};

/// All cases; and those not used in any fit.
struct ValidationTotals {
  ValidationTally all, not_fitted;
  int sources = 0;  ///< distinct sources among the cases run
};
ValidationTotals validation_totals(const std::vector<ValidationOutcome>& outcomes);

/// The scorecard, ending with the line "validate: N passed, M failed". `worst` caps the
/// list of worst cases (every failing case is listed, then passing ones nearest their edge).
std::string validation_scorecard(const std::vector<ValidationOutcome>& outcomes, std::size_t worst = 25);

nlohmann::json validation_json(const ValidationLibrary& lib, const std::vector<ValidationOutcome>& outcomes);

/// One <testsuite> per sport tag, one <testcase> per reference.
std::string validation_junit(const ValidationLibrary& lib, const std::vector<ValidationOutcome>& outcomes);

}  // namespace sweetspot
