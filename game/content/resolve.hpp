// resolve(): a ShotSpec against the Assets context -> the equipment, materials, aero model,
// world and ball position physics runs with. Deterministic and safe to call from many
// threads on one Assets.
#pragma once

#include <optional>
#include <string>

#include "game/content/assets.hpp"
#include "game/core/shot_spec.hpp"

namespace sweetspot {

/// A ShotSpec with every name looked up and every override applied.
struct ResolvedShot {
  ShotSpec spec;
  const SportProfile* sport = nullptr;
  BallSpec ball;                        ///< after the mass / radius overrides
  std::optional<ClubSpec> club;         ///< club strikes: after the head-mass override
  const ClubInfo* club_info = nullptr;
  std::optional<BatSpec> bat;           ///< bat strikes: after the mass override
  const BatInfo* bat_info = nullptr;
  ImpactMaterial material;              ///< the face or bat material after impact.* overrides
  const AeroModel* aero = nullptr;
  const WorldAsset* world = nullptr;    ///< nullptr: the flat fairway
  std::string world_name;               ///< as resolved ("golf_hole", "none")
  Vec3 ground = Vec3::Zero();           ///< m, the ground point under the ball
  Vec3 ball_centre = Vec3::Zero();      ///< m, the ball's centre at contact
  std::string start_surface;            ///< the surface under the ball ("tee", "fairway", ...; "" in the air)
  double lie_friction = 1.0;            ///< the lie's factor on the face µ (SurfaceMaterial::lie_friction)
  double lie_speed_loss = 0.0;          ///< the lie's club-speed loss before contact
  CorCurve lie_restitution = CorCurve::constant(0.0);  ///< the surface's own bounce (a splash's cushion)
};

/// Looks up every name of `spec` and checks every value against its physics range.
/// Throws InputError naming the field (as a scenario key) and its range.
ResolvedShot resolve(const ShotSpec& spec, const Assets& assets);

}  // namespace sweetspot
