// Baseball sessions (DESIGN §9): a home-run derby (swings until N outs, every swing that is
// not a home run an out), an at-bat (a count, a pitcher who mixes types and locations, a
// batter who may take), batting practice (free swings for the spray chart). A bot batter of
// a skill plays them headless with seeded errors; the window lets a person swing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "game/modes/baseball/batting.hpp"
#include "game/util/rng.hpp"

namespace sweetspot {

struct SwingRecord {
  PitchCall call;
  PitchFlight pitch;
  double timing_ms = 0.0;
  double undercut = 0.0;
  bool swung = true;
  bool by_pro = false;  ///< the cage's B: the pro bot swung this one for the player
  SwingResult result;
  std::string call_text;  ///< at-bat: "ball", "called_strike", "swinging_strike", "foul", or the outcome
  std::string said;       ///< the cage: the call as the player was told it ("Strikeout on a foul tip")
};

struct SessionOptions {
  std::string mode = "derby";      ///< derby, at-bat, practice
  int outs = 10;                   ///< derby: outs before it ends
  static constexpr Range kOuts{1.0, 50.0};
  int swings = 20;                 ///< practice: pitches
  static constexpr Range kSwings{1.0, 500.0};
  bool left_handed = false;
};

/// A derby pitch: a batting-practice fastball, ~62 mph down the middle (ESTIMATE of a derby
/// pitcher's pace; the physics of a four-seamer, slower).
PitchCall derby_pitch(const std::vector<PitchType>& types, Rng& rng);

class BotBatter {
 public:
  BotBatter(const Assets& assets, const BatterSkill& skill, std::uint64_t seed);
  /// The swing it means (timing 0, the height that drives the ball farthest for a derby, a
  /// line drive otherwise), then its errors.
  SwingInput plan(const PitchFlight& pitch, bool derby, bool left_handed);
  const BatterSkill& skill() const { return skill_; }

 private:
  const Assets& assets_;
  BatterSkill skill_;
  Rng rng_;
  bool derby_planned_ = false;
  double derby_undercut_ = 0.02;
  double derby_timing_ = 0.0;
};

/// Runs a session with the bot; every swing recorded (JSON as DESIGN §9 for the derby).
std::vector<SwingRecord> run_session(const Assets& assets, const SessionOptions& o, BotBatter& bot, std::uint64_t seed);

}  // namespace sweetspot
