#include "game/app/display.hpp"

#include <cstdlib>

namespace sweetspot {

bool display_available(std::string* why) {
  const char* x = std::getenv("DISPLAY");
  const char* wl = std::getenv("WAYLAND_DISPLAY");
  if ((x && *x) || (wl && *wl)) return true;
  if (why) *why = "no display found ($DISPLAY and $WAYLAND_DISPLAY are unset)";
  return false;
}

}  // namespace sweetspot
