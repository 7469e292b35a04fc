#include "game/cli/launch_flags.hpp"

#include "physics/error.hpp"

namespace sweetspot::cli {

void add_launch_flags(CLI::App& sub, LaunchFlags& f, bool required) {
  sub.add_option("--sport", f.sport, "a sport of assets/sports.toml: golf or baseball")->capture_default_str();
  auto* speed = sub.add_option("--ball-speed", f.ball_speed, "ball speed with its unit, e.g. 167mph");
  auto* angle = sub.add_option("--launch-angle", f.launch_angle, "vertical launch angle, e.g. 10.9deg");
  auto* spin = sub.add_option("--spin", f.spin, "total spin, e.g. 2686rpm");
  if (required) {
    speed->required();
    angle->required();
    spin->required();
  }
  sub.add_option("--spin-axis", f.spin_axis, "spin axis, + curves right, 180deg = topspin (default 0deg)");
  sub.add_option("--direction", f.direction, "horizontal launch angle, + right (default 0deg)");
  sub.add_option("--aero", f.aero, "aero model of assets/aero_models.toml (default: the sport's)");
  sub.add_option("--world", f.world, "world: golf_hole, ballpark, a .toml path, or none (default: the sport's)");
  sub.add_option("--set", f.sets, "ball.KEY, environment.KEY, aero.KEY or world.KEY=VALUE, e.g. environment.temperature=90F")
      ->type_name("KEY=VALUE");
}

bool has_launch_numbers(const LaunchFlags& f) {
  return !f.ball_speed.empty() || !f.launch_angle.empty() || !f.spin.empty();
}

Scenario launch_scenario(const Assets& assets, const LaunchFlags& f, const std::string& name) {
  ScenarioDoc doc;
  doc.source = name;
  const auto flag = [&](const char* key, const std::string& value, const char* name_of_flag) {
    if (value.empty()) return;
    apply_set(doc, std::string(key) + "=" + value, std::string(name_of_flag) + " " + value);
  };
  flag("sport", f.sport, "--sport");
  if (f.ball_speed.empty() || f.launch_angle.empty() || f.spin.empty())
    throw InputError(std::string(f.ball_speed.empty() ? "--ball-speed" : f.launch_angle.empty() ? "--launch-angle" : "--spin") +
                     " is required: a launch is --ball-speed, --launch-angle and --spin together (e.g. --ball-speed "
                     "167mph --launch-angle 10.9deg --spin 2686rpm)");
  flag("launch.ball_speed", f.ball_speed, "--ball-speed");
  flag("launch.vertical_angle", f.launch_angle, "--launch-angle");
  flag("launch.spin", f.spin, "--spin");
  flag("launch.spin_axis", f.spin_axis, "--spin-axis");
  flag("launch.horizontal_angle", f.direction, "--direction");
  flag("aero.model", f.aero, "--aero");
  flag("world.name", f.world, "--world");
  for (const std::string& kv : f.sets) {
    const std::string key = kv.substr(0, kv.find('='));
    const bool allowed = key.rfind("ball.", 0) == 0 || key.rfind("environment.", 0) == 0 ||
                         key.rfind("aero.", 0) == 0 || key.rfind("world.", 0) == 0;
    if (!allowed) {
      throw InputError("--set " + kv + ": launch numbers take ball.*, environment.*, aero.* and world.* keys only "
                       "(the launch comes from the flags; there is no club or bat)");
    }
    apply_set(doc, kv);
  }
  return scenario_from_doc(assets, doc, name);
}

}  // namespace sweetspot::cli
