// What a launch monitor's shots play (DESIGN §10): a round of a course, stroke by stroke from
// where the ball lies (the device's shot replaces the swing meter), or a practice range where
// every shot flies from the world's tee. It turns each Open Connect shot into a ShotSpec run
// through the one data path (resolve -> run_shot), and, when the device sent ClubData, runs
// our impact model on the same delivery so the two can be compared. No sockets here: the
// server (game/net/connect_server) and the window both use it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/content/assets.hpp"
#include "game/core/shot_result.hpp"
#include "game/net/open_connect.hpp"

namespace sweetspot {

struct ShotTableOptions {
  std::string course;  ///< play this course's round (a name of assets/courses or a .toml); "" = the range
  std::string world;   ///< the range's world ("" = the golf sport's world, "none" = flat)
};

class ShotTable {
 public:
  /// Throws InputError for an unknown course or world.
  ShotTable(const Assets& assets, const ShotTableOptions& o);
  ~ShotTable();
  ShotTable(const ShotTable&) = delete;
  ShotTable& operator=(const ShotTable&) = delete;

  struct Played {
    /// The shot's line (DESIGN §10): shot_number, launch and flight (§6 keys, SI), club,
    /// device, and for a round the hole, stroke, lie and end; with ClubData, `club_data`
    /// (the device's delivery, SI) and `model` (our impact model's launch for it).
    nlohmann::json line;
    bool flown = false;                ///< false: a zero-speed "shot" (no ball hit), not flown
    bool club_changed = false;         ///< the club the game expects next changed (send 201)
    bool round_over = false;           ///< the round ended with this shot (send 203)
    std::optional<ShotResult> result;  ///< the physics result, for drawing (when flown)
  };
  /// Plays one shot message (kind Shot, with BallData). Throws InputError when the numbers
  /// are beyond what the flight can fly (the message says which).
  Played play(const OcMessage& m, bool record_samples = false);

  /// The 201 reply for what the game expects now: handed "RH", the club's GSPro code and,
  /// in a round, the distance to the pin in yards.
  std::string player_reply() const;
  /// The club the game expects next (a club of golf_bag()).
  std::string club() const;
  /// "hole 2, 143 m to the pin, fairway" / "range on golf_hole".
  std::string where() const;
  /// The round, when playing one (nullptr on the range).
  const class GolfRound* round() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Our impact model's launch for a device's ClubData with `club` (a club of the bag): the
/// delivery fields mapped to GolfSwing (speed, attack, path, face to target, dynamic loft,
/// face impact in mm with + toward the toe and up, closure rate), flown on flat ground
/// without flight. nullopt when the device sent no club speed; throws InputError when a
/// field is beyond the physics range (naming the field).
std::optional<ShotResult> predict_from_club_data(const Assets& assets, const std::string& club, const OcClubData& c);

/// The club in the player's hands on the range (which has no club choice): the bag's club
/// whose typical dynamic loft is nearest the device's loft; without a loft, the one whose
/// impact-model launch angle for the device's delivery is nearest the measured `vla_deg`;
/// "driver" when the device sent no club speed either.
std::string club_for_delivery(const Assets& assets, const OcClubData& c, double vla_deg);

}  // namespace sweetspot
