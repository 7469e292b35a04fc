// The key to the image's colours (the trail's phases, the delivery marks), drawn in the
// bottom-left corner as screen-fixed overlay geometry: a coloured swatch and a word per
// entry, sized in pixels. Pure geometry.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "game/render/camera.hpp"
#include "game/render/mesh_data.hpp"

namespace sweetspot {

struct LegendEntry {
  Eigen::Vector3f color;  ///< the swatch, RGB 0..1
  const char* name;       ///< lower-case word in the 5x7 font ("flight", "path", ...)
};

/// Appends the legend to `out` (drawn without depth test) for a width x height image;
/// `scale` multiplies its pixel sizes (1 at 720 lines). Returns the pixel rectangle it
/// covers (x0, y0, x1, y1), for the label declutter to keep clear.
Eigen::Vector4d append_legend(MeshData& out, const std::vector<LegendEntry>& entries, const Camera& camera, int width,
                              int height, double scale);

}  // namespace sweetspot
