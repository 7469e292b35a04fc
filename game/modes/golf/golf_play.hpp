// The golf game as a headless model (DESIGN §1, §9): a round stroke by stroke against a bot
// of the same skill, the club and aim the player picks, the three-click meter judged from
// each click's own time, the flight's time in the air, the hole's and the round's end. The
// window's view draws it and turns keys into intents; the tests drive it with scripted ones.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/meter_clock.hpp"
#include "game/modes/golf/round.hpp"
#include "game/modes/intent.hpp"

namespace sweetspot {

class GolfPlay {
 public:
  enum class Stage { Aiming, Swinging, Flying, HoleOver, RoundOver };

  /// `opponent_seed`: the bot of the same skill, who plays the course first (its card is fixed).
  GolfPlay(const Assets& assets, Course course, const GolferSkill& skill, std::uint64_t opponent_seed = 7);

  /// Applies `intents` in time order and advances to `now` (s, the mode's clock): a meter
  /// finishes itself at its end, a flight lands, the hole ends.
  void update(const Intents& intents, double now);

  Stage stage() const { return stage_; }
  const GolfRound& round() const { return round_; }
  const GolferSkill& skill() const { return skill_; }
  const GolfBot& caddie() const { return caddie_; }
  const std::vector<int>& opponent_strokes() const { return opponent_; }
  const std::string& club() const;
  double aim() const { return aim_; }              ///< rad right of the line to the pin
  const std::optional<MeterClock>& meter() const { return meter_; }
  /// The last stroke's physics and the time it was struck (its flight runs from then).
  const ShotResult& last_shot() const { return last_; }
  double struck_at() const { return struck_at_; }
  /// The last stroke's meter result (none for the caddie's strokes).
  const std::optional<MeterInput>& last_meter() const { return last_meter_; }
  const std::string& message() const { return message_; }
  /// Strokes cancelled with Esc this round (none of them counted).
  int cancelled() const { return cancelled_; }

  /// The ball's centre where it lies (teed up on a tee).
  Vec3 ball_centre() const;
  /// World direction of the aim, horizontal unit.
  Vec3 aim_direction() const;

  /// Aim steps: a degree for a full shot, a quarter of one for a putt.
  static constexpr double kAimStep = 0.017453292519943295;   // rad (1°)
  static constexpr double kPuttAimStep = 0.004363323129985824; // rad (0.25°)
  /// A scorecard takes no Enter for this long after the ball stops: a press meant to skip a
  /// flight that had just ended does not skip the card too.
  static constexpr double kCardGrace = 0.5;  // s

 private:
  void apply(const Intent& in);
  void advance(double t);
  void land(double t);
  void strike(const StrokeInput& s, double t);
  void choose_club();
  void new_round();
  void restart_hole();

  const Assets& assets_;
  Course course_;
  GolferSkill skill_;
  GolfRound round_;
  GolfBot caddie_;
  std::vector<int> opponent_;
  std::vector<std::vector<StrokeInput>> played_;  ///< each hole's strokes: restart replays the holes before
  Stage stage_ = Stage::Aiming;
  std::size_t club_ = 0;  ///< index in golf_bag()
  double aim_ = 0.0;
  std::optional<MeterClock> meter_;
  std::optional<MeterInput> last_meter_;
  ShotResult last_;
  double struck_at_ = 0.0, landed_at_ = 0.0;
  std::string message_;
  int cancelled_ = 0;
};

const char* to_string(GolfPlay::Stage s);

}  // namespace sweetspot
