#include "game/app/connect_app.hpp"

#include "game/app/game_window.hpp"
#include "game/app/main_loop.hpp"
#include "game/render/renderer.hpp"
#include "game/ui/connect_view.hpp"

namespace sweetspot {

int run_connect_window(const Assets& assets, const ConnectWindowOptions& o, std::ostream& out, std::ostream& log) {
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
  run_main_loop(win, renderer, modes, 0, lo, out);
  return 0;
}

}  // namespace sweetspot
