// A splash from a bunker (the "explosion" shot): the club enters the sand before the ball,
// ploughs through it, and meets the ball through a cushion of sand rather than with its face.
//
// Two mechanisms, each from the sand itself:
// - The plough. The sole sweeps up the sand in its path, a channel cut_width wide and
//   kSplashDepth deep, and throws it ahead at its own speed: momentum is shared with the sand
//   and the sand's share of the energy is spent in it, so after `entry` m of sand a head of
//   mass m moves at v·m / (m + ρ·A·entry). Nothing is fitted: ρ is bunker sand's bulk density.
// - The cushion. The ball is pushed by sand, so its normal rebound is the sand's own
//   restitution (the bounce of a ball landing in that bunker, SurfaceMaterial::e), and the
//   face's grip reaches it through layers of sand that slide over one another (McPhee, Golf
//   Digest 2015: the more layers, the less spin), the sand's lie_friction.
// A ball struck first (entry 0: the fairway-bunker "pick") meets the face as from a tight lie.
// Between the two, the cushion is only as thick as the sand the sole has gathered: a layer
// thinner than the ball flattens against the face is pressed through, and the face meets the
// ball through it. The sand takes the strike's share cushion / flattening (at most all of it),
// so a splash that enters a few millimetres behind the ball plays between the two and nothing
// jumps as the entry moves.
#pragma once

#include "physics/impact.hpp"
#include "physics/range.hpp"

namespace sweetspot {

/// kg/m³, dry bunker sand: USGA Green Section guidance gives bulk densities of ~1.4-1.7 g/cm³
/// for bunker sands (silica, medium to fine); the middle of that range.
inline constexpr double kBunkerSandDensity = 1600.0;
/// m, how deep the sole runs under the ball on a splash: teaching's "slide the club about half
/// an inch under the ball" (the sand's "dollar-bill" divot).
inline constexpr double kSplashDepth = 0.0127;
/// m of sand before the ball: from a ball struck first to 6 in behind it, past the 2-4 in
/// behind that a splash is ever taught with (the farther, the fatter).
inline constexpr Range kSandEntry{0.0, 0.1524};
/// The taught splash: the club enters the sand "an inch behind the ball", and the 30-yard
/// pitch stroke then sends the ball "roughly 30 feet" (Backswing, "Calibrate your sand
/// explosion shots"; tests/unit/game/rules/test_run_shot.cpp checks it).
inline constexpr double kSplashEntry = 0.0254;

/// The head's speed where it reaches the ball after ploughing `entry` m of sand (m/s), for a
/// head (with the shaft tip that moves with it) of `head_mass` kg cutting a channel
/// `cut_width` m wide. Never faster than `speed`; equal to it at entry 0.
double club_speed_after_sand(double speed, double head_mass, double cut_width, double entry,
                             double density = kBunkerSandDensity, double depth = kSplashDepth);

/// m of sand between face and ball after a splash that entered `entry` m behind it: the
/// channel's sand (`depth` deep, the face's width) banked up the face from the sole to the
/// ball's centre, depth + radius high: depth · entry / (depth + radius). 9.5 mm at the taught
/// inch for a golf ball.
double sand_cushion(double entry, double ball_radius, double depth = kSplashDepth);

/// m, how far a ball of `mass` kg and Hertz stiffness `stiffness` (F = k δ^{3/2}) flattens
/// against a rigid face met at `normal_speed` m/s: all the approach energy stored at the
/// undamped peak, ½ m v² = (2/5) k δ^{5/2}, so δ = (5 m v² / 4k)^{2/5}. A golf ball: 1.9 mm at
/// 8 m/s (a splash), 7.5 mm at 45 m/s (a drive).
double hertz_flattening(double mass, double stiffness, double normal_speed);

/// The share of the strike the sand takes: `cushion` over the ball's `flattening`, in [0, 1].
/// 1 for a flattening of 0 (a rigid ball: any sand is a cushion) with sand there.
double cushion_share(double cushion, double flattening);

/// `face` and `sand` mixed in `share` of the sand: each point of either curve is kept, its
/// restitution (1 − share)·face + share·sand there; the face's curve at share 0, the sand's
/// at 1. Where the two have more points together than a curve holds, the face's points.
CorCurve mix_restitution(const CorCurve& face, const CorCurve& sand, double share);

}  // namespace sweetspot
