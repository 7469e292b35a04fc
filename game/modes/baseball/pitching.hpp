// Pitches (DESIGN §9): a pitch type is data (assets/pitches.toml, Statcast league averages);
// the flight from the release point to the plate is the same physics as every ball's (the
// baseball aero model, gravity, drag, Magnus), so the break comes out of the spin.
//
// Frame: home plate at the origin (DESIGN §2), the pitcher's mound toward +x, first base
// toward +z, y up. The pitch flies toward −x; it is read where it crosses the plate, x = 0.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "game/content/assets.hpp"
#include "physics/flight.hpp"
#include "physics/range.hpp"
#include "physics/units.hpp"

namespace sweetspot {

struct PitchType {
  std::string type;              ///< "four-seam", "sinker", "cutter", "slider", "curveball", "changeup"
  double speed = 42.1;           ///< m/s out of the hand
  static constexpr Range kSpeed{mph_to_mps(40.0), mph_to_mps(110.0)};  ///< a lob to the fastest pitch ever (105.8 mph)
  double spin = 239.0;           ///< rad/s, total
  static constexpr Range kSpin{0.0, rpm_to_radps(4000.0)};
  double active_spin = 0.9;      ///< fraction of the spin that is transverse
  double movement_direction = 0; ///< rad from up, + toward first base (catcher's view), right-handed pitcher
  /// rad: how far the pitch's movement turns from where its spin alone pushes it,
  /// + counter-clockwise as the catcher sees a right-hander's pitch (a sinker's: toward the arm
  /// side and down): Hawk-Eye's measured spin axis against the axis its movement implies, the
  /// seam-shifted wake's share. The Magnus force acts at movement_direction + this.
  double seam_wake_deviation = 0;
  static constexpr Range kSeamWakeDeviation{-kPi / 4.0, kPi / 4.0};
  double release_height = 1.78;  ///< m
  double release_side = -0.55;   ///< m, + toward first base
  double extension = 1.98;       ///< m in front of the rubber (60.5 ft from the plate)
  double usage = 0.2;            ///< share of pitches
  /// Share of this type's pitches that cross the zone (Statcast): the pitcher means a type
  /// for the zone as much more or less often than his others (Pitcher::next).
  double zone_share = 0.5;
};

/// The six types; InputError naming the file:line for a bad file.
std::vector<PitchType> load_pitch_types(const Assets& assets);
/// The type by name; InputError listing the names.
const PitchType& pitch_type(const std::vector<PitchType>& types, std::string_view name);

/// A pitch to throw: a type (optionally faster or with more spin), where it should cross
/// the plate, and which hand throws it.
struct PitchCall {
  PitchType type;
  double target_height = 0.76;   ///< m above the ground where it crosses the plate (2.5 ft: mid zone)
  double target_side = 0.0;      ///< m, + toward first base
  bool left_handed = false;
};

/// The pitch as it crosses the plate, and how it got there.
struct PitchFlight {
  Vec3 release = Vec3::Zero();   ///< m
  Vec3 release_velocity = Vec3::Zero();
  Vec3 spin = Vec3::Zero();      ///< rad/s
  double flight_time = 0.0;      ///< s, release to the plate
  Vec3 plate = Vec3::Zero();     ///< m, where it crosses x = 0
  Vec3 plate_velocity = Vec3::Zero();
  Vec3 plate_spin = Vec3::Zero();
  /// The whole flight's break, m (up, + toward first base): at the plate's back point, against
  /// the same release thrown without spin. What a batter sees develop from the hand;
  /// statcast_movement() gives what Statcast reports.
  double flight_break_vertical = 0.0, flight_break_horizontal = 0.0;
  double seam_side_force = 0.0;  ///< C_s of its seam-shifted wake (ShotModel::seam_side_force)
  ShotTrajectory trajectory;     ///< release to the plate (samples), for drawing
};

/// Distance from the rubber to the plate's back point, 60 ft 6 in (MLB Rule 2.01).
inline constexpr double kRubberToPlate = 18.4404;
/// Where Statcast's movement starts and ends, m from the plate's back point: y = 50 ft, the
/// reference of the tracking's nine-parameter fit (PITCHf/x and Statcast's y0), and the
/// front of the plate, 17 in ahead of its back point (MLB Rule 2.02), where plate_x and
/// plate_z are read.
inline constexpr double kMovementStart = 15.24;
inline constexpr double kPlateFront = 0.4318;

/// Flies the pitch to the plate, aimed (by the pitcher's release direction) to cross at the
/// target. Throws InputError for a speed or spin out of range.
PitchFlight throw_pitch(const Assets& assets, const PitchCall& call);

/// A pitch's movement as Statcast reports it (pfx_z, "induced vertical break", and pfx_x), m:
/// from y = 50 ft, where the tracking's fit of the pitch starts, to the front of the plate,
/// the pitch's position less that of the same ball from the same state at 50 ft under the
/// aero law without lift (gravity, drag, spin and its decay alike): the Magnus force's share
/// over those 48.6 ft. Over the whole flight from the hand the same push moves it ~18 % more.
struct PitchMovement {
  double induced_vertical_break = 0.0;
  double horizontal_break = 0.0;  ///< + toward first base (Statcast's pfx_x sign)
  /// Of that movement, the seam-shifted wake's (m, up and + toward first base): against the
  /// same ball from 50 ft with its spin's Magnus force alone. 0 for a pitch without a wake.
  double seam_wake_vertical = 0.0, seam_wake_horizontal = 0.0;
};
PitchMovement statcast_movement(const Assets& assets, const PitchFlight& pitch);

}  // namespace sweetspot
