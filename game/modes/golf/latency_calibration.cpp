#include "game/modes/golf/latency_calibration.hpp"

#include <algorithm>
#include <cmath>

namespace sweetspot {

void LatencyCalibration::tap(double t) {
  const int k = static_cast<int>(std::lround((t - start_) / kPeriod)) - 1;
  if (k < kLeadIn || k >= kBeats || tapped_[static_cast<std::size_t>(k)]) return;
  const double offset = t - beat(k);
  if (std::abs(offset) > 0.5 * kPeriod) return;
  tapped_[static_cast<std::size_t>(k)] = true;
  offsets_.push_back(offset);
}

double LatencyCalibration::flash(double now) const {
  const double since = std::fmod(now - start_, kPeriod);
  if (now < beat(0) - 1e-9 || now > beat(kBeats - 1) + 0.2 * kPeriod) return 0.0;
  return std::max(0.0, 1.0 - since / (0.2 * kPeriod));
}

std::optional<double> LatencyCalibration::latency() const {
  if (counted() < kMinTaps) return std::nullopt;
  std::vector<double> v = offsets_;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  const double median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  return std::clamp(median, kLatency.min, kLatency.max);
}

}  // namespace sweetspot
