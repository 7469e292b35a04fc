// `sweetspot connect`: a GSPro Open Connect v1 server (DESIGN §10). A launch monitor's
// connector (Garmin R10, MLM2Pro, Square, PiTrac, ...) points at it as it would at GSPro;
// each shot flies on the course round (`--course`) or the range (`--world`), headless as one
// JSON line per shot on stdout, or in the window.
#include <iostream>
#include <memory>

#include "game/app/connect_app.hpp"
#include "game/app/display.hpp"
#include "game/cli/command.hpp"
#include "game/content/assets.hpp"
#include "game/content/course_file.hpp"
#include "game/content/world_asset.hpp"
#include "game/render/image.hpp"
#include "game/content/quantity_text.hpp"
#include "game/net/connect_server.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot::cli {
namespace {

struct ConnectCliOptions {
  ConnectOptions server;
  std::string idle = "30min";
  bool headless = false;
  std::string screenshot;
  int frames = 0;
};

RunFn setup_connect(CLI::App& sub) {
  auto o = std::make_shared<ConnectCliOptions>();
  sub.add_option("--port", o->server.port, "TCP port, 0..65535 (GSPro's is 921; below 1024 needs root; 0 = any free port)")
      ->capture_default_str();
  sub.add_option("--bind", o->server.bind, "address to listen on (0.0.0.0 for a launch monitor on another machine)")
      ->capture_default_str();
  sub.add_flag("--headless", o->headless, "no window: one JSON line per shot on stdout");
  auto* course = sub.add_option("--course", o->server.table.course, "play this course's round (a name of assets/courses, a .toml, or a directory from course import)");
  auto* world = sub.add_option("--world", o->server.table.world, "a range on this world: every shot from its tee (default: the golf hole)");
  course->excludes(world);
  sub.add_option("--idle-timeout", o->idle, "drop a client silent this long, 1s..24h (some connectors never send a heartbeat)")
      ->capture_default_str();
  sub.add_option("--record", o->server.record, "append each shot message received to FILE (JSON lines; replay it with `sweetspot send`)");
  sub.add_option("--max-shots", o->server.max_shots, "stop after N shots (replays, tests; 0 = never)")->check(int_range<int>(0, 100000000));
  sub.add_option("--frames", o->frames, "window: run N frames then exit (automation)")->check(int_range<int>(1, 1000000));
  sub.add_option("--screenshot", o->screenshot, "window: save the last frame to FILE.png");
  return [o](const Assets& assets) -> int {
    // The course or range is checked before the port opens, so a typo is named by its flag
    // instead of answered as an error to the launch monitor's first shot.
    if (!o->server.table.world.empty()) {
      try {
        const WorldAsset* w = assets.world(o->server.table.world);
        if (w != nullptr && !w->sport.empty() && w->sport != "golf")  // nullptr: "none", the flat range
          throw InputError("'" + o->server.table.world + "' is a " + w->sport + " world; a launch monitor's range is a golf world");
      } catch (const InputError& e) {
        throw InputError(std::string("--world: ") + e.what());
      }
    }
    if (!o->server.table.course.empty()) {
      try {
        load_course(assets, o->server.table.course);
      } catch (const InputError& e) {
        throw InputError(std::string("--course: ") + e.what());
      }
    }
    const Range idle_range{ConnectOptions::kMinIdle, ConnectOptions::kMaxIdle};
    o->server.idle_timeout = flag_quantity("--idle-timeout", o->idle, Dimension::Time, &idle_range);
    std::string why;
    const bool window_only = o->frames > 0 || !o->screenshot.empty();
    const char* window_flag = o->frames > 0 ? "--frames" : "--screenshot";
    if (o->headless && window_only)
      throw InputError(std::string(window_flag) + ": a window option; --headless serves until --max-shots or Ctrl-C");
    if (!o->headless && !display_available(&why)) {
      // Headless, --frames would be ignored and the server would run forever: refuse.
      if (window_only) throw InputError(std::string(window_flag) + " needs a window, and " + why);
      std::cerr << "sweetspot connect: " << why << "; running headless.\n";
      o->headless = true;
    }
    if (!o->screenshot.empty()) check_png_output(o->screenshot, "--screenshot");
    if (o->headless) {
      ConnectServer server(assets, o->server, std::cout, std::cerr);
      return server.run();
    }
    ConnectWindowOptions w;
    w.server = o->server;
    w.frames = o->frames;
    w.screenshot = o->screenshot;
    return run_connect_window(assets, w, std::cout, std::cerr);
  };
}

const CommandRegistrar connect_command{37, "connect", "serve a launch monitor (GSPro Open Connect v1): its shots play the course or the range",
                           setup_connect};

}  // namespace
}  // namespace sweetspot::cli
