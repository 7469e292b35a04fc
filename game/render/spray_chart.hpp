// A spray chart: where each batted ball of a session landed on the field, seen
// from above, coloured by outcome. Drawn on the CPU into a PNG (no GL), so it works headless.
#pragma once

#include <filesystem>
#include <vector>

#include "game/modes/baseball/session.hpp"

namespace sweetspot {

/// 800 x 800 px: home plate at the bottom, the foul lines, the ballpark's fence, a dot per
/// ball in play (home run red, triple orange, double yellow, single green, out grey, foul
/// light blue). Written atomically; InputError naming the path when it cannot be written.
void write_spray_chart(const Assets& assets, const std::vector<SwingRecord>& swings, const std::filesystem::path& png);

}  // namespace sweetspot
