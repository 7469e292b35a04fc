// Equipment files: assets/equipment/{balls,clubs,bats}.toml -> BallSpec, ClubSpec, BatSpec
// (physics) plus what the game needs to use and show each piece (kind, mesh, tee height).
// Every value carries its unit in the file ("204g", "9.8deg"); errors name the file, line,
// key and the allowed range (the physics struct's, game/content/toml_file.hpp's rule).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "physics/equipment.hpp"

namespace sweetspot {

/// The game's side of a club: how it is drawn and played.
/// What laboratories measure for a ball against this impactor: a value of e, µ or e_t
/// outside it still runs (tuning explores), with a warning naming the range and `source`.
struct MeasuredRange {
  Range e{0.0, 1.0};    ///< normal COR at the contact (after the speed curve and location factor)
  Range mu{0.0, 2.0};   ///< face/barrel friction coefficient
  Range e_t{0.0, 1.0};  ///< tangential restitution (the rigid model's input)
  std::string pair;     ///< "a golf ball on a club face"
  std::string source;   ///< where the ranges come from
};

struct ClubInfo {
  std::string name;            ///< as ClubSpec::name
  std::string kind;            ///< "wood", "hybrid", "iron", "wedge", "putter" (club choice, sound, camera)
  std::string mesh;            ///< assets/meshes/<mesh>.obj, in the HEAD FRAME of physics/equipment.hpp
  /// m the ball's bottom sits above the ground when teed up on a tee box (driver ~30 mm,
  /// irons ~5 mm); 0 = played off the ground even from the tee (a putter).
  double tee_height = 0.0;
  static constexpr Range kTeeHeight{0.0, 0.1016};  ///< Rule 4.3: a tee is at most 4 in long
  /// A tour player's full swing with this club (TrackMan PGA averages): m/s and rad. The
  /// game scales the speed for every golfer by their driver speed.
  double tour_speed = 40.0;
  double tour_attack = 0.0;
  MeasuredRange measured;      ///< clubs.toml [face.measured], the same for every club
};

/// The game's side of a bat.
struct BatInfo {
  std::string name;
  std::string mesh;            ///< assets/meshes/<mesh>.obj, in the BAT FRAME
  MeasuredRange measured;      ///< bats.toml [bat.material.measured]
};

struct EquipmentCatalog {
  std::vector<BallSpec> balls;
  std::vector<ClubSpec> clubs;   ///< bag order: driver first, putter last
  std::vector<ClubInfo> club_info;  ///< parallel to clubs
  std::vector<BatSpec> bats;
  std::vector<BatInfo> bat_info;    ///< parallel to bats
  /// Look-ups by name; throw InputError listing the allowed names.
  const BallSpec& ball(std::string_view name) const;
  const ClubSpec& club(std::string_view name) const;
  const ClubInfo& club_info_of(std::string_view name) const;
  const BatSpec& bat(std::string_view name) const;
  const BatInfo& bat_info_of(std::string_view name) const;
};

/// Reads balls.toml, clubs.toml and bats.toml from `dir`; heads' meshes are looked up in
/// `dir`/../meshes (the assets layout). Throws InputError
/// ("clubs.toml:42: club 'driver': head_mass = 5 kg is out of range (allowed [0.05, 1] kg)").
EquipmentCatalog load_equipment(const std::filesystem::path& dir);

}  // namespace sweetspot
