// The people on the field as articulated stick figures (DESIGN §9): joint positions from the
// play's own numbers, for the window to draw. The pitcher's delivery ends with his hand at
// the pitch's release point, the batter's bat reaches the ball's height at contact, a fielder
// runs the route field_play gave him at his own reaction, acceleration and speed. Headless:
// no drawing here, only where each joint is at a time.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "game/modes/baseball/fielding.hpp"
#include "physics/math.hpp"

namespace sweetspot {

enum Joint : int {
  kHead, kNeck, kPelvis,
  kLeftShoulder, kLeftElbow, kLeftHand, kRightShoulder, kRightElbow, kRightHand,
  kLeftHip, kLeftKnee, kLeftFoot, kRightHip, kRightKnee, kRightFoot,
  kBatKnob, kBatTip,
  kJointCount
};

struct Figure {
  std::array<Vec3, kJointCount> joint{};
  bool has_bat = false;
};

/// The bones to draw between joints (the bat is a bone when the figure has one).
const std::vector<std::pair<Joint, Joint>>& figure_bones();

/// The pitcher's delivery: `t` s from release (negative: the wind-up from the set position,
/// kWindupTime long; positive: the follow-through), ending with his throwing hand at
/// `release` (m, world). `left_handed` mirrors it.
inline constexpr double kWindupTime = 0.9;  // s from the set position to release (ESTIMATE: ~1 s)
Figure pitcher_figure(const Vec3& release, double t, bool left_handed);

/// The batter in the box: `phase` 0 in his stance, 1 at contact (the bat level with the ball
/// at `bat_height` over the plate), up to 1.6 in the follow-through. `left_handed`: he stands
/// on the first-base side.
Figure batter_figure(double phase, double bat_height, bool left_handed);

/// A fielder `t` s after contact running from `start` toward `goal` as field_play timed him
/// (standing still before his reaction, accelerating, then at top speed; stopped at the goal),
/// facing home before he moves and his run after.
Vec3 fielder_position(const Vec3& start, const Vec3& goal, const FielderAbility& ability, double t);
/// `glove`: where the ball is as he fields it (m, world): his glove hand (the left, a
/// right-hander's) reaches for it as far as his arm goes, and he bends for a low one.
Figure fielder_figure(const Vec3& start, const Vec3& goal, const FielderAbility& ability, double t, bool catcher,
                      const std::optional<Vec3>& glove = std::nullopt);

}  // namespace sweetspot
