#include "game/app/connect_app.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "game/app/game_window.hpp"
#include "game/app/main_loop.hpp"
#include "game/render/renderer.hpp"
#include "game/ui/connect_view.hpp"

namespace sweetspot {

namespace {

LoopStats run_connect(const Assets& assets, const ConnectWindowOptions& o, std::ostream& out, std::ostream& log) {
  ConnectServer server(assets, o.server, out, log);  // bad input fails before a window opens
  log << "sweetspot connect: listening on " << o.server.bind << ":" << server.port() << "; " << server.table().where() << "\n";
  WindowOptions wo;
  wo.width = o.width;
  wo.height = o.height;
  wo.vsync = o.frames == 0;
  wo.title = "Sweetspot: launch monitor";
  GameWindow win(wo);
  Renderer renderer(win.framebuffer_width(), win.framebuffer_height());
  const std::string range = o.server.table.world.empty() ? std::string("golf_hole") : o.server.table.world;
  const ModeRegistry modes = {
      {"connect", [&] { return make_connect_view(assets, server, o.server.bind, range); }},
  };
  LoopOptions lo;
  lo.frames = o.frames;
  lo.screenshot = o.screenshot;
  lo.mute = o.frames > 0;  // automation and the bench: no sound
  return run_main_loop(win, renderer, modes, 0, lo, out);
}

}  // namespace

int run_connect_window(const Assets& assets, const ConnectWindowOptions& o, std::ostream& out, std::ostream& log) {
  run_connect(assets, o, out, log);
  return 0;
}

double measure_connect_frame_ms(const Assets& assets, int width, int height, int frames) {
  constexpr int kWarmUp = 10;
  ConnectWindowOptions o;
  o.server.port = 0;
  o.server.bind = "127.0.0.1";
  o.width = width;
  o.height = height;
  o.frames = kWarmUp + std::max(frames, 1);
  std::ostringstream quiet;
  const LoopStats stats = run_connect(assets, o, quiet, quiet);
  std::vector<double> ms(stats.frame_ms.begin() + std::min<std::ptrdiff_t>(kWarmUp, static_cast<std::ptrdiff_t>(stats.frame_ms.size())),
                         stats.frame_ms.end());
  if (ms.empty()) throw std::runtime_error("the window ran no frames");
  std::nth_element(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace sweetspot
