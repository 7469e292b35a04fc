// The three-click swing meter (DESIGN §9): the first click starts the swing, the second sets
// the power, the third the accuracy. What the clicks become is a swing the physics then
// plays: power sets club speed; the accuracy click's timing error opens or closes the face,
// moves the path and the strike across the face (so a mishit is gear effect, not a dice
// roll); over-swinging past 100 % adds speed but thins the strike and magnifies the error.
#pragma once

#include "game/content/equipment_file.hpp"
#include "physics/delivery.hpp"
#include "game/core/stroke_input.hpp"

namespace sweetspot {


/// The mapping, per ms of timing error with the driver (a shorter club's by its length
/// ratio: at the same body speed its head, and so its face's turning through impact, is
/// slower in that ratio): the face turns 0.08°, the path 0.04° the other
/// way, the strike moves 0.15 mm toward the heel when late (toe when early). Over-swing
/// p > 1 multiplies the error by 1 + 4 (p − 1) and moves the strike down 30 mm × (p − 1)
/// from the club's usual spot (a thin contact). These are the game's feel, not physics:
/// 20 ms late with a driver opens the face 1.6° — a push-fade of ~20 yd on a tour drive.
inline constexpr double kFacePerMs = 0.0013962634;   // rad (0.08°)
inline constexpr double kPathPerMs = -0.00069813170; // rad (−0.04°)
inline constexpr double kHeelPerMs = 0.00015;        // m toward the heel per late ms
inline constexpr double kDriverLength = 1.1557;      // m (45.5 in): the error's reference club

/// The accuracy click's timing error as the driver would feel it (ms, + late): the click's
/// error scaled by `club`'s length over the driver's and magnified by an over-swing, the
/// error every mapping above reads.
double timing_error_ms(const MeterInput& m, const ClubSpec& club);

/// The swing a meter result delivers with `club` (its ClubSpec and ClubInfo) for a golfer
/// whose full swing with it is `full_speed` m/s. A putter takes the power only.
GolfSwing meter_swing(const MeterInput& m, const ClubSpec& club, const ClubInfo& info, double full_speed);

}  // namespace sweetspot
