// Marks the window draws over the 3D image (a flagstick, a label) kept clear of the image's
// own labels (Scene::label_boxes) and of the panels: boxes are px (x0, y0, x1, y1), y down.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace sweetspot {

/// The parts of the segment a -> b that lie outside every box, as [t0, t1] along it
/// (0 at a, 1 at b), in order. A segment crossing no box is one part, [0, 1].
std::vector<std::pair<float, float>> parts_clear_of(const Eigen::Vector2f& a, const Eigen::Vector2f& b,
                                                    const std::vector<Eigen::Vector4f>& boxes);

/// Whether the rectangle lo..hi overlaps any of the boxes.
bool overlaps_any(const Eigen::Vector2f& lo, const Eigen::Vector2f& hi, const std::vector<Eigen::Vector4f>& boxes);

}  // namespace sweetspot
