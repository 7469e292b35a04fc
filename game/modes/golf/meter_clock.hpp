// The three-click meter in time (DESIGN §9), for the window: the first click starts the
// backswing, the marker climbs from 0 to 110 %; the second fixes the power where it is and
// the marker runs back down, past the accuracy mark at 0 to −15 %; the third, its timing
// against the moment the marker crossed the mark, is the accuracy error (+ late). A putt
// takes two clicks (power only). Left alone at the top (no power click: a stray key) the
// swing is abandoned and nothing is played; after the power click, a missing third click
// plays the latest a swing can be (200 ms late).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "game/modes/golf/swing_meter.hpp"

namespace sweetspot {

/// How forgiving the accuracy click is: a window around the mark inside which a click plays
/// as perfect, and outside which the error plays less the window's half-width. The click's
/// own error is still shown as it was.
enum class MeterDifficulty { Easy, Standard, Pro };
/// The window's half-width (ms): Easy 25, Standard 10, Pro 0 (every ms counts). A 60 Hz
/// frame is 16.7 ms and a good player's click scatter ~10 ms (DESIGN §9's tour bot draws
/// 10 ms): Standard forgives that scatter, Easy a frame and a half, Pro nothing.
double perfect_window_ms(MeterDifficulty d);
const char* to_string(MeterDifficulty d);
/// "easy", "standard", "pro"; InputError listing them.
MeterDifficulty meter_difficulty(std::string_view name);
/// A click's timing in a player's words: "on time", "late 8 ms", "early 40 ms"; the number
/// and its unit joined by a no-break space (U+00A0, in the HUD font's Latin-1 range), as a
/// panel wraps its lines at spaces and "late 8" over "ms" reads as two things.
std::string timing_words(double late_ms);

class MeterClock {
 public:
  enum class Phase { Idle, Backswing, Downswing, Done, Abandoned };

  /// `tempo`: seconds the marker takes from 0 to 100 % on the way up; down is 1.5x faster.
  MeterClock(double tempo, bool putting, double window_ms = 0.0) : tempo_(tempo), putting_(putting), window_ms_(window_ms) {}

  Phase phase() const { return phase_; }
  /// When the first click started the backswing.
  double started() const { return t_start_; }
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
  /// The result once Done: the accuracy error as it plays (less the perfect window).
  std::optional<MeterInput> result() const;
  /// The accuracy click's own error (ms, + late) once Done, as the player clicked it.
  double click_error_ms() const { return accuracy_ms_; }
  /// Where the marker stood at the accuracy click (−0.15 … 1.1): the meter's click mark.
  double accuracy_position() const { return -kDownFactor * (accuracy_ms_ / 1000.0) / tempo_; }
  double window_ms() const { return window_ms_; }
  /// Seconds the marker takes from 0 to 100 % on the way up.
  double tempo() const { return tempo_; }
  /// The perfect window's half-width as a fraction of the meter (for drawing it).
  double window_fraction() const { return kDownFactor * (window_ms_ / 1000.0) / tempo_; }

  /// Seconds for 0 -> 100 %: 0.9 s for every club, 1.2 s for the putter's stroke. A golfer
  /// keeps one tempo through the bag (Novosel & Garrity, "Tour Tempo", 2004: tour players'
  /// swings take the same time and the same 3:1 backswing-to-downswing ratio with a driver
  /// as with a wedge), and a player times his clicks to the marker's pace, which a tempo
  /// that changed with the club would throw off with every club change.
  static double tempo_for(bool putter);
  /// The putter's stroke for a putt whose cup is at `cup_power` on the meter: 1.2 s for
  /// 0 -> 100 %, slowed so the marker takes at least kLeastToCup to reach the cup's power. A
  /// tap-in at 8 % is then a press 0.6 s long, not a flick of 96 ms where 24 ms is a quarter
  /// of the distance; a 20 ft putt (~55 %) keeps the usual tempo.
  static double putt_tempo(double cup_power);
  /// A part swing's tempo when the caddie's power for it is `mark_power`: the full swing's
  /// tempo, slowed as a putt's is so the marker takes at least
  /// kLeastToCup to reach the mark. A 14 % chip with the lob wedge is then a 0.6 s press and a
  /// 0.4 s fall to the accuracy mark, not 126 and 84 ms at the full tempo, quicker than a
  /// hand can judge; a 90 % swing keeps the full tempo.
  static double part_swing_tempo(double mark_power);
  static constexpr double kLeastToCup = 0.6;  // s

 private:
  static constexpr double kTop = 1.1, kBottom = -0.15, kDownFactor = 1.5, kHoldAtTop = 0.2;
  double tempo_;
  bool putting_;
  double window_ms_;
  Phase phase_ = Phase::Idle;
  double t_start_ = 0.0, t_top_ = 0.0, power_ = 0.0, accuracy_ms_ = 0.0;
};

}  // namespace sweetspot
