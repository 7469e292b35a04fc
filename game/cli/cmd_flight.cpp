// `sweetspot flight`: replay launch-monitor numbers (ball speed, launch angle, spin, axis,
// direction) through the flight, bounce and roll of a full shot (DESIGN §6).
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/assets/assets.hpp"
#include "game/cli/command.hpp"
#include "game/environment_keys.hpp"
#include "game/report/flight_json.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/units.hpp"
#include "game/scenario/scenario.hpp"
#include "physics/world.hpp"

namespace sweetspot::cli {
namespace {

struct FlightOptions {
  std::string sport;
  std::string ball_speed, launch_angle, spin;
  std::string spin_axis = "0deg";
  std::string direction = "0deg";
  std::string aero;
  std::string world;  // empty: the sport's default world
  std::vector<std::string> sets;
  bool json = false;
};

/// Parses a flag's quantity and checks its range, naming the flag on failure.
double flag_quantity(const std::string& flag, const std::string& text, Dimension dim, double lo, double hi,
                     const char* range) {
  double v = 0.0;
  try {
    v = parse_quantity(text, dim);
  } catch (const InputError& e) {
    throw InputError(flag + ": " + e.what());
  }
  if (!(v >= lo && v <= hi)) throw InputError(flag + " " + text + " is out of range (allowed " + range + ")");
  return v;
}

void print_table(const FlightInput& in, const std::string& sport, const std::string& world, const ShotTrajectory& tr) {
  const bool golf = sport == "golf";
  const LaunchMetrics m = measure_launch(in.launch);
  const FlightSummary& s = tr.summary;
  // Display units at the edge: golf in yards, baseball in feet; speeds in mph.
  const auto dist = [&](double metres) { return golf ? m_to_yd(metres) : m_to_ft(metres); };
  const char* du = golf ? "yd" : "ft";
  std::printf("sweetspot flight: %s, aero %s, world %s, air %.4f kg/m^3\n", sport.c_str(), in.aero->name.c_str(),
              world.c_str(), air_density(in.environment));
  std::printf("  launch   ball speed %7.1f mph   launch %5.1f deg   direction %5.1f deg\n",
              mps_to_mph(m.ball_speed), rad_to_deg(m.vertical_angle), rad_to_deg(m.horizontal_angle));
  std::printf("           spin %7.0f rpm   backspin %6.0f rpm   sidespin %6.0f rpm   axis %5.1f deg\n",
              radps_to_rpm(m.spin.total), radps_to_rpm(m.spin.backspin) + 0.0,  // + 0.0: print -0 as 0
              radps_to_rpm(m.spin.sidespin_right) + 0.0, rad_to_deg(m.spin.axis_rad) + 0.0);
  std::printf("  flight   carry %7.1f %s   total %7.1f %s   apex %5.1f %s   lateral %+6.1f %s\n", dist(s.carry_m), du,
              dist(s.total_m), du, dist(s.apex_m), du, dist(s.lateral_m), du);
  std::printf("           landing angle %4.1f deg   hang time %4.2f s   bounces %d   end %s\n", s.landing_angle_deg,
              s.hang_time_s, s.bounces, to_string(s.end));
  std::printf("           rest at (%.1f, %.1f, %.1f) m after %.2f s\n", s.rest_position.x(), s.rest_position.y(),
              s.rest_position.z(), s.total_time_s);
}

RunFn setup_flight(CLI::App& sub) {
  auto o = std::make_shared<FlightOptions>();
  sub.add_option("--sport", o->sport, "golf or baseball")->required()->check(CLI::IsMember({"golf", "baseball"}));
  sub.add_option("--ball-speed", o->ball_speed, "ball speed with units, e.g. 167mph (1..150 m/s)")->required();
  sub.add_option("--launch-angle", o->launch_angle, "vertical launch angle, e.g. 10.9deg (-90..90 deg)")->required();
  sub.add_option("--spin", o->spin, "total spin, e.g. 2686rpm (0..14000 rpm)")->required();
  sub.add_option("--spin-axis", o->spin_axis, "spin axis, + curves right, e.g. -3deg (-90..90 deg)")->capture_default_str();
  sub.add_option("--direction", o->direction, "horizontal launch angle, + right (-90..90 deg)")->capture_default_str();
  sub.add_option("--aero", o->aero, "aero model: ferguson2022 (golf default), smits_smith1994, nathan (baseball default)");
  sub.add_option("--world", o->world,
                 "world: golf_hole (golf default), ballpark (baseball default), a .toml path, or none (flat fairway)");
  sub.add_option("--set", o->sets, "environment.KEY=VALUE, e.g. environment.temperature=90F");
  sub.add_flag("--json", o->json, "print the DESIGN §6 JSON object");
  return [o]() -> int {
    FlightInput in;
    in.ball = o->sport == "golf" ? golf_ball_properties() : baseball_properties();
    in.aero = o->aero.empty() ? &default_aero_model(o->sport) : &aero_model(o->aero);
    const double speed = flag_quantity("--ball-speed", o->ball_speed, Dimension::Speed, 1.0, 150.0, "1..150 m/s, 2..335 mph");
    const double launch = flag_quantity("--launch-angle", o->launch_angle, Dimension::Angle, -kPi / 2, kPi / 2, "-90..90 deg");
    const double spin = flag_quantity("--spin", o->spin, Dimension::AngularVelocity, 0.0, rpm_to_radps(14000.0), "0..14000 rpm");
    const double axis = flag_quantity("--spin-axis", o->spin_axis, Dimension::Angle, -kPi / 2, kPi / 2, "-90..90 deg");
    const double dir = flag_quantity("--direction", o->direction, Dimension::Angle, -kPi / 2, kPi / 2, "-90..90 deg");
    for (const std::string& kv : o->sets) {
      const auto eq = kv.find('=');
      if (eq == std::string::npos) throw InputError("--set '" + kv + "': expected environment.KEY=VALUE");
      const std::string key = kv.substr(0, eq);
      if (key.rfind("environment.", 0) != 0)
        throw InputError("--set '" + kv + "': flight accepts only environment.KEY (allowed: environment.{" +
                         environment_key_names() + "})");
      set_environment_key(in.environment, key, kv.substr(eq + 1));
    }
    check_environment(in.environment);
    // The same world and ground as a full shot: the sport's default unless told otherwise.
    const std::string world_name = o->world.empty() ? default_world_name(o->sport) : o->world;
    const World* world = nullptr;
    try {
      world = shared_world(world_name);
    } catch (const InputError& e) {
      throw InputError(std::string("--world: ") + e.what());
    }
    if (world != nullptr) {
      for (const std::string& note : world->description().notes) std::cerr << "sweetspot: note: " << note << "\n";
    }
    // Golf: ball centre on the ground at the tee (origin). Baseball: contact 0.9 m above home plate.
    const Vec3 start = o->sport == "golf" ? Vec3(0.0, in.ball.radius, 0.0) : Vec3(0.0, 0.9, 0.0);
    in.launch = launch_from_metrics(speed, launch, dir, spin, axis, start);
    const ShotTrajectory tr = simulate_shot(in, world);
    if (o->json) {
      nlohmann::json j;
      j["scenario"] = "flight";
      j["sport"] = o->sport;
      j["aero"] = in.aero->name;
      j["world"] = world_name;
      j["air_density_kgm3"] = air_density(in.environment);
      j["launch"] = launch_json(measure_launch(in.launch));
      j["flight"] = flight_json(tr.summary);
      std::cout << j.dump(2) << "\n";
    } else {
      print_table(in, o->sport, world_name, tr);
    }
    return 0;
  };
}

const CommandRegistrar reg{30, "flight", "fly, bounce and roll a ball from launch-monitor numbers", setup_flight};

}  // namespace
}  // namespace sweetspot::cli
