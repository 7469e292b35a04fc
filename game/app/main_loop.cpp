#include "game/app/main_loop.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "game/app/audio_out.hpp"
#include "game/app/clip_recorder.hpp"
#include "game/app/pause_menu.hpp"
#include "game/app/resolution_scaler.hpp"
#include "game/render/image.hpp"
#include "game/render/renderer.hpp"

namespace sweetspot {
namespace {

// A mode's place in the loop: its view once made, and its clock: mode time = window time -
// offset, the offset growing by every stretch the mode spent paused or in the background.
struct Slot {
  std::unique_ptr<ModeView> view;
  double offset = 0.0;
  double left_at = 0.0;   // window time the mode was left (its clock stopped there)
  double last_now = 0.0;  // mode time of its last frame
};

// A frame of its own while a mode is made on its first Tab (the golf course's worlds take
// about a second): its name and a word, not the last mode's frame held still. Keys pressed
// meanwhile are kept for the mode.
void show_loading(GameWindow& win, const std::string& mode, std::vector<KeyPress>& keys) {
  const FrameInput fin = win.begin_frame();
  keys.insert(keys.end(), fin.keys.begin(), fin.keys.end());
  const float w = static_cast<float>(win.framebuffer_width()), h = static_cast<float>(win.framebuffer_height());
  // Drawn on the background list: a new auto-sized window is not shown on its first frame.
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  dl->AddRectFilled(ImVec2(0, 0), ImVec2(w, h), IM_COL32(20, 24, 28, 255));
  const std::string text = "Loading " + mode + " ...";
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  dl->AddText(ImVec2(0.5f * (w - size.x), 0.5f * (h - size.y)), IM_COL32(230, 230, 230, 255), text.c_str());
  win.render_ui();
  win.present();
}

}  // namespace

LoopStats run_main_loop(GameWindow& win, Renderer& renderer, const ModeRegistry& modes, std::size_t first,
                        const LoopOptions& o, std::ostream& out) {
  LoopStats stats;
  std::vector<Slot> slots(modes.size());
  AudioOut audio(!o.mute);
  std::optional<ModeView::AmbienceSpec> ambience;  // what the ambience loop plays
  ClipRecorder clips(o.shots_dir);
  ResolutionScaler resolution;
  std::size_t active = first;
  const auto activate = [&](std::size_t i, double wall) {
    Slot& s = slots[i];
    if (!s.view) {
      s.view = modes[i].make();
      s.offset = wall;
      s.last_now = 0.0;
    } else {
      s.offset += wall - s.left_at;
    }
  };
  activate(active, win.clock());
  bool paused = false, quit = false;
  PauseMenu menu;
  double paused_at = 0.0;
  std::vector<KeyPress> carried;  // keys pressed after a Tab: the next mode's
  int shots = 0;                  // F12 screenshots taken

  while (!win.should_close() && !quit) {
    const auto t0 = std::chrono::steady_clock::now();
    FrameInput fin = win.begin_frame();
    std::vector<KeyPress> keys = std::move(carried);
    carried.clear();
    keys.insert(keys.end(), fin.keys.begin(), fin.keys.end());
    const double wall = win.clock();
    Slot& slot = slots[active];
    ModeView& view = *slot.view;

    MenuChoice choice = MenuChoice::None;
    ViewInput vi;
    bool snapshot = false;
    // Takes back a swing under way (Esc; Tab on the way out): no stroke counted.
    const auto cancel_at = [&](double key_time) {
      Intent cancel;
      cancel.kind = IntentKind::Cancel;
      cancel.time = key_time - slot.offset;
      view.send(cancel);
    };
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const KeyPress& k = keys[i];
      if (k.key == GLFW_KEY_F12) {  // a screenshot, in any mode, paused or not
        snapshot = true;
        continue;
      }
      if (k.key == GLFW_KEY_F10) {  // a clip of the shot on screen, in any mode, one at a time
        if (clips.busy()) {
          out << "clip: one is still being made; F10 again once it is written\n";
          continue;
        }
        const ShotScene* scene = view.clip_scene();
        const std::string path = scene ? clips.start(*scene) : std::string();
        out << (path.empty() ? std::string("clip: no shot on screen yet") : "clip: making " + path) << "\n";
        continue;
      }
      if (paused) {
        choice = menu.key(k.key, view.restart_loses(), view.quit_loses());
        if (choice != MenuChoice::None) {
          carried.assign(keys.begin() + static_cast<std::ptrdiff_t>(i) + 1, keys.end());
          break;
        }
        continue;
      }
      if (k.key == GLFW_KEY_TAB) {
        // A swing under way is taken back first (no stroke counted), as Esc takes it back: the
        // mode left behind does not play it out with the clicks it never got.
        if (view.busy()) cancel_at(k.time);
        choice = MenuChoice::NextMode;
        carried.assign(keys.begin() + static_cast<std::ptrdiff_t>(i) + 1, keys.end());
        break;
      }
      if (k.key == GLFW_KEY_ESCAPE) {
        // Esc takes back a swing under way (no stroke counted) and play goes on; with none,
        // it pauses. (Both at one press opened the menu over a cancelled swing.)
        const bool busy = view.busy();
        cancel_at(k.time);
        if (busy) continue;
        paused = true;
        paused_at = k.time;
        continue;
      }
      vi.keys.push_back({k.key, k.time - slot.offset});
    }
    vi.now = (paused ? paused_at : wall) - slot.offset;
    vi.paused = paused;
    vi.dt = std::max(0.0, vi.now - slot.last_now);
    slot.last_now = vi.now;
    vi.render_scale = o.dynamic_resolution ? resolution.scale() : 1.0;
    vi.width = win.framebuffer_width();
    vi.height = win.framebuffer_height();
    if (!paused) {
      vi.orbit_dx = fin.orbit_dx;
      vi.orbit_dy = fin.orbit_dy;
      vi.zoom = fin.zoom;
    }
    view.frame(vi, renderer);
    for (const ImpactSoundInput& s : view.take_sounds())
      if (audio.active()) audio.play(synthesize_impact(s), kImpactSampleRate);
    for (const std::vector<float>& c : view.take_clips())
      if (audio.active()) audio.play(c, kImpactSampleRate);
    if (audio.active()) {
      // The mode's ambience, made anew when it changes (the wind to the nearest m/s).
      ModeView::AmbienceSpec a = view.ambience();
      a.wind_speed = std::round(a.wind_speed);
      if (!ambience || !(*ambience == a)) {
        audio.loop(synthesize_ambience(a.kind, a.wind_speed), kImpactSampleRate);
        ambience = a;
      }
    }
    audio.collect();
    if (paused && choice == MenuChoice::None)
      choice = draw_pause_menu(menu, view.title(), view.restart_label(), view.restart_loses(), view.quit_loses(),
                               view.pause_menu_right(vi.width, vi.height), vi.height);
    if (choice != MenuChoice::None) menu.reset();
    win.render_ui();

    // What the frame decided, applied after the ImGui frame has ended.
    std::optional<std::size_t> next;
    switch (choice) {
      case MenuChoice::None: break;
      case MenuChoice::Resume:
        slot.offset += wall - paused_at;
        paused = false;
        break;
      case MenuChoice::Restart: {
        Intent restart;
        restart.kind = IntentKind::Restart;
        restart.time = paused_at - slot.offset;
        view.send(restart);
        slot.offset += wall - paused_at;
        paused = false;
        break;
      }
      case MenuChoice::NextMode: next = (active + 1) % slots.size(); break;
      case MenuChoice::Quit: quit = true; break;
    }
    if (next) {
      // The mode left keeps its clock where it stopped: at the pause, or now.
      slot.left_at = paused ? paused_at : wall;
      paused = false;
      active = *next;
      if (!slots[active].view) show_loading(win, modes[active].name, carried);
      activate(active, win.clock());
    }

    const bool last = quit || win.should_close() || (o.frames > 0 && stats.frames + 1 >= o.frames) || slots[active].view->done();
    if (snapshot) {
      int sw = 0, sh = 0;
      std::vector<unsigned char> rgba;
      win.read_pixels(sw, sh, rgba);
      // The next number not taken: a screenshot never replaces an earlier one (another run's).
      std::string path;
      std::error_code ec;
      do {
        path = (std::filesystem::path(o.shots_dir) / ("sweetspot_shot_" + std::to_string(++shots) + ".png")).string();
      } while (std::filesystem::exists(path, ec) && shots < 100000);
      try {
        write_png_atomic(path, sw, sh, rgba);
        out << "screenshot: " << path << " (" << sw << "x" << sh << ")\n";
      } catch (const std::exception& e) {
        out << "screenshot not written: " << e.what() << "\n";
      }
    }
    if (last && !o.screenshot.empty()) {
      int sw = 0, sh = 0;
      std::vector<unsigned char> rgba;
      win.read_pixels(sw, sh, rgba);
      write_png_atomic(o.screenshot, sw, sh, rgba);
      out << "screenshot: " << o.screenshot << " (" << sw << "x" << sh << ")\n";
    }
    for (const std::string& line : clips.finished()) out << line << "\n";
    win.present();
    // The whole frame, the swap included: a software rasteriser finishes its work there.
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    resolution.frame(ms);
    ++stats.frames;
    stats.ms_total += ms;
    stats.frame_ms.push_back(ms);
    if (last) break;
  }
  for (const Slot& s : slots)
    if (s.view) s.view->report(out);
  if (clips.busy()) out << "clip: finishing the clip being made before closing\n" << std::flush;
  clips.wait();
  for (const std::string& line : clips.finished()) out << line << "\n";
  return stats;
}

}  // namespace sweetspot
