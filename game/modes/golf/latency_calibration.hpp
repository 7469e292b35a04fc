// Input latency calibration: a beat flashes at a steady tempo and the player taps in time
// with it; the median of their taps' offsets from the beats is the delay between seeing and
// pressing on this machine (display lag, input lag, reaction habit). The meter then judges
// each click that much earlier, so a player whose screen lags is not always "late".
#pragma once

#include <optional>
#include <vector>

#include "physics/range.hpp"

namespace sweetspot {

class LatencyCalibration {
 public:
  /// 0.6 s between beats (100 beats a minute, an easy tempo to tap); 10 beats, the first two
  /// to find the rhythm (not counted); at least 5 counted taps for a result.
  static constexpr double kPeriod = 0.6;  // s
  static constexpr int kBeats = 10, kLeadIn = 2, kMinTaps = 5;
  /// What the meter accepts: a display and input chain lags 10-150 ms (a 60 Hz TV with game
  /// mode off reaches ~100 ms; rtings.com measures 10-120 ms input lag across monitors/TVs).
  static constexpr Range kLatency{0.0, 0.25};  // s

  explicit LatencyCalibration(double start) : start_(start) {}

  /// When beat k (0-based) flashes.
  double beat(int k) const { return start_ + (k + 1) * kPeriod; }
  /// A tap (Space) at time t: matched to the nearest beat.
  void tap(double t);
  bool done(double now) const { return now >= beat(kBeats - 1) + 0.5 * kPeriod; }
  /// How bright the flash is at `now` (1 on the beat, fading over a fifth of the period).
  double flash(double now) const;
  /// Beats flashed by `now` (0..kBeats): the dialog's progress.
  int beats_shown(double now) const {
    const int k = static_cast<int>((now - start_) / kPeriod);
    return k < 0 ? 0 : k > kBeats ? kBeats : k;
  }
  /// Taps counted so far.
  int counted() const { return static_cast<int>(offsets_.size()); }
  /// The latency (s): the median offset of the counted taps, clamped to kLatency; none with
  /// fewer than kMinTaps taps.
  std::optional<double> latency() const;

 private:
  double start_;
  std::vector<double> offsets_;
  std::vector<bool> tapped_ = std::vector<bool>(kBeats, false);
};

/// After a calibration ends, Space taps still coming in its rhythm (a player who started
/// late taps on past the last beat) are taps, not a swing: each one within kQuiet of the
/// calibration's end or of the tap before it is swallowed, and the quiet runs on from it.
class TapQuiet {
 public:
  /// Three beats: long enough that a tap a beat or two late is caught, short enough that a
  /// deliberate swing after the dialog is not refused for long.
  static constexpr double kQuiet = 3.0 * LatencyCalibration::kPeriod;  // s
  void start(double now) { until_ = now + kQuiet; }
  /// Whether a Space at `t` is such a tap (and so no swing).
  bool swallow(double t) {
    if (t >= until_) return false;
    until_ = t + kQuiet;
    return true;
  }

 private:
  double until_ = -1.0;
};

}  // namespace sweetspot
