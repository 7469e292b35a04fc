// The hole on a green (DESIGN §5): where a rolling ball drops, lips out, or meets
// the flagstick. Geometry and mechanics only; holing out as a score is the game's rule.
//
// Capture (Holmes, "Putting: how a golf ball and hole interact", Am. J. Phys. 59, 1991):
// a ball whose centre crosses the hole on a chord of length L falls freely while its centre
// is over the hole; it is caught when it has dropped a ball radius before its centre reaches
// the far edge less a radius, so the fastest ball that drops is
//     v_c(b) = (L(b) − R_ball) · √(g / (2 R_ball)),   L(b) = 2 √(R_hole² − b²),
// 1.31 m/s through the centre (b = 0) for a 108 mm hole and a 42.7 mm ball. Holmes's fall
// starts where the ball leaves the rim's edge, which it does at once when it comes in toward
// the hole's axis faster than √(g r) (0.46 m/s: the edge would have to pull to keep it). A
// faster ball meets the far rim's edge while its centre is still above it; the edge grips, so
// the ball keeps its angular momentum about the edge through the blow and tips over it,
// turned toward the hole's middle when it passed off centre and slowed by the blow. A ball that comes in slower toward the axis (a glancing putt) rolls
// onto the edge and rides it (Hogan & Antali, "Mechanics of the golf lip out", R. Soc. Open
// Sci. 12, 250907, 2025): gravity tips it in, its turn around the hole flings it out, and it
// leaves turned around the hole, toward the side it did not pass on, by as much as half a
// turn, or drops.
//
// Flagstick (Rules of Golf 13.2a: the player may leave it in): a vertical cylinder of radius
// 6.35 mm (0.25 in, the stick Pelz measured) at the centre. A ball that strikes it rebounds
// off the cylinder with the stick's restitution and then drops or not by Holmes's rule from
// where it is, along its new path: a centred putt that would have jumped the hole is stopped
// by the stick and drops (Pelz 1990), a glancing one is turned aside and can lip out (Mase 2019).
#pragma once

#include "physics/math.hpp"
#include "physics/range.hpp"

namespace sweetspot {

struct Cup {
  Vec3 centre = Vec3::Zero();   ///< m, the hole's centre on the green surface
  double radius = 0.053975;     ///< m; Rules of Golf: 4.25 in (107.95 mm) diameter
  static constexpr Range kRadius{0.03, 0.5};
  double depth = 0.1016;        ///< m; at least 4 in (Rules of Golf, Definitions "Hole")
  bool flagstick = false;       ///< the stick left in the hole
  double stick_radius = 0.00635;     ///< m, 0.25 in
  /// Ball–stick restitution, ESTIMATE: a fibreglass stick flexing in its ferrule absorbs
  /// nearly all of a putt's speed (Pelz 1990: the stick "absorbs speed"); 0.05.
  double stick_restitution = 0.05;
};

/// Holmes's capture speed (m/s, ≥ 0) for a ball of `ball_radius` whose centre passes
/// `offset` m from the hole's centre (0 when the chord is shorter than the ball's radius).
double cup_capture_speed(const Cup& cup, double ball_radius, double offset);

/// What the hole does to a ball rolling from `from` to `to` (centres, m) with velocity `v`.
struct CupPass {
  enum class Kind { Miss, Holed, LipOut, Stick };
  Kind kind = Kind::Miss;
  double fraction = 1.0;        ///< along from→to where it happened
  Vec3 velocity = Vec3::Zero(); ///< after (LipOut, Stick: the ball goes on)
  /// LipOut: where the ball leaves the rim, from the point at `fraction` (m, in the green's
  /// plane), and the time it spent over and around the hole after reaching it (s; Holed too).
  Vec3 leave_offset = Vec3::Zero();
  double time_on_rim = 0.0;
};
/// Where the centre's straight path from→to enters the hole's circle (radius cup.radius
/// about its axis), as a fraction of the way; +infinity when the path misses the circle or
/// meets it only behind `from`. `up`: the green's normal there.
double cup_entry(const Cup& cup, const Vec3& from, const Vec3& to, const Vec3& up);
/// `up`: the green's normal there (the hole is cut perpendicular to it).
CupPass pass_over_cup(const Cup& cup, double ball_radius, const Vec3& from, const Vec3& to, const Vec3& v,
                      const Vec3& up);

}  // namespace sweetspot
