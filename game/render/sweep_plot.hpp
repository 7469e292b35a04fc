// `sweep --plot`: the e × µ grid read at a glance. One PNG: a heatmap per output (carry,
// total spin, ball speed) over the grid with the grip boundary µ_grip(e) drawn across it
// (right of the line the contact grips and µ changes nothing), and the dispersion of the
// grid's landing points (carry against side, coloured by e). Drawn on the CPU, headless.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "game/report/metrics.hpp"
#include "game/tuning/sweep.hpp"

namespace sweetspot {

/// 1200 × 940 px. `title` heads the image (the scenario); distances and speeds are shown in
/// `units`. A --no-flight grid (no carry) leaves the carry and dispersion panels saying so.
/// Written atomically; InputError naming the path when it cannot be written.
void write_sweep_plot(const std::vector<SweepPoint>& points, const SweepOptions& options, const DisplayUnits& units,
                      const std::string& title, const std::filesystem::path& png);

}  // namespace sweetspot
