// The window's Play mode (issue 16): a round of golf on a course, stroke by stroke with the
// three-click meter, beside the Lab (play_app). Tab switches between them.
#pragma once

#include <ostream>
#include <vector>

#include "game/app/game_window.hpp"
#include "game/app/play_app.hpp"
#include "game/render/renderer.hpp"

namespace sweetspot {

/// What a window loop hands back to play_app: close, or switch to the other mode.
enum class WindowNext { Quit, Lab, Golf, Baseball };

/// Frames run so far and their time, shared by the modes (the `--frames` budget is one).
struct FrameStats {
  int frames = 0;
  double ms_total = 0.0;
  std::vector<double> frame_ms;  ///< each frame's time (ms), in order
};

/// Ends a frame: the screenshot on the last automated frame, then the swap. True when
/// the `--frames` budget is spent.
bool end_frame(GameWindow& win, const PlayOptions& o, FrameStats& stats, double frame_ms, std::ostream& out,
               bool force_last = false);

WindowNext run_golf_loop(const Assets& assets, GameWindow& win, Renderer& renderer, const PlayOptions& o,
                         FrameStats& stats, std::ostream& out);

}  // namespace sweetspot
