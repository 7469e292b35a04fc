#include "game/app/play_app.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "game/app/game_window.hpp"
#include "game/app/bat_app.hpp"
#include "game/app/golf_app.hpp"
#include "game/content/course_file.hpp"
#include "game/modes/golf/golfer.hpp"
#include "game/render/shot_view.hpp"
#include "game/render/gl.hpp"
#include "game/render/image.hpp"
#include "game/render/render_error.hpp"
#include "game/render/renderer.hpp"
#include "game/report/report.hpp"
#include "game/ui/panels.hpp"
#include "game/tuning/grip.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
namespace {

// Mouse orbit on top of the chosen camera: yaw about the vertical through the target,
// pitch toward the zenith, zoom along the view line. Reset when the camera changes.
struct Orbit {
  double yaw = 0.0, pitch = 0.0, zoom = 1.0;
  void reset() { *this = Orbit{}; }
  Camera apply(Camera c) const {
    Vec3 off = c.eye - c.target;
    off = Eigen::AngleAxisd(yaw, Vec3::UnitY()) * off;
    const Vec3 side = off.cross(Vec3::UnitY());
    if (side.norm() > 1e-9) {
      const Vec3 pitched = Eigen::AngleAxisd(pitch, side.normalized()) * off;
      // Stop short of the zenith and the ground plane so the view never flips.
      const double elev = std::asin(std::clamp(pitched.normalized().y(), -1.0, 1.0));
      if (elev < 1.45 && elev > -0.05) off = pitched;
    }
    c.eye = c.target + off * zoom;
    return c;
  }
};

struct Shot {
  Scenario scenario;
  ShotResult result;
};

Shot compute(const Assets& assets, const UiState& st) {
  Shot s{load_ui_scenario(assets, st), {}};
  s.result = run_scenario(s.scenario);
  // The Tuning panel says whether moving µ can change this launch (~1 ms of launches).
  if (s.result.impact.present) s.result.impact.mu_grip = mu_grip(s.scenario.resolved);
  return s;
}

/// The UI state `play` starts from: the scenario and each --set key=value applied to it.
UiState ui_state_from(const PlayOptions& o) {
  UiState st;
  st.scenario = o.scenario;
  for (const std::string& a : o.overrides) {
    const auto eq = a.find('=');
    if (eq == std::string::npos) throw InputError("--set " + a + ": expected key=value");
    st.set(a.substr(0, eq), a.substr(eq + 1));
  }
  return st;
}

}  // namespace

