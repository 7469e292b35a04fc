// Where along his bat a hitter means to meet the ball (DESIGN §9).
//
// Not at the sweet spot itself. People aim a quick movement away from where a miss costs them,
// by as much as their own scatter makes worth it: they pick the aim that maximises their
// expected gain (J. Trommershäuser, L. T. Maloney & M. S. Landy, "Statistical decision theory
// and trade-offs in the control of motor response", Spatial Vision 16 (2003) 255; "Decision
// making, movement planning and statistical decision theory", Trends Cogn. Sci. 12 (2008) 291).
// A hitter's miss lies past the end of his bat, 15 cm beyond the sweet spot, while the barrel
// runs 30 cm the other way before his hands. And a bat met off time is turned by θ from square:
// the ball then crosses its axis 1/cos θ farther out than where he aimed it, so his timing
// alone carries his contact out toward the end. Over his own scatter (his reach and timing
// reads) his mean exit speed is highest a few centimetres inside the sweet spot: there he aims.
#pragma once

#include <string>

#include "game/modes/baseball/batting.hpp"

namespace sweetspot {

class Assets;

/// m toward the hands from the sweet spot of `bat_name` where `skill` aims the pitch's line
/// (SwingInput::aim_inside): the aim whose mean exit speed, head on against a 90 mph pitch, is
/// highest over his reach error (read_reach_sd and eye_sd) and his timing error
/// (read_timing_sd_ms, turning the bat at its sweet spot's speed over its arm); a ball past the
/// end of the bat counts as no exit speed.
/// It allows for his read's scatter only: not for the bias of a type he misreads (early on a
/// changeup he took for the fastball), nor for his shorter two-strike swing; and it never aims
/// out toward the tip (≥ 0).
double aim_inside(const Assets& assets, const BatterSkill& skill, const std::string& bat_name);

}  // namespace sweetspot
