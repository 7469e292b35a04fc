// The golf game's view: the hole in 3-D from behind the ball (a putt low and close), the
// aim line and the green's slopes, the meter, the HUD and the scorecard; keys become the
// GolfPlay model's intents.
#pragma once

#include <memory>
#include <string>

#include "game/modes/golf/golf_play.hpp"
#include "game/ui/mode_view.hpp"

namespace sweetspot {

struct GolfViewOptions {
  bool exit_when_done = false;  ///< done() once the final card has been shown a few frames
  std::string save_path = "sweetspot_round.json";  ///< S writes the round here (resume with play --resume)
  bool imperial = true;         ///< yards and feet (U switches to metres)
};

/// Keys: Up/Down club, Left/Right aim, C the caddie's club, Space the meter's clicks, B the
/// caddie plays, H concede the hole (match play), Enter skips the flyover / the flight / the
/// next hole / a new round. The view's own keys: M the map, 1-4 cameras, U units, S save.
Intents golf_intents(const std::vector<KeyPress>& keys);

std::unique_ptr<ModeView> make_golf_view(const Assets& assets, std::unique_ptr<GolfPlay> model, const GolfViewOptions& o,
                                         std::ostream& out);

}  // namespace sweetspot