int run_play_headless(const Assets& assets, const PlayOptions& o, std::ostream& out) {
  UiState st = ui_state_from(o);
  const Shot shot = compute(assets, st);
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

// The window behind the panels: the ImGui dark grey, so the columns read as one surface.
void clear_window(int w, int h) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, w, h);
  glClearColor(0.10f, 0.11f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

WindowNext run_lab_loop(const Assets& assets, GameWindow& win, Renderer& renderer, const PlayOptions& o,
                        FrameStats& stats, std::ostream& out) {
  UiState st = ui_state_from(o);
  Shot shot = compute(assets, st);
  UiState good = st;
  auto scene = std::make_unique<ShotScene>(scene_input_for(assets, shot.scenario.resolved, shot.result));
  scene->set_shot(shot.result.trajectory, impactor_placement(shot.result));

  ReplayState replay;
  replay.pre_roll = scene->pre_roll();
  replay.restart();
  CameraKind camera = CameraKind::Behind;
  Orbit orbit;
  // A camera change glides from the last camera drawn over kCameraGlide s, eased.
  constexpr double kCameraGlide = 0.6;
  std::optional<Camera> last_camera, glide_from;
  double since_switch = kCameraGlide;
  std::string status, save_path = "my-shot.toml";
  bool panels_hidden = false;
  auto last = std::chrono::steady_clock::now();

  while (!win.should_close()) {
    const auto t0 = std::chrono::steady_clock::now();
    const double dt = std::chrono::duration<double>(t0 - last).count();
    last = t0;
    const FrameInput in = win.begin_frame();
    for (const int key : in.keys) {
      if (key == GLFW_KEY_TAB) return WindowNext::Golf;
      if (key == GLFW_KEY_H) panels_hidden = !panels_hidden;
    }
    // A camera key always resets that camera, the current one too (undoes a mouse orbit).
    if (in.camera >= 0) {
      camera = static_cast<CameraKind>(in.camera);
      orbit.reset();
      glide_from = last_camera;
      since_switch = 0.0;
    }
    if (in.replay || in.hit_again) replay.restart();
    orbit.yaw -= in.orbit_dx * 0.005;
    orbit.pitch += in.orbit_dy * 0.005;
    if (in.zoom != 0.0) orbit.zoom = std::clamp(orbit.zoom * std::pow(0.9, in.zoom), 0.1, 5.0);

    const CameraKind before = camera;
    const int w = win.framebuffer_width(), h = win.framebuffer_height();
    const PanelLayout layout = lay_out_panels(static_cast<float>(w), static_cast<float>(h), panels_hidden);
    PanelContext ctx{assets, st, shot.scenario, shot.result, replay, camera, status, save_path};
    const bool changed = draw_panels(ctx, layout) || in.hit_again;
    if (camera != before) {
      orbit.reset();
      glide_from = last_camera;
      since_switch = 0.0;
    }
    since_switch += dt;
    if (changed) {
      // Recompute in the same frame, so the trail drawn below is the new shot's.
      try {
        Shot next = compute(assets, st);
        const bool new_scene = next.scenario.resolved.world != shot.scenario.resolved.world ||
                               next.scenario.resolved.sport != shot.scenario.resolved.sport ||
                               next.result.impactor_mesh != shot.result.impactor_mesh;
        shot = std::move(next);
        good = st;
        if (new_scene) scene = std::make_unique<ShotScene>(scene_input_for(assets, shot.scenario.resolved, shot.result));
        scene->set_shot(shot.result.trajectory, impactor_placement(shot.result));
        replay.pre_roll = scene->pre_roll();
        replay.restart();
        status.clear();
      } catch (const InputError& e) {
        status = e.what();
        st = good;  // keep showing the last valid shot
      }
    }
    replay.advance(dt, duration(shot.result.trajectory));

    // The 3D view fills the layout's view rectangle only: nothing of the shot is under a
    // panel, and a software rasteriser shades no pixel a panel covers.
    const int vw = static_cast<int>(layout.view.w), vh = static_cast<int>(layout.view.h);
    if (w > 0 && h > 0 && vw >= 16 && vh >= 16) {
      if (vw != renderer.width() || vh != renderer.height()) renderer.resize(vw, vh);
      Camera cam = scene->keep_above_ground(orbit.apply(scene->camera(camera, replay.time, vw, vh)));
      if (glide_from && since_switch < kCameraGlide) {
        cam = scene->keep_above_ground(blend_cameras(*glide_from, cam, ease_in_out(since_switch / kCameraGlide)));
      }
      last_camera = cam;
      renderer.draw(scene->build(cam, replay.time, vw, vh), cam);
      clear_window(w, h);
      renderer.blit_to(0, static_cast<int>(layout.view.x), h - static_cast<int>(layout.view.y) - vh, vw, vh);
    }
    win.render_ui();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (end_frame(win, o, stats, ms, out)) return WindowNext::Quit;
  }
  return WindowNext::Quit;
}

}  // namespace

namespace {

FrameStats run_window(const Assets& assets, const PlayOptions& o, std::ostream& out) {
  // Bad input fails here, before a window opens.
  if (o.mode == "golf") {
    load_course(assets, o.course);
    golfer_skill(o.skill);
  } else if (o.mode == "baseball") {
    assets.world("ballpark");
  } else if (o.mode == "lab") {
    UiState st = ui_state_from(o);
    (void)compute(assets, st);
  } else {
    throw InputError("--mode " + o.mode + ": unknown mode (allowed: lab, golf, baseball)");
  }
  WindowOptions wo;
  wo.width = o.width;
  wo.height = o.height;
  wo.vsync = o.frames == 0;
  GameWindow win(wo);
  Renderer renderer(win.framebuffer_width(), win.framebuffer_height());
  FrameStats stats;
  WindowNext next = o.mode == "golf" ? WindowNext::Golf : o.mode == "baseball" ? WindowNext::Baseball : WindowNext::Lab;
  while (next != WindowNext::Quit) {
    switch (next) {
      case WindowNext::Lab: next = run_lab_loop(assets, win, renderer, o, stats, out); break;
      case WindowNext::Golf: next = run_golf_loop(assets, win, renderer, o, stats, out); break;
      case WindowNext::Baseball: next = run_bat_loop(assets, win, renderer, o, stats, out); break;
      case WindowNext::Quit: break;
    }
  }
  return stats;
}

}  // namespace

int run_play_window(const Assets& assets, const PlayOptions& o, std::ostream& out) {
  const FrameStats stats = run_window(assets, o, out);
  if (stats.frames > 0) out << "play: " << stats.frames << " frames, " << stats.ms_total / stats.frames << " ms per frame\n";
  return 0;
}

double measure_window_frame_ms(const Assets& assets, int width, int height, int frames) {
  constexpr int kWarmUp = 10;
  PlayOptions o;
  o.mode = "lab";
  o.width = width;
  o.height = height;
  o.frames = kWarmUp + std::max(frames, 1);
  std::ostringstream quiet;
  FrameStats stats = run_window(assets, o, quiet);
  std::vector<double> ms(stats.frame_ms.begin() + std::min<std::ptrdiff_t>(kWarmUp, static_cast<std::ptrdiff_t>(stats.frame_ms.size())),
                         stats.frame_ms.end());
  if (ms.empty()) throw std::runtime_error("the window ran no frames");
  std::nth_element(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace sweetspot
