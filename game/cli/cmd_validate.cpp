// `sweetspot validate [--json] [--junit FILE] [--filter TAG] [--min-pass-rate P [--min-unfitted-pass-rate Q]]
// [--library PATH]`:
// the published references of assets/validation run through the shot and pitch paths
// (docs/validation.md). Exit 0 when every case passes (with --min-pass-rate: when at least
// P % do, and Q % of those never fitted), 1 otherwise, 2 for a bad library or flag (nothing
// written).
#include <algorithm>
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/report/report.hpp"
#include "game/tuning/validation.hpp"
#include "game/tuning/validation_report.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot::cli {
namespace {

struct ValidateOptions {
  std::string library, junit, filter;
  double min_pass_rate = -1.0;
  double min_unfitted_pass_rate = -1.0;
  bool json = false;
};

RunFn setup_validate(CLI::App& sub) {
  auto o = std::make_shared<ValidateOptions>();
  sub.add_flag("--json", o->json, "print every case as JSON (SI values) instead of the scorecard");
  sub.add_option("--junit", o->junit, "also write JUnit XML to FILE (one testcase per reference), whole or not at all");
  sub.add_option("--filter", o->filter, "run only the cases with this tag (golf, baseball, launch, carry, roll, ...)");
  sub.add_option("--min-pass-rate", o->min_pass_rate,
                 "exit 0 when at least this percent of the cases pass (default: every case must)")
      ->check(finite_range(0.0, 100.0));
  sub.add_option("--min-unfitted-pass-rate", o->min_unfitted_pass_rate,
                 "with --min-pass-rate: also at least this percent of the cases no model was fitted to")
      ->check(finite_range(0.0, 100.0));
  sub.add_option("--library", o->library, "a validation file or folder (default: the assets' validation/)");
  return [o](const Assets& assets) -> int {
    // Every flag is checked before a case runs: a bad one prints nothing but its message.
    if (o->min_unfitted_pass_rate >= 0.0 && o->min_pass_rate < 0.0)
      throw InputError("--min-unfitted-pass-rate: give --min-pass-rate too (without it every case must pass)");
    if (!o->filter.empty()) {
      const auto& tags = validation_tags();
      if (std::find(tags.begin(), tags.end(), o->filter) == tags.end()) {
        std::string names;
        for (const auto t : tags) names += (names.empty() ? "" : ", ") + std::string(t);
        throw InputError("--filter " + o->filter + ": unknown tag (allowed: " + names + ")");
      }
    }
    const std::filesystem::path library = o->library.empty() ? validation_dir(assets) : std::filesystem::path(o->library);
    const ValidationLibrary lib = load_validation_library(library);
    if (!o->junit.empty()) refuse_output_over_input(o->junit, library, "--junit");
    const std::vector<ValidationOutcome> outcomes = run_validation(assets, lib, o->filter);
    if (outcomes.empty()) throw InputError("--filter " + o->filter + ": no case carries this tag");
    if (!o->junit.empty()) write_file_atomic(o->junit, validation_junit(lib, outcomes));
    if (o->json)
      std::cout << json_text(validation_json(lib, outcomes)) << "\n";
    else
      std::cout << validation_scorecard(outcomes);
    const ValidationTotals t = validation_totals(outcomes);
    if (o->min_pass_rate >= 0.0) {
      const bool all_ok = t.all.percent() + 1e-9 >= o->min_pass_rate;
      const bool unfitted_ok = o->min_unfitted_pass_rate < 0.0 || t.not_fitted.percent() + 1e-9 >= o->min_unfitted_pass_rate;
      return all_ok && unfitted_ok ? 0 : 1;
    }
    return t.all.failed == 0 ? 0 : 1;
  };
}

const CommandRegistrar validate_command{32, "validate", "run the published references of assets/validation (exit 1 when one fails)",
                           setup_validate};

}  // namespace
}  // namespace sweetspot::cli
