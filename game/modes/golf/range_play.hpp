// The practice range as a headless model: the player hits full swings with the meter at
// target flags on a flat range, a bag-gapping session of `shots_per_club` shots with each
// club moving down the bag by itself, each club's mean carry and spread as they go. The
// measured bag is what the caddie and the map's rings then use (written by the view).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "game/modes/golf/meter_clock.hpp"
#include "game/modes/golf/range_session.hpp"
#include "game/modes/intent.hpp"
#include "physics/math.hpp"

namespace sweetspot {

class RangePlay {
 public:
  enum class Stage { Aiming, Swinging, Flying };

  /// `seed`: the caddie's swings (B) draw their errors from it.
  RangePlay(const Assets& assets, const GolferSkill& skill, int shots_per_club = 5,
            MeterDifficulty difficulty = MeterDifficulty::Standard, std::uint64_t seed = 1);

  /// Intents: Swing (the meter's clicks), Cancel, ClubUp/ClubDown, CaddiePlays (a swing with
  /// the skill's own errors), Continue (skip the flight), Restart (a new session).
  void update(const Intents& intents, double now);

  Stage stage() const { return stage_; }
  const std::string& club() const;
  const std::optional<MeterClock>& meter() const { return meter_; }
  /// The meter a swing press starts: the full swing's tempo at the range's difficulty.
  MeterClock next_meter() const { return MeterClock(MeterClock::tempo_for(false), false, perfect_window_ms(difficulty_)); }
  const std::optional<MeterClock>& last_click() const { return last_click_; }
  const ShotResult& last_shot() const { return last_; }
  double struck_at() const { return struck_at_; }
  const RangeSession& session() const { return session_; }
  int shots_per_club() const { return per_club_; }
  /// Shots hit with the selected club this session.
  int shots_with_club() const;
  const std::string& message() const { return message_; }
  const GolferSkill& skill() const { return skill_; }
  /// The target flags on the ground (m, the tee at the origin, +x down the range): every
  /// 50 yd out to 250 yd (`imperial`), else every 50 m out to 250 m, as the ground's stripes
  /// are marked; set off the line left and right in turn as a range's greens are, so that
  /// from the tee each stands on its own instead of one pole in front of the next.
  static std::vector<Vec3> targets(bool imperial = true);

 private:
  void apply(const Intent& in);
  void advance(double t);
  /// Hits the ball with `m`; `caddie`: a swing drawn with the skill's errors (B), not the meter.
  void strike(const MeterInput& m, double t, bool caddie);

  const Assets& assets_;
  GolferSkill skill_;
  int per_club_;
  MeterDifficulty difficulty_;
  RangeSession session_;
  GolfBot bot_;
  Stage stage_ = Stage::Aiming;
  std::size_t club_ = 0;  ///< index in golf_bag()
  std::optional<MeterClock> meter_, last_click_;
  ShotResult last_;
  double struck_at_ = 0.0;
  std::string message_;
};

}  // namespace sweetspot
