// `sweetspot flight`: replay launch-monitor numbers (ball speed, launch angle, spin, axis,
// direction) through the flight, bounce and roll of a full shot (DESIGN §6). The flags are
// a launch-only scenario (game/cli/launch_flags.hpp) run like any other.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "game/cli/command.hpp"
#include "game/cli/launch_flags.hpp"
#include "game/report/report.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot::cli {
namespace {

struct FlightOptions {
  LaunchFlags launch;
  bool json = false;
  std::string units = "imperial";
};

RunFn setup_flight(CLI::App& sub) {
  auto o = std::make_shared<FlightOptions>();
  add_launch_flags(sub, o->launch, true);
  sub.add_flag("--json", o->json, "print the DESIGN §6 JSON object");
  sub.add_option("--units", o->units, "display units of the table: imperial or metric")->capture_default_str();
  return [o](const Assets& assets) -> int {
    const UnitSystem units = parse_unit_system(o->units);
    const Scenario s = launch_scenario(assets, o->launch, "flight");
    if (s.resolved.world != nullptr) {
      for (const std::string& note : s.resolved.world->description().notes) std::cerr << "sweetspot: note: " << note << "\n";
    }
    const ShotResult r = run_scenario(s, RunOptions{true, false});
    if (o->json) {
      nlohmann::json j = shot_json(r);
      j["aero"] = s.resolved.aero->name;
      j["air_density_kgm3"] = air_density(s.spec.environment);
      std::cout << json_text(j) << "\n";
    } else {
      std::cout << launch_table(r, *s.resolved.sport, units);
    }
    return 0;
  };
}

const CommandRegistrar flight_command{30, "flight", "fly, bounce and roll a ball from launch-monitor numbers", setup_flight};

}  // namespace
}  // namespace sweetspot::cli
