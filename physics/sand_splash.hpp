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
#pragma once

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

}  // namespace sweetspot
