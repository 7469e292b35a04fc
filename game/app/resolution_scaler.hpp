// Dynamic resolution (issue 44's frame budget): the 3D view renders at a share of the
// window's pixels that keeps frames inside the budget. A software rasteriser's cost grows
// with the pixels it shades (llvmpipe on 2 cores: ~20 ms per megapixel in the batting cage),
// so a frame over budget lowers the share and one well under it raises it again, in steps
// that leave time to see their effect (a resize reallocates the framebuffers). On a GPU the
// frames stay under budget and the share stays 1.
#pragma once

#include <algorithm>
#include <cmath>

namespace sweetspot {

class ResolutionScaler {
 public:
  /// `budget_ms`: the frame time to stay under (the 20 ms, less a margin).
  explicit ResolutionScaler(double budget_ms = 18.0) : budget_(budget_ms) {}
  double scale() const { return scale_; }
  /// The last frame's time (ms, the work of the frame, not a vsync wait).
  void frame(double ms) {
    smoothed_ = smoothed_ <= 0.0 ? ms : 0.8 * smoothed_ + 0.2 * ms;
    if (++since_change_ < kSettleFrames) return;
    // Pixels scale with the square of the share: aim the share at the budget from where the
    // frames are, a step of at most 20 % down and 10 % up.
    double next = scale_;
    if (smoothed_ > budget_) next = scale_ * std::max(0.8, std::sqrt(budget_ / smoothed_));
    else if (smoothed_ < 0.7 * budget_) next = scale_ * 1.1;
    next = std::clamp(std::round(next * 20.0) / 20.0, kMin, 1.0);  // 5 % steps: few resizes
    if (next != scale_) {
      scale_ = next;
      since_change_ = 0;
    }
  }

 private:
  static constexpr int kSettleFrames = 8;
  static constexpr double kMin = 0.5;  ///< below half a side the picture is too soft to play
  double budget_;
  double scale_ = 1.0;
  double smoothed_ = 0.0;
  int since_change_ = 0;
};

}  // namespace sweetspot
