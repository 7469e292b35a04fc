// `sweetspot regress [PATH...] [--update]`: launch spin/velocity (and impact) regression.
// Exit 0 when every expectation holds, 1 on any drift, 2 on a bad case file.
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/tuning/regression.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot::cli {
namespace {

struct RegressOptions {
  std::vector<std::string> paths;
  bool update = false;
};

RunFn setup_regress(CLI::App& sub) {
  auto o = std::make_shared<RegressOptions>();
  sub.add_option("paths", o->paths, "case files or directories (default: tests/regression)");
  sub.add_flag("--update", o->update, "rewrite each case's expected values with what this build computes");
  return [o](const Assets& assets) -> int {
    // Run every case before writing anything: a bad file aborts with no file touched.
    std::vector<RegressionCaseResult> results;
    for (const auto& p : regression_paths(o->paths)) results.push_back(run_regression_case(assets, p));
    std::cout << regression_table(results);
    int failed_cases = 0, failed_rows = 0, rows = 0;
    for (const auto& r : results) {
      for (const auto& row : r.rows) failed_rows += row.pass ? 0 : 1;
      rows += static_cast<int>(r.rows.size());
      failed_cases += r.passed() ? 0 : 1;
    }
    if (o->update) {
      int written = 0;
      std::string done;  // the files already rewritten, named if a later one fails
      for (const auto& r : results) {
        if (r.updated_text == r.original_text) continue;
        try {
          write_file_atomic(r.path, r.updated_text);
        } catch (const InputError& e) {
          throw InputError(std::string(e.what()) + (written == 0 ? "; no case file was changed"
                                                                 : "; already updated: " + done + " (the others are unchanged)"));
        }
        done += (written++ ? ", " : "") + r.path.string();
      }
      std::cout << "updated " << written << " of " << results.size() << " case files\n";
      return 0;
    }
    std::cout << results.size() << " cases (" << failed_cases << " failing), " << rows << " checks, " << failed_rows
              << " failed\n";
    return failed_rows == 0 ? 0 : 1;
  };
}

const CommandRegistrar reg{30, "regress", "launch spin/velocity regression over tests/regression (exit 1 on drift)",
                           setup_regress};

}  // namespace
}  // namespace sweetspot::cli
