// A golf session's dispersion: where each stroke off the green landed, carry against TrackMan's Side
// (from the stroke's own aim line), one colour per club, so a player sees each club's
// spread and bias at a glance. Putts and strokes from the green are left out. CPU, headless.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "game/modes/golf/round.hpp"
#include "game/report/metrics.hpp"

namespace sweetspot {

/// 900 × 800 px, distances in `units`, `title` on top. Written atomically; InputError
/// naming the path when it cannot be written.
void write_dispersion_plot(const std::vector<StrokeRecord>& strokes, const std::string& title, const DisplayUnits& units,
                           const std::filesystem::path& png);

}  // namespace sweetspot
