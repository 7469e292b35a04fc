// `sweetspot regress [PATH...] [--update] [--junit FILE] [--json]`: launch spin/velocity
// (and impact) regression. Exit 0 when every expectation holds, 1 on any drift, 2 on a bad
// case file (nothing written).
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/report/report.hpp"
#include "game/tuning/regression.hpp"
#include "game/tuning/regression_report.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot::cli {
namespace {

struct RegressOptions {
  std::vector<std::string> paths;
  bool update = false;
  std::string junit;
  bool json = false;
};

RunFn setup_regress(CLI::App& sub) {
  auto o = std::make_shared<RegressOptions>();
  sub.add_option("paths", o->paths, "case files or directories (default: tests/regression)");
  sub.add_flag("--update", o->update, "rewrite each case's expected values with what this build computes");
  sub.add_option("--junit", o->junit,
                 "also write a JUnit XML report to FILE (one testcase per check; a failure shows expected, "
                 "actual and tolerance), written whole or not at all");
  sub.add_flag("--json", o->json, "print the results as JSON (SI values beside the case's own units) instead of the table");
  return [o](const Assets& assets) -> int {
    // Run every case before writing anything: a bad file aborts with no file touched.
    std::vector<RegressionCaseResult> results;
    const std::vector<std::filesystem::path> paths = regression_paths(o->paths);
    if (!o->junit.empty())
      for (const auto& p : paths) refuse_output_over_input(o->junit, p, "--junit");
    for (const auto& p : paths) results.push_back(run_regression_case(assets, p));
    if (!o->junit.empty()) write_file_atomic(o->junit, regression_junit(results));
    if (o->json)
      std::cout << json_text(regression_json(results)) << "\n";
    else
      std::cout << regression_table(results);
    int failed_cases = 0, failed_rows = 0, rows = 0;
    for (const auto& r : results) {
      for (const auto& row : r.rows) failed_rows += row.pass ? 0 : 1;
      rows += static_cast<int>(r.rows.size());
      failed_cases += r.passed() ? 0 : 1;
    }
    if (o->update) {
      // Every file to rewrite must be writable before the first is touched: all updated or
      // none (a read-only case among them is refused up front).
      for (const auto& r : results) {
        if (r.updated_text == r.original_text) continue;
        try {
          check_output_path(r.path, "--update");
        } catch (const InputError& e) {
          throw InputError(std::string(e.what()) + "; no case file was changed");
        }
      }
      int written = 0;
      std::string done;  // the files already rewritten, named if a later one fails
      for (const auto& r : results) {
        if (r.updated_text == r.original_text) continue;
        try {
          write_file_atomic(r.path, r.updated_text, OverInput::Allow);  // --update rewrites its cases
        } catch (const InputError& e) {
          throw InputError(std::string(e.what()) + (written == 0 ? "; no case file was changed"
                                                                 : "; already updated: " + done + " (the others are unchanged)"));
        }
        done += (written++ ? ", " : "") + r.path.string();
      }
      (o->json ? std::cerr : std::cout) << "updated " << written << " of " << results.size() << " case files\n";
      return 0;
    }
    if (!o->json) std::cout << results.size() << " cases (" << failed_cases << " failing), " << rows << " checks, " << failed_rows
              << " failed\n";
    return failed_rows == 0 ? 0 : 1;
  };
}

const CommandRegistrar regress_command{31, "regress", "launch spin/velocity regression over tests/regression (exit 1 on drift)",
                           setup_regress};

}  // namespace
}  // namespace sweetspot::cli
