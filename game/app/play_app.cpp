#include "game/app/play_app.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <random>
#include <sstream>
#include <stdexcept>

#include "game/app/game_window.hpp"
#include "game/app/main_loop.hpp"
#include "game/app/mode_registry.hpp"
#include "game/content/course_file.hpp"
#include "game/modes/golf/golfer.hpp"
#include "game/render/shot_view.hpp"
#include "game/render/image.hpp"
#include "game/render/render_error.hpp"
#include "game/render/renderer.hpp"
#include "game/report/report.hpp"
#include "game/report/round_save.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
namespace {

struct Shot {
  Scenario scenario;
  ShotResult result;
};

// The scenario `play` starts from, with each --set key=value, and its shot.
Shot compute(const Assets& assets, const PlayOptions& o) {
  Shot s{load_scenario(assets, o.scenario, o.overrides), {}};
  s.result = run_scenario(s.scenario);
  return s;
}

}  // namespace

int run_play_headless(const Assets& assets, const PlayOptions& o, std::ostream& out) {
  const Shot shot = compute(assets, o);
  // The image first: a refused output (a bad path, the scenario itself) leaves stdout empty.
  std::string image = "image: none (add --screenshot FILE.png to render the shot)\n";
  if (!o.screenshot.empty()) {
    const std::string& png = o.screenshot;
    try {
      RenderRequest req = render_request_for(assets, shot.scenario.resolved, shot.result);
      req.width = o.width;
      req.height = o.height;
      render_shot_png(shot.result.trajectory, req, png);
      image = "image: " + png + " (" + std::to_string(req.width) + "x" + std::to_string(req.height) + ", off-screen EGL)\n";
    } catch (const RenderUnavailable& e) {
      image = std::string("image: skipped, no off-screen OpenGL here (") + e.what() + ")\n";
    }
  }
  out << launch_table(shot.result, *shot.scenario.resolved.sport, UnitSystem::Imperial) << image;
  return 0;
}

namespace {

// A session's own draw of winds, swings and pitches: two 32-bit words from the system's
// entropy source, never 0 (0 asks for a draw).
std::uint64_t session_seed() {
  std::random_device rd;
  const std::uint64_t seed = (static_cast<std::uint64_t>(rd()) << 32) ^ static_cast<std::uint64_t>(rd());
  return seed == 0 ? 1 : seed;
}

LoopStats run_window(const Assets& assets, const PlayOptions& given, std::ostream& out) {
  // Each session draws its own winds, bot swings and pitches (a fixed one would deal the
  // same round and the same pitches every time); the seed is printed, and --seed plays that
  // session again.
  PlayOptions o = given;
  // A resumed round goes on with its own seed (its winds and bots): the session takes it.
  if (o.seed == 0 && !o.resume.empty()) o.seed = read_round_save(o.resume).options.seed;
  if (o.seed == 0) o.seed = session_seed();
  out << "seed " << o.seed << " (play --seed " << o.seed << " draws this session again)\n";
  // Bad input fails here, before a window opens.
  const ModeRegistry modes = play_modes(assets, o, out);
  std::size_t first = modes.size();
  for (std::size_t i = 0; i < modes.size(); ++i)
    if (modes[i].name == o.mode) first = i;
  if (first == modes.size()) check_play_mode(assets, o);  // names the modes there are
  if (o.mode == "range") {
    golfer_skill(o.skill);
  } else if (o.mode == "golf") {
    Course c = load_course(assets, o.course);
    set_up(c, o.course_setup, "--tees", "--pins");  // a tee set the course lacks is named before the window opens
    golfer_skill(o.skill);
  } else if (o.mode == "baseball") {
    assets.world("ballpark");
  } else {
    (void)compute(assets, o);
  }
  WindowOptions wo;
  wo.width = o.width;
  wo.height = o.height;
  wo.vsync = o.frames == 0;
  check_quality(o.quality);
  GameWindow win(wo);
  RendererOptions ro;
  ro.shadows = o.quality == "high" ? 1 : o.quality == "low" ? 0 : -1;
  Renderer renderer(win.framebuffer_width(), win.framebuffer_height(), ro);
  LoopOptions lo;
  lo.dynamic_resolution = o.quality != "high";
  lo.frames = o.frames;
  lo.screenshot = o.screenshot;
  lo.shots_dir = o.shots_dir;
  lo.mute = o.mute;
  return run_main_loop(win, renderer, modes, first, lo, out);
}

}  // namespace

void check_quality(const std::string& quality) {
  if (quality != "auto" && quality != "low" && quality != "high") throw InputError("--quality " + quality + ": allowed auto, low, high");
}

int run_play_window(const Assets& assets, const PlayOptions& o, std::ostream& out) {
  const LoopStats stats = run_window(assets, o, out);
  if (stats.frames > 0) out << "play: " << stats.frames << " frames, " << stats.ms_total / stats.frames << " ms per frame\n";
  return 0;
}

double measure_window_frame_ms(const Assets& assets, const std::string& mode, int width, int height, int frames) {
  constexpr int kWarmUp = 10;
  PlayOptions o;
  o.mode = mode;
  o.mute = true;
  o.width = width;
  o.height = height;
  o.frames = kWarmUp + std::max(frames, 1);
  std::ostringstream quiet;
  LoopStats stats = run_window(assets, o, quiet);
  std::vector<double> ms(stats.frame_ms.begin() + std::min<std::ptrdiff_t>(kWarmUp, static_cast<std::ptrdiff_t>(stats.frame_ms.size())),
                         stats.frame_ms.end());
  if (ms.empty()) throw std::runtime_error("the window ran no frames");
  std::nth_element(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace sweetspot
