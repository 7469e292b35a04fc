// `sweetspot shot SCENARIO`: one shot, printed as a launch-monitor table (default), the
// DESIGN §6 JSON, a GSPro OpenConnect v1 message or a CSV row.
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/report/report.hpp"
#include "game/content/scenario.hpp"

namespace sweetspot::cli {
namespace {

struct ShotOptions {
  std::string scenario;
  std::string e, mu;
  std::vector<std::string> sets;
  bool json = false, gspro = false, csv = false;
  std::string units = "imperial";
};

RunFn setup_shot(CLI::App& sub) {
  auto o = std::make_shared<ShotOptions>();
  sub.add_option("scenario", o->scenario, "built-in name (see `sweetspot list`) or a .toml file")->required();
  sub.add_option("--e", o->e, "normal restitution override, 0..1 (= --set impact.e=X)");
  sub.add_option("--mu", o->mu, "friction coefficient override, >= 0 (= --set impact.mu=X)");
  sub.add_option("--set", o->sets, "override any scenario key: key=value, e.g. swing.speed=105mph")
      ->type_name("KEY=VALUE");
  auto* json = sub.add_flag("--json", o->json, "print the DESIGN §6 JSON object");
  auto* gspro = sub.add_flag("--gspro", o->gspro, "print a GSPro OpenConnect v1 shot message");
  auto* csv = sub.add_flag("--csv", o->csv, "print a CSV header and row (Statcast names for baseball)");
  json->excludes(gspro)->excludes(csv);
  gspro->excludes(csv);
  sub.add_option("--units", o->units, "display units of the table and CSV: imperial or metric")
      ->capture_default_str();
  return [o](const Assets& assets) -> int {
    const UnitSystem units = parse_unit_system(o->units);
    // --e / --mu are --set shorthands; their messages name the flag itself.
    ScenarioDoc doc = read_toml_doc(resolve_scenario(assets, o->scenario));
    for (const auto& s : o->sets) apply_set(doc, s);
    if (!o->e.empty()) apply_set(doc, "impact.e=" + o->e, "--e " + o->e);
    if (!o->mu.empty()) apply_set(doc, "impact.mu=" + o->mu, "--mu " + o->mu);
    const Scenario scenario = scenario_from_doc(assets, doc, o->scenario);
    const ShotResult r = run_scenario(scenario, RunOptions{true, false});
    const SportProfile& sport = *scenario.resolved.sport;
    if (o->json) {
      std::cout << shot_json(r).dump(2) << "\n";
    } else if (o->gspro) {
      std::cout << gspro_json(r).dump(2) << "\n";
    } else if (o->csv) {
      std::cout << csv_header(sport, units) << csv_row(r, sport, units);
    } else {
      std::cout << launch_table(r, sport, units);
    }
    return 0;
  };
}

const CommandRegistrar reg{20, "shot", "simulate one scenario: launch-monitor table, --json, --gspro or --csv", setup_shot};

}  // namespace
}  // namespace sweetspot::cli
