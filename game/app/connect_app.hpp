// `sweetspot connect` with a window: the launch monitor plays the round or the range, each
// shot replayed as it arrives (the device's shot replaces the swing meter), with the device's
// numbers beside the result and, when it sends club data, beside our impact model's launch.
#pragma once

#include <ostream>
#include <string>

#include "game/content/assets.hpp"
#include "game/net/connect_server.hpp"

namespace sweetspot {

struct ConnectWindowOptions {
  ConnectOptions server;
  int frames = 0;          ///< run this many frames then exit (0 = until closed)
  std::string screenshot;  ///< PNG of the last frame
  int width = 1280, height = 800;
};

/// Serves and draws until the window closes (or `frames`, or the server stops). Shot lines
/// go to `out` as headless; server events to `log`. Returns 0.
int run_connect_window(const Assets& assets, const ConnectWindowOptions& o, std::ostream& out, std::ostream& log);

/// The connect window's frame time (ms) at width x height, serving on a free local port with
/// no monitor attached: the median of `frames` frames after 10 warm-up frames, vsync off.
/// What `bench` reports as frame_ms_window_connect_1280x800. Throws std::runtime_error when
/// no window can be opened.
double measure_connect_frame_ms(const Assets& assets, int width, int height, int frames);

}  // namespace sweetspot
