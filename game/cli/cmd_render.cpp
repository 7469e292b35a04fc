// `sweetspot render SCENARIO -o FILE.png`: an off-screen image of a shot (DESIGN §7).
//
// The shot comes from a ShotSource: a scenario run through delivery, impact and flight on
// its world (the club or bat drawn where the delivery put it), or, without SCENARIO,
// launch-monitor flags flown on the flat default ground (as `sweetspot flight`).
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "game/app/shot_view.hpp"
#include "game/assets/assets.hpp"
#include "game/cli/command.hpp"
#include "game/render/render_command.hpp"
#include "game/render/render_error.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/units.hpp"
#include "game/scenario/scenario.hpp"
#include "physics/world.hpp"

namespace sweetspot::cli {
namespace {

struct RenderOptions {
  std::string scenario;                 // built-in name or .toml; "" = launch flags
  std::vector<std::string> overrides;   // --set key=value
  std::string output;
  int width = 1280, height = 720;
  std::string camera = "behind";
  std::string at;  // quantity, e.g. 2.5 or 2500ms; "" = the shot's end
  // Launch-monitor flags (the shot source until scenarios are wired in).
  std::string sport = "golf";
  std::string ball_speed, launch_angle, spin;
  std::string spin_axis = "0deg", direction = "0deg";
  std::string impactor;  // "" = by sport
  std::string world;  // "" = the sport's default world
  int samples = 0;
};

/// What the renderer needs of a shot, whatever produced it.
struct ShotSource {
  ShotTrajectory trajectory;
  std::string sport;
  double ball_radius = 0.0;
  std::string world;  // world name or mesh path for the renderer; "" = the flat default ground
  std::optional<Vec3> flag;
  std::optional<ImpactorPlacement> impactor;
  std::string impactor_mesh;
};

double flag_quantity(const std::string& flag, const std::string& text, Dimension dim, double lo, double hi,
                     const char* range) {
  if (text.empty()) throw InputError(flag + " is required (e.g. --ball-speed 167mph --launch-angle 10.9deg --spin 2686rpm)");
  double v = 0.0;
  try {
    v = parse_quantity(text, dim);
  } catch (const InputError& e) {
    throw InputError(flag + ": " + e.what());
  }
  if (!(v >= lo && v <= hi)) throw InputError(flag + " " + text + " is out of range (allowed " + range + ")");
  return v;
}

// Where the club or bat is drawn when only launch numbers are known: an illustrative pose,
// not an impact solve. Golf: the face centre touches the back of the ball, the face normal
// along the launch direction (loft ~ launch angle). Baseball: the bat's sweet spot (6 in
// from the tip) behind the ball, the bat level and square to the launch direction, knob on
// the third-base side (right-handed batter).
ImpactorPlacement nominal_impactor(const std::string& mesh, const LaunchState& launch, double ball_radius) {
  const Vec3 n = launch.velocity.normalized();
  const double yaw = std::atan2(n.z(), n.x());
  ImpactorPlacement p;
  if (mesh == "bat") {
    constexpr double kLength = 0.84, kSweetFromTip = 0.1524, kBarrelRadius = 0.033;
    const Quat q = Quat(Eigen::AngleAxisd(-yaw, Vec3::UnitY())) * Quat(Eigen::AngleAxisd(-kPi / 2, Vec3::UnitY()));
    const Vec3 contact = launch.position - (ball_radius + kBarrelRadius) * Vec3(n.x(), 0, n.z()).normalized();
    p.orientation = q;
    p.position = contact - (kLength - kSweetFromTip) * (q * Vec3::UnitX());
    return p;
  }
  const double loft = std::asin(std::clamp(n.y(), -1.0, 1.0));
  p.orientation = Quat(Eigen::AngleAxisd(-yaw, Vec3::UnitY())) * Quat(Eigen::AngleAxisd(loft, Vec3::UnitZ()));
  p.position = launch.position - ball_radius * (p.orientation * Vec3::UnitX());
  return p;
}

ShotSource scenario_shot(const RenderOptions& o) {
  if (!o.ball_speed.empty() || !o.launch_angle.empty() || !o.spin.empty())
    throw InputError("render: give a SCENARIO or the launch flags (--ball-speed, --launch-angle, --spin), not both");
  const Scenario scenario = load_scenario(o.scenario, o.overrides);
  const ShotResult result = run_scenario(scenario);
  const RenderRequest req = render_request_for(scenario, result);
  ShotSource s;
  s.trajectory = result.trajectory;
  s.sport = req.sport;
  s.ball_radius = req.ball_radius;
  s.world = req.world;
  s.impactor = req.impactor;
  s.impactor_mesh = o.impactor.empty() ? req.impactor_mesh : (o.impactor == "none" ? "" : o.impactor);
  if (s.impactor_mesh.empty()) s.impactor.reset();
  return s;
}

ShotSource make_shot(const RenderOptions& o) {
  if (!o.scenario.empty()) return scenario_shot(o);
  if (!o.overrides.empty()) throw InputError("--set needs a SCENARIO (e.g. render golf/driver --set swing.speed=100mph)");
  ShotSource s;
  s.sport = o.sport;
  FlightInput in;
  in.ball = o.sport == "golf" ? golf_ball_properties() : baseball_properties();
  in.aero = &default_aero_model(o.sport);
  const double speed = flag_quantity("--ball-speed", o.ball_speed, Dimension::Speed, 1.0, 150.0, "1..150 m/s, 2..335 mph");
  const double launch = flag_quantity("--launch-angle", o.launch_angle, Dimension::Angle, -kPi / 2, kPi / 2, "-90..90 deg");
  const double spin = flag_quantity("--spin", o.spin, Dimension::AngularVelocity, 0.0, rpm_to_radps(14000.0), "0..14000 rpm");
  const double axis = flag_quantity("--spin-axis", o.spin_axis, Dimension::Angle, -kPi / 2, kPi / 2, "-90..90 deg");
  const double dir = flag_quantity("--direction", o.direction, Dimension::Angle, -kPi / 2, kPi / 2, "-90..90 deg");
  // The same world for physics and picture: the sport's default unless told otherwise.
  const std::string world_name = o.world.empty() ? default_world_name(o.sport) : o.world;
  const World* world = nullptr;
  try {
    world = shared_world(world_name);
  } catch (const InputError& e) {
    throw InputError(std::string("--world: ") + e.what());
  }
  if (world != nullptr) {
    s.flag = world->description().flag;
    // A world .toml names its mesh; the renderer draws the .obj next to it.
    s.world = world_name.ends_with(".toml")
                  ? std::filesystem::path(world_name).replace_extension(".obj").string()
                  : world_name;
  }
  // Golf: ball centre on the ground at the tee (origin). Baseball: contact 0.9 m above home plate.
  const Vec3 start = o.sport == "golf" ? Vec3(0.0, in.ball.radius, 0.0) : Vec3(0.0, 0.9, 0.0);
  in.launch = launch_from_metrics(speed, launch, dir, spin, axis, start);
  s.trajectory = simulate_shot(in, world);
  s.ball_radius = in.ball.radius;
  s.impactor_mesh = o.impactor.empty() ? (o.sport == "golf" ? "driver_head" : "bat") : o.impactor;
  if (s.impactor_mesh == "none") {
    s.impactor_mesh.clear();
  } else {
    s.impactor = nominal_impactor(s.impactor_mesh, in.launch, in.ball.radius);
  }
  return s;
}

RunFn setup_render(CLI::App& sub) {
  auto o = std::make_shared<RenderOptions>();
  sub.add_option("scenario", o->scenario, "built-in scenario name or .toml path (without it: the launch flags below)");
  sub.add_option("--set", o->overrides, "override a scenario key, e.g. swing.speed=105mph (repeatable)");
  sub.add_option("-o,--output", o->output, "PNG file to write (written atomically)")->required();
  sub.add_option("--width", o->width, "image width in pixels (16..8192)")->check(CLI::Range(16, 8192))->capture_default_str();
  sub.add_option("--height", o->height, "image height in pixels (16..8192)")->check(CLI::Range(16, 8192))->capture_default_str();
  sub.add_option("--camera", o->camera, "behind, side, top or follow")->capture_default_str();
  sub.add_option("--at", o->at, "time since launch, e.g. 2.5 or 2500ms (default: the shot's end)");
  sub.add_option("--sport", o->sport, "golf or baseball")->capture_default_str()->check(CLI::IsMember({"golf", "baseball"}));
  sub.add_option("--ball-speed", o->ball_speed, "ball speed with units, e.g. 167mph (1..150 m/s)");
  sub.add_option("--launch-angle", o->launch_angle, "vertical launch angle, e.g. 10.9deg (-90..90 deg)");
  sub.add_option("--spin", o->spin, "total spin, e.g. 2686rpm (0..14000 rpm)");
  sub.add_option("--spin-axis", o->spin_axis, "spin axis, + curves right (-90..90 deg)")->capture_default_str();
  sub.add_option("--direction", o->direction, "horizontal launch angle, + right (-90..90 deg)")->capture_default_str();
  sub.add_option("--impactor", o->impactor, "driver_head, iron_head, bat or none (default: driver_head / bat)")
      ->check(CLI::IsMember({"driver_head", "iron_head", "bat", "none"}));
  sub.add_option("--world", o->world,
                 "world: golf_hole (golf default), ballpark (baseball default), a .toml path, or none (flat fairway)");
  sub.add_option("--msaa", o->samples, "multisample count: 0 = auto (4 on a GPU, 1 on llvmpipe), 1, 2, 4, 8")
      ->capture_default_str()->check(CLI::IsMember({0, 1, 2, 4, 8}));
  return [o]() -> int {
    RenderRequest r;
    r.width = o->width;
    r.height = o->height;
    r.samples = o->samples;
    r.camera = parse_camera_kind(o->camera);
    if (!o->at.empty()) {
      try {
        r.at_seconds = parse_quantity(o->at, Dimension::Time);
      } catch (const InputError& e) {
        throw InputError(std::string("--at: ") + e.what());
      }
    }
    const ShotSource shot = make_shot(*o);
    r.sport = shot.sport;
    r.world = shot.world;
    r.flag = shot.flag;
    r.ball_radius = shot.ball_radius;
    r.impactor = shot.impactor;
    r.impactor_mesh = shot.impactor_mesh;
    try {
      render_shot_png(shot.trajectory, r, o->output);
    } catch (const RenderUnavailable& e) {
      std::cerr << "sweetspot render: " << e.what() << "\n"
                << "sweetspot render: rendering needs EGL with Mesa (libegl-mesa0, libgl1-mesa-dri) or a GPU driver\n";
      return 3;
    } catch (const RenderError& e) {
      std::cerr << "sweetspot render: " << e.what() << "\n";
      return 3;
    }
    std::cout << "sweetspot render: wrote " << o->output << " (" << r.width << "x" << r.height << ", camera "
              << to_string(r.camera) << ")\n";
    return 0;
  };
}

const CommandRegistrar reg{40, "render", "render a shot to a PNG off-screen (EGL; llvmpipe without a GPU)", setup_render};

}  // namespace
}  // namespace sweetspot::cli
