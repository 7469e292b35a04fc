// The practice range's view: the tee and target flags every 50 yd on a flat range, the
// meter, the flight, and the bag-gapping table (each club's shots, mean carry, spread and
// the gap to the next club); S saves the measured bag for the caddie (play --bag FILE).
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "game/modes/golf/range_play.hpp"
#include "game/ui/mode_view.hpp"

namespace sweetspot {

struct RangeViewOptions {
  std::string bag_path = "sweetspot_bag.toml";  ///< S writes the measured bag here
  bool imperial = true;
};

/// Keys: Space the meter's clicks, Up/Down club, B a swing with your skill's own errors,
/// Enter skips the flight, S saves the bag, U units.
Intents range_intents(const std::vector<KeyPress>& keys);

std::unique_ptr<ModeView> make_range_view(const Assets& assets, std::unique_ptr<RangePlay> model, const RangeViewOptions& o);

}  // namespace sweetspot
