#include "game/modes/golf/meter_clock.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "physics/error.hpp"

namespace sweetspot {

double perfect_window_ms(MeterDifficulty d) {
  switch (d) {
    case MeterDifficulty::Easy: return 25.0;
    case MeterDifficulty::Standard: return 10.0;
    case MeterDifficulty::Pro: return 0.0;
  }
  return 0.0;
}

const char* to_string(MeterDifficulty d) {
  switch (d) {
    case MeterDifficulty::Easy: return "easy";
    case MeterDifficulty::Standard: return "standard";
    case MeterDifficulty::Pro: return "pro";
  }
  return "?";
}

MeterDifficulty meter_difficulty(std::string_view name) {
  for (MeterDifficulty d : {MeterDifficulty::Easy, MeterDifficulty::Standard, MeterDifficulty::Pro})
    if (name == to_string(d)) return d;
  throw InputError("unknown difficulty '" + std::string(name) + "' (allowed: easy, standard, pro)");
}

double MeterClock::tempo_for(bool putter) { return putter ? 1.2 : 0.9; }

namespace {
/// `usual`, or slower so that the marker takes kLeastToCup to climb to `mark_power`.
double slowed_to_mark(double usual, double mark_power) {
  if (!(mark_power > 0.0)) return usual;  // no mark to read: the usual
  return std::max(usual, MeterClock::kLeastToCup / mark_power);
}
}  // namespace

double MeterClock::putt_tempo(double cup_power) { return slowed_to_mark(tempo_for(true), cup_power); }

double MeterClock::part_swing_tempo(double mark_power) { return slowed_to_mark(tempo_for(false), mark_power); }

double MeterClock::position(double t) const {
  switch (phase_) {
    case Phase::Idle: return 0.0;
    case Phase::Backswing: return std::min(kTop, (t - t_start_) / tempo_);
    case Phase::Downswing: return std::max(kBottom, power_ - kDownFactor * (t - t_top_) / tempo_);
    case Phase::Done: return putting_ ? power_ : 0.0;
    case Phase::Abandoned: return 0.0;
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
    case Phase::Done:
    case Phase::Abandoned: break;
  }
}

void MeterClock::update(double t) {
  // A moment at the top (a fifth of the tempo) for a late power click, then abandoned.
  if (phase_ == Phase::Backswing && (t - t_start_) / tempo_ >= kTop + kHoldAtTop) phase_ = Phase::Abandoned;
  if (phase_ == Phase::Downswing && position(t) <= kBottom) {
    accuracy_ms_ = MeterInput::kAccuracy.max;
    phase_ = Phase::Done;
  }
}

std::optional<MeterInput> MeterClock::result() const {
  if (phase_ != Phase::Done) return std::nullopt;
  MeterInput m;
  m.power = power_;
  // Inside the window a click plays as perfect; outside, the error less the window.
  const double beyond = std::max(0.0, std::abs(accuracy_ms_) - window_ms_);
  m.accuracy_ms = putting_ ? 0.0 : std::copysign(beyond, accuracy_ms_);
  return m;
}

std::string timing_words(double late_ms) {
  if (std::abs(late_ms) < 0.5) return "on time";
  return (late_ms > 0.0 ? "late " : "early ") + std::to_string(static_cast<long>(std::lround(std::abs(late_ms)))) + "\u00a0ms";
}

}  // namespace sweetspot
