// Whether a window can be opened here. `play` falls back to headless without one.
#pragma once

#include <string>

namespace sweetspot {

/// True when $DISPLAY or $WAYLAND_DISPLAY names a display. `why` gets a sentence for the
/// user when there is none.
bool display_available(std::string* why = nullptr);

}  // namespace sweetspot
