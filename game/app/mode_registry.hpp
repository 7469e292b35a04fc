// The modes `play` offers, in Tab order. Adding a mode is one model (game/modes), one view
// (game/ui) and one line in mode_registry.cpp.
#pragma once

#include <ostream>

#include "game/app/main_loop.hpp"
#include "game/app/play_app.hpp"

namespace sweetspot {

ModeRegistry play_modes(const Assets& assets, const PlayOptions& o, std::ostream& out);

/// Refuses (InputError listing the registry's names) a --mode that is not one of them.
void check_play_mode(const Assets& assets, const PlayOptions& o);
/// Loads the golf course the options name (--course, --tees, --pins, --holes), so a wrong one
/// is refused at start, display or not, not when Tab first opens golf.
void check_play_course(const Assets& assets, const PlayOptions& o);

}  // namespace sweetspot
