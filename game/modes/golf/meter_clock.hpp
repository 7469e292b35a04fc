// The three-click meter in time (DESIGN §9), for the window: the first click starts the
// backswing, the marker climbs from 0 to 110 %; the second fixes the power where it is and
// the marker runs back down, past the accuracy mark at 0 to −15 %; the third, its timing
// against the moment the marker crossed the mark, is the accuracy error (+ late). A putt
// takes two clicks (power only). Left alone the meter finishes itself: 110 % and, on the way
// down, the latest a swing can be (200 ms).
#pragma once

#include <optional>

#include "game/modes/golf/swing_meter.hpp"

namespace sweetspot {

class MeterClock {
 public:
  enum class Phase { Idle, Backswing, Downswing, Done };

  /// `tempo`: seconds the marker takes from 0 to 100 % on the way up; down is 1.5x faster.
  MeterClock(double tempo, bool putting) : tempo_(tempo), putting_(putting) {}

  Phase phase() const { return phase_; }
  bool putting() const { return putting_; }
  /// A click (Space) at time t (s, any clock that only moves forward).
  void click(double t);
  /// Advances to time t: the automatic ends.
  void update(double t);
  /// The marker at time t, −0.15 … 1.1 (fraction of a full swing).
  double position(double t) const;
  double power() const { return power_; }
  /// When the marker crosses the accuracy mark on the way down (s, the click clock): the
  /// time a perfect third click is made. Meaningful from the power click on.
  double mark_time() const { return t_top_ + power_ * tempo_ / kDownFactor; }
  /// The result once Done.
  std::optional<MeterInput> result() const;

  /// Seconds for 0 -> 100 % with `club_length` m (the driver's 0.9 s; shorter clubs swing
  /// quicker in proportion, the putter's stroke 1.2 s).
  static double tempo_for(double club_length, bool putter);

 private:
  static constexpr double kTop = 1.1, kBottom = -0.15, kDownFactor = 1.5;
  double tempo_;
  bool putting_;
  Phase phase_ = Phase::Idle;
  double t_start_ = 0.0, t_top_ = 0.0, power_ = 0.0, accuracy_ms_ = 0.0;
};

}  // namespace sweetspot
