#include "game/ui/clear_of.hpp"

#include <algorithm>

namespace sweetspot {

std::vector<std::pair<float, float>> parts_clear_of(const Eigen::Vector2f& a, const Eigen::Vector2f& b,
                                                    const std::vector<Eigen::Vector4f>& boxes) {
  // The stretch of [0, 1] inside each box (Liang-Barsky clipping), then what they leave.
  std::vector<std::pair<float, float>> hidden;
  const Eigen::Vector2f d = b - a;
  for (const Eigen::Vector4f& o : boxes) {
    float t0 = 0.0f, t1 = 1.0f;
    bool inside = true;
    const float p[4] = {-d.x(), d.x(), -d.y(), d.y()};
    const float q[4] = {a.x() - o[0], o[2] - a.x(), a.y() - o[1], o[3] - a.y()};
    for (int k = 0; k < 4 && inside; ++k) {
      if (p[k] == 0.0f) {
        inside = q[k] >= 0.0f;  // parallel to this edge: inside only on its inner side
      } else {
        const float t = q[k] / p[k];
        if (p[k] < 0.0f) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        inside = t0 < t1;
      }
    }
    if (inside) hidden.emplace_back(t0, t1);
  }
  std::sort(hidden.begin(), hidden.end());
  std::vector<std::pair<float, float>> parts;
  float from = 0.0f;
  for (const auto& [h0, h1] : hidden) {
    if (h0 > from) parts.emplace_back(from, h0);
    from = std::max(from, h1);
  }
  if (from < 1.0f) parts.emplace_back(from, 1.0f);
  return parts;
}

bool overlaps_any(const Eigen::Vector2f& lo, const Eigen::Vector2f& hi, const std::vector<Eigen::Vector4f>& boxes) {
  return std::any_of(boxes.begin(), boxes.end(), [&](const Eigen::Vector4f& o) {
    return lo.x() < o[2] && o[0] < hi.x() && lo.y() < o[3] && o[1] < hi.y();
  });
}

}  // namespace sweetspot
