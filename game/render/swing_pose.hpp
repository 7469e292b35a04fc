// The club head or bat before impact, for the replay's pre-roll (the strike animated with
// the delivery we simulate). The impactor swings on an arc about a pivot (the
// lead shoulder, the batter's hands) that lies up the shaft from the contact (the shaft's
// part square to the velocity), in the plane of the shaft and the delivered velocity, speeding up from rest at the top to the delivered
// speed at impact: it arrives along the club path and attack angle the impact solve used,
// with the face the solve used. Pure geometry; visual only (the physics starts at impact).
#pragma once

#include <optional>
#include <string>

#include "game/render/shot_scene.hpp"

namespace sweetspot {

/// Visual swing constants: the arc's radius from the contact to the pivot (a tour driver's
/// lead arm plus its 45 in shaft is ~1.7 m, an iron's less; a bat's sweet spot is ~0.7 m
/// from the knob plus the arms) and the downswing's duration (tour golfers ~0.25 s, the
/// "3:1" tempo of a 0.75 s backswing; a major-league swing ~0.15 s from launch to contact).
/// After impact the impactor turns on round the same arc, slowing evenly to rest at the
/// finish: `finish` rad past impact (ESTIMATE: ~170°, a golfer's club ends over his lead
/// shoulder and a batter's bat wraps round behind him).
/// A club's part swing finishes short: its follow-through runs `follow_per_backswing` times
/// its backswing's arc (ESTIMATE 1.5: chipping instruction's "a follow-through as long as the
/// backswing, or a little longer"), up to `finish` (0: always `finish`). A full swing's arc,
/// ω·downswing/2, passes 2 rad from ~24 m/s (a 54 mph wedge): every full swing finishes
/// over the shoulder, a 14 % chip at ~6 m/s about 0.75 rad past the ball.
struct SwingShape {
  double radius = 1.5;     ///< m, contact to pivot
  double downswing = 0.25; ///< s, from rest at the top to impact
  double finish = 3.0;     ///< rad turned after impact, to rest
  double follow_per_backswing = 0.0;  ///< a part swing's follow-through over its backswing's arc (0: always `finish`)
};
inline constexpr SwingShape kClubSwing{1.5, 0.25, 3.0, 1.5};
inline constexpr SwingShape kBatSwing{1.2, 0.15, 3.0};
/// A putting stroke: a pendulum from the shoulders (arms and a 34 in putter, ~1.1 m), its
/// forward stroke ~0.3 s (tour putting tempo: a ~0.6 s backstroke, ~2:1), and a
/// follow-through about as long as a mid-length putt's backstroke (~0.35 rad, ~40 cm of
/// head travel; ESTIMATE), not a full swing's finish over the shoulder.
inline constexpr SwingShape kPutterSwing{1.1, 0.3, 0.35};

/// The swing of an impactor mesh: "bat", "putter_head", or any other club's.
const SwingShape& swing_shape(const std::string& impactor_mesh);

/// The impactor at time t (s; impact at 0) given its pose and velocity at impact.
/// `contact` is the point of the impactor touching the ball (m); `shaft` the unit direction
/// from the contact toward the grip or knob. At t = 0 it is `impact`; around it, it moves
/// at impact.velocity; before -shape.downswing it rests at the top of the swing, and after
/// 2 finish / ω (ω = speed / radius) at the finish. An impact without a velocity is
/// returned unchanged.
ImpactorPlacement swing_pose(const ImpactorPlacement& impact, const Vec3& contact, const Vec3& shaft, double t,
                             const SwingShape& shape);

/// m/s: an impactor slower than this at impact has no swing to show (GolfSwing's slowest
/// putter head is 0.1 m/s).
inline constexpr double kMinDeliveredSpeed = 0.05;

/// How long before launch a replay (or `render --at`) may show the downswing: the swing's
/// duration when the impactor has a mesh and a delivered velocity, else 0.
double swing_pre_roll(const std::optional<ImpactorPlacement>& impactor, const std::string& impactor_mesh);

/// HEAD FRAME's shaft axis (scripts/gen_meshes.py: up the ~60 deg lie toward the heel,
/// tilted back a little), unit.
Vec3 head_frame_shaft_axis();

}  // namespace sweetspot
