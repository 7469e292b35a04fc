// The game window's one main loop (DESIGN §1): a registry of modes, each a view over its
// model; one is active. Every frame the active view gets the key presses of the frame with
// the time each went down, on its own clock, and draws. Tab switches to the next mode (each
// keeps its state: a round in progress is there when you come back); Esc cancels what is in
// progress and pauses (resume, restart, next mode, quit). A mode's clock stops while it is
// paused or another mode is active.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "game/app/game_window.hpp"
#include "game/ui/mode_view.hpp"

namespace sweetspot {

class Renderer;

/// A mode the window can show: its name (`--mode NAME`) and how its view (with its model) is
/// made, on first use.
struct ModeEntry {
  std::string name;
  std::function<std::unique_ptr<ModeView>()> make;
};
using ModeRegistry = std::vector<ModeEntry>;

struct LoopOptions {
  int frames = 0;           ///< stop after this many frames (automation); 0 = until closed
  std::string screenshot;   ///< PNG of the last frame
  std::string shots_dir = ".";  ///< F12 writes sweetspot_shot_N.png here
  bool mute = false;        ///< no sound (no audio device is opened)
  /// Lower the 3D view's resolution while frames run over budget (ResolutionScaler).
  bool dynamic_resolution = true;
};

struct LoopStats {
  int frames = 0;
  double ms_total = 0.0;
  std::vector<double> frame_ms;  ///< each frame's time (ms), in order
};

/// Runs `modes` from `first` until the window closes, Quit is chosen, the frame budget is
/// spent or the active view is done(). At the end each mode that ran reports to `out`.
LoopStats run_main_loop(GameWindow& win, Renderer& renderer, const ModeRegistry& modes, std::size_t first,
                        const LoopOptions& o, std::ostream& out);

}  // namespace sweetspot
