// The modes `play` offers, in Tab order. Adding a mode is one model (game/modes), one view
// (game/ui) and one line in mode_registry.cpp.
#pragma once

#include <ostream>

#include "game/app/main_loop.hpp"
#include "game/app/play_app.hpp"

namespace sweetspot {

ModeRegistry play_modes(const Assets& assets, const PlayOptions& o, std::ostream& out);

}  // namespace sweetspot
