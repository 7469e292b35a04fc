#include "game/modes/golf/meter_clock.hpp"

#include <algorithm>

namespace sweetspot {

double MeterClock::tempo_for(double club_length, bool putter) {
  return putter ? 1.2 : 0.9 * club_length / kDriverLength;
}

double MeterClock::position(double t) const {
  switch (phase_) {
    case Phase::Idle: return 0.0;
    case Phase::Backswing: return std::min(kTop, (t - t_start_) / tempo_);
    case Phase::Downswing: return std::max(kBottom, power_ - kDownFactor * (t - t_top_) / tempo_);
    case Phase::Done: return putting_ ? power_ : 0.0;
  }
  return 0.0;
}

void MeterClock::click(double t) {
  switch (phase_) {
    case Phase::Idle:
      phase_ = Phase::Backswing;
      t_start_ = t;
      break;
    case Phase::Backswing:
      power_ = std::clamp(position(t), 0.01, kTop);
      if (putting_) {
        phase_ = Phase::Done;
      } else {
        phase_ = Phase::Downswing;
        t_top_ = t;
      }
      break;
    case Phase::Downswing: {
      accuracy_ms_ = std::clamp(1000.0 * (t - mark_time()), MeterInput::kAccuracy.min, MeterInput::kAccuracy.max);
      phase_ = Phase::Done;
      break;
    }
    case Phase::Done: break;
  }
}

void MeterClock::update(double t) {
  if (phase_ == Phase::Backswing && (t - t_start_) / tempo_ >= kTop) click(t_start_ + kTop * tempo_);
  if (phase_ == Phase::Downswing && position(t) <= kBottom) {
    accuracy_ms_ = MeterInput::kAccuracy.max;
    phase_ = Phase::Done;
  }
}

std::optional<MeterInput> MeterClock::result() const {
  if (phase_ != Phase::Done) return std::nullopt;
  MeterInput m;
  m.power = power_;
  m.accuracy_ms = putting_ ? 0.0 : accuracy_ms_;
  return m;
}

}  // namespace sweetspot
