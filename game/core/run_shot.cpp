// Sections: 1. resolve   2. launch (delivery or launch numbers, placed on the world)   3. fly
#include "game/core/run_shot.hpp"

#include <cmath>
#include <cstdio>

#include "game/rules/shot_rules.hpp"
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

// Rotation about +y that turns the target line (+x) by `aim` toward +z (right).
Mat3 aim_rotation(double aim) { return Eigen::AngleAxisd(-aim, Vec3::UnitY()).toRotationMatrix(); }

}  // namespace

// ---- 1. resolve ----------------------------------------------------------------------------
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
                       " m] in world " + r.world_name);
    }
    r.ground.y() = hit.point.y();
    const SurfaceMaterial& under = r.world->world->material(hit.material);
    r.start_surface = to_string(under.kind);
    r.lie_friction = under.lie_friction;
    r.lie_speed_loss = under.lie_speed_loss;
  }
  if (!p.lie.empty() && p.lie != r.start_surface) {
    throw InputError("world.lie: the ball at world.ball_position lies on " + r.start_surface + ", not " + p.lie);
  }
  const double tee = p.teed && r.start_surface == "tee" && r.club_info ? r.club_info->tee_height : 0.0;
  r.ball_centre = r.ground + Vec3(0.0, r.ball.radius + tee, 0.0);
  return r;
}

// ---- 2. launch ------------------------------------------------------------------------------
ShotResult launch_shot(const ResolvedShot& s, const std::string& name) {
  ShotResult r;
  r.scenario = name;
  r.sport = s.sport->name;
  r.world = s.world_name;
  r.aim = s.spec.placement.aim;
  if (const auto* l = std::get_if<LaunchStrike>(&s.spec.strike)) {
    const LaunchNumbers& n = l->numbers;
    r.launch_state = launch_from_metrics(n.ball_speed, n.vertical_angle, n.horizontal_angle, n.spin, n.spin_axis,
                                         s.ball_centre);
  } else {
    Delivery d;
    if (const auto* c = std::get_if<ClubStrike>(&s.spec.strike)) {
      // The lie acts on the strike: grass between face and ball, a club slowed by sand.
      ImpactMaterial face = s.material;
      face.mu *= s.lie_friction;
      GolfSwing through = c->swing;
      through.club_speed *= 1.0 - s.lie_speed_loss;
      // The swing is checked as written first, so a refusal names the value the user gave;
      // then the speed the lie leaves, naming the lie.
      validate_golf_swing(c->swing, *s.club);
      if (!GolfSwing::kClubSpeed.contains(through.club_speed))
        throw InputError("swing.speed: the " + s.start_surface + " lie takes " +
                         std::to_string(static_cast<int>(std::lround(100.0 * s.lie_speed_loss))) +
                         " % of it, leaving " + range_refusal("the speed at the ball", through.club_speed,
                                                              GolfSwing::kClubSpeed, "m/s"));
      d = deliver_golf(s.ball, *s.club, through, face);
      r.lie = s.start_surface;
      const auto& w = c->swing;
      ClubNumbers& k = r.club;
      k.club = s.club->name;
      k.speed = w.club_speed;
      k.speed_at_impact = d.impactor_speed;
      k.attack_angle = w.attack_angle;
      k.path = w.club_path;
      k.face_to_target = w.face_angle;
      k.dynamic_loft = std::isnan(w.dynamic_loft) ? s.club->dynamic_loft : w.dynamic_loft;
      k.lie = s.club->lie;
      k.impact_toe = w.impact_toe;
      k.impact_up = std::isnan(w.impact_up) ? s.club->strike_height : w.impact_up;
      k.closure_rate = w.closure_rate;
      r.impactor_mesh = s.club_info->mesh;
    } else {
      const auto& b = std::get<BatStrike>(s.spec.strike);
      d = deliver_baseball(s.ball, *s.bat, b.swing, b.pitch, s.material);
      BatNumbers& k = r.bat;
      k.bat = s.bat->name;
      k.speed = b.swing.bat_speed;
      k.speed_at_impact = d.impactor_speed;
      k.attack_angle = b.swing.attack_angle;
      k.direction = b.swing.direction;
      k.impact_from_tip = b.swing.impact_from_tip;
      k.undercut = b.swing.undercut;
      k.pitch_speed = b.pitch.speed;
      k.pitch_spin = b.pitch.spin;
      r.impactor_mesh = s.bat_info->mesh;
    }
    // Delivery works with the ball at its own frame's origin; move the shot so the ball
    // sits where it is played.
    const Vec3 shift = s.ball_centre - d.launch.position;
    r.launch_state = d.launch;
    r.launch_state.position += shift;
    r.impactor_at_impact = d.impactor_at_impact;
    r.impactor_at_impact.position += shift;
    r.has_impactor = true;
    r.smash_factor = d.smash_factor;
    ImpactSummary& i = r.impact;
    i.present = true;
    i.e = d.impact.e_used;
    i.e_t = d.impact.e_t_used;
    i.e_t_nominal = s.material.e_t;
    i.mu = s.material.mu;
    i.friction = s.material.friction;
    i.contact = d.impact.contact;
    i.normal_impulse = d.impact.normal_impulse;
    i.tangential_impulse = d.impact.tangential_impulse;
    i.energy_loss = d.impact.energy_loss;
  }
  // Launch numbers are measured relative to the aim line; then the shot turns onto it.
  r.launch = measure_launch(r.launch_state);
  if (r.aim != 0.0) {
    const Mat3 R = aim_rotation(r.aim);
    const Vec3 c = s.ball_centre;
    LaunchState& L = r.launch_state;
    L.position = c + R * (L.position - c);
    L.velocity = R * L.velocity;
    L.spin = R * L.spin;
    if (r.has_impactor) {
      ImpactorPose& P = r.impactor_at_impact;
      P.position = c + R * (P.position - c);
      P.orientation = Quat(R) * P.orientation;
      P.velocity = R * P.velocity;
      P.angular_velocity = R * P.angular_velocity;
    }
  }
  return r;
}

