#include "game/render/legend.hpp"

#include <cmath>

#include "game/render/overlay_geometry.hpp"

namespace sweetspot {
namespace {

const Eigen::Vector3f kText{0.92f, 0.92f, 0.92f};
const Eigen::Vector3f kTextShadow{0.05f, 0.07f, 0.05f};

}  // namespace

Eigen::Vector4d append_legend(MeshData& out, const std::vector<LegendEntry>& entries, const Camera& camera, int width,
                              int height, double scale) {
  // A point `depth` m in front of the eye under pixel (x, y): twice the near plane, so it
  // is never clipped; the overlay pass draws it over everything.
  const double depth = 2.0 * camera.near_m;
  const double mpp = 2.0 * depth * std::tan(camera.fov_y / 2) / height;
  const Vec3 f = camera.forward(), right = camera.right(), up = camera.true_up();
  auto screen = [&](double x, double y) {
    return Vec3(camera.eye + depth * f + (x - 0.5 * width) * mpp * right - (y - 0.5 * height) * mpp * up);
  };
  const double h_px = scale * 12.0, gap = scale * 8.0, swatch = scale * 18.0;
  const double x_start = scale * 12.0, y = height - scale * 12.0;
  double x = x_start;
  for (const LegendEntry& e : entries) {
    const double mid = y - 0.5 * h_px;
    append_band(out, screen(x, mid), screen(x + swatch, mid), 0.4 * h_px * mpp, -f, e.color);
    x += swatch + 0.5 * gap;
    append_text(out, e.name, screen(x + 1.0, y + 1.0), right, up, h_px * mpp, kTextShadow);
    append_text(out, e.name, screen(x, y), right, up, h_px * mpp, kText);
    x += text_width(e.name, h_px) + 1.5 * gap;
  }
  return {x_start - 4.0, y - h_px - 4.0, x, y + text_descent(h_px) + 4.0};
}

}  // namespace sweetspot
