// The window's batting cage (issue 17): pitches seen from the batter's box, a strike-zone
// overlay, the swing on a key, the call on screen, a spray chart and session stats.
#pragma once

#include "game/app/golf_app.hpp"

namespace sweetspot {

WindowNext run_bat_loop(const Assets& assets, GameWindow& win, Renderer& renderer, const PlayOptions& o,
                        FrameStats& stats, std::ostream& out);

}  // namespace sweetspot