// ---- 3. fly ---------------------------------------------------------------------------------
namespace {

/// Warns (never refuses) when the e the contact used, or the µ / e_t the scenario set, lies
/// outside what laboratories measure for this ball and impactor (clubs.toml / bats.toml
/// `measured`): tuning may explore, but the reader must know the shot is not a real one.
void add_measured_range_warnings(const ResolvedShot& s, ShotResult& r) {
  const MeasuredRange* m = s.club_info ? &s.club_info->measured : s.bat_info ? &s.bat_info->measured : nullptr;
  if (m == nullptr || m->pair.empty()) return;
  const auto check = [&](const char* name, double value, const Range& range) {
    if (range.contains(value)) return;
    char buf[400];
    std::snprintf(buf, sizeof buf, "%s = %.3f is outside the %.2f-%.2f measured for %s (%s); the shot runs, but no real "
                  "equipment does this", name, value, range.min, range.max, m->pair.c_str(), m->source.c_str());
    r.warnings.emplace_back(buf);
  };
  check("e", r.impact.e, m->e);
  if (s.material.friction != FrictionModel::None) check("mu", s.material.mu, m->mu);
  // The compliant contact makes its own e_t; only the rigid model (and the textbook
  // friction) take it as an input.
  if (s.material.model == ImpactModel::Rigid || s.material.friction == FrictionModel::Textbook)
    check("e_t", s.material.e_t, m->e_t);
}

}  // namespace

ShotResult run_shot(const ResolvedShot& s, const std::string& name, const RunOptions& options) {
  ShotResult r = launch_shot(s, name);
  if (!options.fly) return r;
  const BallProperties ball{s.ball.mass, s.ball.radius, s.ball.inertia};
  const Terrain* terrain = s.world ? s.world->world.get() : nullptr;
  ShotModel model = make_shot_model(ball, *s.aero, s.spec.environment, terrain, s.spec.flight);
  if (s.world != nullptr && (s.spec.cup || s.world->pin)) {
    Cup cup;
    cup.centre = s.spec.cup ? *s.spec.cup : *s.world->pin;  // a course may move the world's pin
    cup.flagstick = s.spec.flagstick;
    model.cup = cup;
  }
  if (r.impact.present) add_measured_range_warnings(s, r);
  if (r.impact.present && r.impact.energy_loss < 0.0) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "the %s friction model created %.1f J in the impact (it does not bound the tangential impulse)",
                  to_string(r.impact.friction), -r.impact.energy_loss);
    r.warnings.emplace_back(buf);
  }
  // A delivered launch beyond the spin the aero models were fitted on still flies (they hold
  // S at their fit's end), with a warning: the textbook model's wedge can reach 20 000 rpm.
  LaunchState check = r.launch_state;
  if (check.spin.norm() > LaunchNumbers::kSpin.max && check.spin.allFinite()) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "launch spin %.0f rpm is beyond the %.0f rpm the aero models were fitted on",
                  radps_to_rpm(check.spin.norm()), radps_to_rpm(LaunchNumbers::kSpin.max));
    r.warnings.emplace_back(buf);
    check.spin *= LaunchNumbers::kSpin.max / check.spin.norm();
  }
  if (const std::string why = validate_launch(check); !why.empty()) {
    // Valid inputs can still launch an unflyable ball; say which shot and why rather than a
    // bare flight message.
    throw InputError(name + ": the impact launched a ball the flight model refuses (" + why +
                     "); check impact.friction / impact.mu / swing inputs");
  }
  const auto rules = make_shot_rules(*s.sport, s.world, model);
  ShotState state = start_state(r.launch_state);
  TrajectoryRecorder recorder(state, options.record_samples);
  bool over = false;
  while (!state.ended && !over) {
    const ShotState before = state;
    const ShotEvent ev = step(rules->model(), state);
    recorder.add(before, state, ev);
    over = rules->observe(before, state, ev);
  }
  r.trajectory = recorder.finish(state);
  r.end = rules->outcome(state);
  r.final_state = state;
  return r;
}

const char* to_string(ShotEnd e) {
  switch (e) {
    case ShotEnd::Rest: return "rest";
    case ShotEnd::Holed: return "holed";
    case ShotEnd::Water: return "water";
    case ShotEnd::OutOfBounds: return "out_of_bounds";
    case ShotEnd::HomeRun: return "home_run";
    case ShotEnd::StepLimit: return "step_limit";
  }
  return "?";
}

}  // namespace sweetspot
