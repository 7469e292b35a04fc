// ShotSpec: what to simulate, typed, and the only input to a shot (DESIGN §1). Scenario
// files and `--set` (game/content/scenario), the `flight` and `render` flags, the UI, the
// game modes, a launch monitor, the bench and the tests all produce one; resolve() turns
// it, against an explicit Assets context, into what physics runs.
//
// A ShotSpec holds names and values, never loaded assets, so it is cheap to copy, edit and
// compare. Every value's allowed range is the physics parameter's (physics/*.hpp).
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "physics/atmosphere.hpp"
#include "physics/delivery.hpp"
#include "physics/flight.hpp"
#include "physics/impact.hpp"
#include "physics/launch.hpp"

namespace sweetspot {

/// A club swung at the ball (golf). Empty club = the sport's default.
struct ClubStrike {
  std::string club;                    ///< assets/equipment/clubs.toml name, "" = default
  std::optional<double> head_mass;     ///< kg override (inertia scales with it); ClubSpec::kHeadMass
  GolfSwing swing;                     ///< dynamic_loft NaN = the club's typical loft
};

/// A bat swung at a pitch (baseball). Empty bat = the sport's default.
struct BatStrike {
  std::string bat;                     ///< assets/equipment/bats.toml name, "" = default
  std::optional<double> mass;          ///< kg override (inertia scales with it); BatSpec::kMass
  BatSwing swing;
  Pitch pitch;
};

/// No impact: the ball leaves with launch-monitor numbers (`flight`, a launch monitor).
struct LaunchStrike {
  LaunchNumbers numbers;
};

using Strike = std::variant<ClubStrike, BatStrike, LaunchStrike>;

/// Overrides of the impactor's ball contact law; unset = the equipment's own.
struct ImpactOverrides {
  std::optional<double> e;             ///< constant normal restitution (drops the speed curve); ImpactMaterial::kE
  std::optional<double> e_t;           ///< the rigid model's tangential restitution; ImpactMaterial::kEt
  std::optional<double> mu;            ///< ImpactMaterial::kMu
  std::optional<FrictionModel> friction;
  std::optional<ImpactModel> model;    ///< compliant (with duration) or rigid (instantaneous)
};

/// Where the ball is played from on the world.
struct BallPlacement {
  double x = 0.0;                      ///< m downrange of the world's origin
  double z = 0.0;                      ///< m right of it; the height comes from the terrain
  static constexpr Range kHorizontal{-2000.0, 2000.0};
  double aim = 0.0;                    ///< rad, the target line turned right of the world's +x
  static constexpr Range kAim{-kPi, kPi};
  std::string lie;                     ///< required surface under the ball ("" = any); checked by resolve()
  /// Teed up (golf, on a tee box): the ball's bottom sits the club's tee height above the
  /// ground. Ignored by sports that do not rest the ball on the ground.
  bool teed = true;
};

struct ShotSpec {
  std::string sport = "golf";          ///< a sport profile name (assets/sports.toml)
  std::string ball;                    ///< "" = the sport's ball
  std::optional<double> ball_mass;     ///< kg override (inertia scales with it); BallSpec::kMass
  std::optional<double> ball_radius;   ///< m override (inertia scales with r²); BallSpec::kRadius
  Strike strike = ClubStrike{};
  ImpactOverrides impact;
  Environment environment;
  std::string aero;                    ///< "" = the sport's model
  std::string world;                   ///< "" = the sport's world; "none" = flat ground (kFlatWorld)
  BallPlacement placement;
  FlightSettings flight;
  bool flagstick = false;              ///< golf: the flagstick left in the hole (Rules of Golf 13.2a)
  /// golf: the cup's centre on the green (m, world coordinates) when the round moves it (a
  /// course's `pin`); unset = the world's own pin.
  std::optional<Vec3> cup;
};

/// world name of the infinite flat fairway (no course or ballpark), as `flight --world none`.
inline constexpr const char* kFlatWorld = "none";

}  // namespace sweetspot
