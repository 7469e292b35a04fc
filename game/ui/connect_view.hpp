// The launch-monitor range's view: the Open Connect server's shots replayed as they arrive
// on the round's hole or the range (the device's shot replaces the swing meter), with the
// device's numbers beside the result and, when it sends club data, beside our impact
// model's launch. The server and its ShotTable are the mode's model (game/net).
#pragma once

#include <memory>

#include "game/net/connect_server.hpp"
#include "game/ui/mode_view.hpp"

namespace sweetspot {

/// `where`: "bind:port" for the panel. The server must outlive the view.
std::unique_ptr<ModeView> make_connect_view(const Assets& assets, ConnectServer& server, const std::string& bind,
                                            const std::string& range_world);

}  // namespace sweetspot
