// `sweetspot bench [--json] [--quick]`: throughput figures (DESIGN §8) as one JSON object
// or a table. Each figure is one row of `measurements`; further benchmarks add rows.
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/bench/impact_bench.hpp"
#include "game/cli/command.hpp"

namespace sweetspot::cli {
namespace {

struct BenchOptions {
  bool json = false;
  bool quick = false;
};

struct Measurement {
  std::string key;    ///< JSON key, SI-style suffix ("impact_solves_per_s")
  double value;
  std::string label;  ///< table text
};

RunFn setup_bench(CLI::App& sub) {
  auto opts = std::make_shared<BenchOptions>();
  sub.add_flag("--json", opts->json, "print one JSON object");
  sub.add_flag("--quick", opts->quick, "short timing runs (tests, smoke checks)");
  return [opts]() -> int {
    const double seconds = opts->quick ? 0.05 : 1.0;
    std::vector<Measurement> rows;
    rows.push_back({"impact_solves_per_s", measure_impact_solves_per_s(seconds), "impact solves/s (one core)"});

    if (opts->json) {
      nlohmann::json j = nlohmann::json::object();
      for (const auto& r : rows) j[r.key] = r.value;
      j["quick"] = opts->quick;
      std::cout << j.dump(2) << "\n";
    } else {
      for (const auto& r : rows) {
        std::cout << std::left << std::setw(32) << r.label << std::right << std::setprecision(4) << r.value << "\n";
      }
    }
    return 0;
  };
}

const CommandRegistrar reg{80, "bench", "measure throughput (impact solves/s, ...)", setup_bench};

}  // namespace
}  // namespace sweetspot::cli
