#include "game/ui/mode_view.hpp"

#include <algorithm>
#include <cmath>

#include "game/render/renderer.hpp"

namespace sweetspot {

void fit_renderer(Renderer& renderer, int w, int h, double scale) {
  const double s = std::clamp(scale, 0.25, 1.0);
  const int rw = std::max(16, static_cast<int>(std::lround(w * s)));
  const int rh = std::max(16, static_cast<int>(std::lround(h * s)));
  if (rw != renderer.width() || rh != renderer.height()) renderer.resize(rw, rh);
}

}  // namespace sweetspot
