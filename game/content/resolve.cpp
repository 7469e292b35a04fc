// resolve(): a ShotSpec's names looked up in the Assets context and every value checked.
#include "game/content/resolve.hpp"

#include <cmath>

#include "game/content/world_asset.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

// Names the spec field in a physics validator's refusal.
template <class F>
auto checked(const char* what, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(std::string(what) + ": " + e.what());
  }
}

void apply_overrides(const ImpactOverrides& o, ImpactMaterial& m) {
  if (o.e) {
    check_range("impact.e", *o.e, ImpactMaterial::kE, "");
    m.e = CorCurve::constant(*o.e);
  }
  if (o.e_t) {
    check_range("impact.e_t", *o.e_t, ImpactMaterial::kEt, "");
    m.e_t = *o.e_t;
  }
  if (o.mu) {
    check_range("impact.mu", *o.mu, ImpactMaterial::kMu, "");
    m.mu = *o.mu;
  }
  if (o.friction) m.friction = *o.friction;
  if (o.model) m.model = *o.model;
}

}  // namespace

ResolvedShot resolve(const ShotSpec& spec, const Assets& assets) {
  ResolvedShot r;
  r.spec = spec;
  r.sport = &assets.sport(spec.sport);
  const EquipmentCatalog& eq = assets.equipment();
  r.ball = checked("ball.name", [&] { return eq.ball(spec.ball.empty() ? r.sport->ball : spec.ball); });
  // A heavier or larger ball of the same construction: inertia ∝ m r².
  if (spec.ball_mass) {
    check_range("ball.mass", *spec.ball_mass, BallSpec::kMass, "kg");
    r.ball.inertia *= *spec.ball_mass / r.ball.mass;
    r.ball.mass = *spec.ball_mass;
  }
  if (spec.ball_radius) {
    check_range("ball.radius", *spec.ball_radius, BallSpec::kRadius, "m");
    r.ball.inertia *= (*spec.ball_radius / r.ball.radius) * (*spec.ball_radius / r.ball.radius);
    r.ball.radius = *spec.ball_radius;
  }
  if (const auto* c = std::get_if<ClubStrike>(&spec.strike)) {
    if (r.sport->impactor != ImpactorKind::Club)
      throw InputError("a club strike in a " + r.sport->name + " shot (its impactor is a bat)");
    const std::string name = c->club.empty() ? r.sport->default_impactor : c->club;
    r.club = checked("club.name", [&] { return eq.club(name); });
    r.club_info = &eq.club_info_of(name);
    if (c->head_mass) {
      check_range("club.head_mass", *c->head_mass, ClubSpec::kHeadMass, "kg");
      r.club->inertia *= *c->head_mass / r.club->head_mass;
      r.club->head_mass = *c->head_mass;
    }
    r.material = r.club->face;
    validate_golf_swing(c->swing, *r.club);
  } else if (const auto* b = std::get_if<BatStrike>(&spec.strike)) {
    if (r.sport->impactor != ImpactorKind::Bat)
      throw InputError("a bat strike in a " + r.sport->name + " shot (its impactor is a club)");
    const std::string name = b->bat.empty() ? r.sport->default_impactor : b->bat;
    r.bat = checked("bat.name", [&] { return eq.bat(name); });
    r.bat_info = &eq.bat_info_of(name);
    if (b->mass) {
      check_range("bat.mass", *b->mass, BatSpec::kMass, "kg");
      r.bat->inertia_cg *= *b->mass / r.bat->mass;
      r.bat->inertia_axial *= *b->mass / r.bat->mass;
      r.bat->mass = *b->mass;
    }
    r.material = r.bat->material;
    validate_bat_swing(b->swing, *r.bat, r.ball);
    validate_pitch(b->pitch);
  } else {
    const LaunchNumbers& n = std::get<LaunchStrike>(spec.strike).numbers;
    check_range("launch.ball_speed", n.ball_speed, LaunchNumbers::kBallSpeed, "m/s");
    check_range("launch.vertical_angle", n.vertical_angle, LaunchNumbers::kVerticalAngle, "rad");
    check_range("launch.horizontal_angle", n.horizontal_angle, LaunchNumbers::kHorizontalAngle, "rad");
    check_range("launch.spin", n.spin, LaunchNumbers::kSpin, "rad/s");
    check_range("launch.spin_axis", n.spin_axis, LaunchNumbers::kSpinAxis, "rad");
  }
  apply_overrides(spec.impact, r.material);
  check_environment(spec.environment);
  r.aero = &checked("aero.model", [&]() -> const AeroModel& {
    return assets.aero(spec.aero.empty() ? r.sport->default_aero : spec.aero);
  });
  r.world_name = spec.world.empty() ? r.sport->default_world : spec.world;
  r.world = checked("world.name", [&] { return assets.world(r.world_name); });
  // A world is built for one sport (a ballpark's fence, a hole's cup): another sport's shot
  // on it would be scored by the wrong rules.
  if (r.world != nullptr && !r.world->sport.empty() && r.world->sport != r.sport->name)
    throw InputError("world.name: '" + r.world_name + "' is a " + r.world->sport + " world; a " + r.sport->name +
                     " shot needs a " + r.sport->name + " world (e.g. " + r.sport->default_world + ") or none");

  // Where the ball is: resting on the ground at the placement (teed up by the club's tee
  // height), or held at the sport's contact height above the world's origin.
  const BallPlacement& p = spec.placement;
  check_range("world.ball_position[0]", p.x, BallPlacement::kHorizontal, "m");
  check_range("world.ball_position[1]", p.z, BallPlacement::kHorizontal, "m");
  check_range("world.aim", p.aim, BallPlacement::kAim, "rad");
  if (r.sport->contact_height) {
    const Vec3 origin = r.world ? r.world->description().origin : Vec3::Zero();
    r.ground = origin;
    r.ball_centre = origin + Vec3(0.0, *r.sport->contact_height, 0.0);
    return r;
  }
  // BallPlacement is measured from the world's origin (the tee of a hole).
  const Vec3 origin = r.world ? r.world->description().origin : Vec3::Zero();
  r.ground = Vec3(origin.x() + p.x, 0.0, origin.z() + p.z);
  r.start_surface = "fairway";
  if (r.world != nullptr) {
    const WorldDescription& d = r.world->description();
    SurfaceContact hit;
    if (!ground_under(*r.world->world, r.ground.x(), r.ground.z(), d.bounds_max.y(), d.bounds_max.y() - d.bounds_min.y(),
                      &hit)) {
      throw InputError("world.ball_position: no ground under [" + std::to_string(p.x) + " m, " + std::to_string(p.z) +
                       " m] in world " + r.world_name + " (from its origin, " + ground_extent_text(d, d.origin) + ")");
    }
    r.ground.y() = hit.point.y();
    const SurfaceMaterial& under = r.world->world->material(hit.material);
    r.start_surface = to_string(under.kind);
    r.lie_friction = under.lie_friction;
    r.lie_speed_loss = under.lie_speed_loss;
    r.lie_restitution = under.e;
  }
  if (!p.lie.empty() && p.lie != r.start_surface) {
    throw InputError("world.lie: the ball at world.ball_position lies on " + r.start_surface + ", not " + p.lie);
  }
  const double tee = p.teed && r.start_surface == "tee" && r.club_info ? r.club_info->tee_height : 0.0;
  r.ball_centre = r.ground + Vec3(0.0, r.ball.radius + tee, 0.0);
  return r;
}

}  // namespace sweetspot
