// The golf game's view: the hole in 3-D from behind the ball (a putt low and close), the
// aim line and the green's slopes, the meter, the HUD and the scorecard; keys become the
// GolfPlay model's intents.
#pragma once

#include <memory>

#include "game/modes/golf/golf_play.hpp"
#include "game/ui/mode_view.hpp"

namespace sweetspot {

struct GolfViewOptions {
  bool exit_when_done = false;  ///< done() once the final card has been shown a few frames
};

/// Keys: Up/Down club, Left/Right aim, C the caddie's club, Space the meter's clicks, B the
/// caddie plays, Enter skips the flight / the next hole / a new round.
Intents golf_intents(const std::vector<KeyPress>& keys);

std::unique_ptr<ModeView> make_golf_view(const Assets& assets, std::unique_ptr<GolfPlay> model, const GolfViewOptions& o,
                                         std::ostream& out);

}  // namespace sweetspot
