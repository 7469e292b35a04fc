// Sections: 1. launch (delivery or launch numbers, placed on the world)   2. fly
#include "game/rules/run_shot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "game/rules/shot_rules.hpp"
#include "physics/error.hpp"
#include "physics/sand_splash.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

// Rotation about +y that turns the target line (+x) by `aim` toward +z (right).
Mat3 aim_rotation(double aim) { return Eigen::AngleAxisd(-aim, Vec3::UnitY()).toRotationMatrix(); }

}  // namespace

// ---- 1. launch ------------------------------------------------------------------------------
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
      // The lie acts on the strike. Grass lies between face and ball wherever the ball sits in
      // it (less grip; long grass slows the club too). A ball in sand sits on it: struck first
      // it meets the face as from a tight lie, and a splash meets it through the sand
      // (physics/sand_splash.hpp).
      ImpactMaterial face = s.material;
      GolfSwing through = c->swing;
      // The swing is checked as written first, so a refusal names the value the user gave;
      // then the speed the lie leaves, naming the lie.
      validate_golf_swing(c->swing, *s.club);
      const bool sand = s.start_surface == "sand";
      if (c->swing.sand_entry > 0.0) {
        if (!sand)
          throw InputError("swing.sand_entry: a splash is played from sand, and the ball lies on " +
                           (s.start_surface.empty() ? std::string("nothing") : s.start_surface) +
                           " (0in strikes the ball first; from a bunker 0in to 6in)");
        const ClubSpec& k = *s.club;
        through.club_speed = club_speed_after_sand(through.club_speed, k.head_mass + k.shaft_tip_mass,
                                                   2.0 * k.face_half_width, c->swing.sand_entry);
        // The sand's share: its cushion against how far the ball flattens on the face at the
        // strike's normal approach (the head's speed across the face's loft).
        const double approach = through.club_speed * std::cos(face_centre_loft(c->swing, k));
        const double share = cushion_share(sand_cushion(c->swing.sand_entry, s.ball.radius),
                                           hertz_flattening(s.ball.mass, s.ball.compliance.stiffness, approach));
        face.e = mix_restitution(face.e, s.lie_restitution, share);
        face.mu *= 1.0 - share + share * s.lie_friction;
      } else if (!sand) {
        face.mu *= s.lie_friction;
        through.club_speed *= 1.0 - s.lie_speed_loss;
      }
      if (!GolfSwing::kClubSpeed.contains(through.club_speed))
        throw InputError("swing.speed: " +
                         std::string(c->swing.sand_entry > 0.0 ? "the sand before the ball takes " : "the " + s.start_surface + " lie takes ") +
                         std::to_string(static_cast<int>(std::lround(100.0 * (1.0 - through.club_speed / c->swing.club_speed)))) +
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
      k.face_to_target = face_centre_face_angle(w, *s.club);
      k.dynamic_loft = face_centre_loft(w, *s.club);
      k.lie = s.club->lie;
      k.impact_toe = w.impact_toe;
      k.impact_up = strike_up(w, *s.club);
      k.strike_loft = k.dynamic_loft + strike_tilt(*s.club, k.impact_up);
      k.strike_face_angle = k.face_to_target + strike_turn(*s.club, k.dynamic_loft, k.impact_toe, k.impact_up);
      // TrackMan's spin loft: the angle between the head's direction (attack and path) and
      // the face's normal where it meets the ball; a face open or shut to the path adds to it.
      k.spin_loft = std::acos(std::clamp(d.impact_input.normal.normalized().dot(head_direction(w)), -1.0, 1.0));
      k.closure_rate = w.closure_rate;
      k.sand_entry = w.sand_entry;
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
    i.contact_time = d.contact_time;
    // e_t is the rigid solve's input: the contact with duration makes its own tangential
    // rebound from the ball's shear, so a set e_t would otherwise change nothing unseen.
    if (s.spec.impact.e_t && uses_duration(s.ball, s.material))
      r.warnings.emplace_back("impact.e_t acts in the rigid model only (impact.model=rigid); the compliant contact's "
                              "tangential rebound comes from the ball's shear (balls.toml), so it is unused here");
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

// ---- 2. fly ---------------------------------------------------------------------------------
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
  // A splash's rebound is the sand's (run_shot's lie), not the face's: no face's range for it.
  if (r.club.sand_entry <= 0.0) check("e", r.impact.e, m->e);
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
  // Energy created beyond the solve's own round-off (the compliant contact integrates to
  // ~1e-5 J of a ~150 J impact; 0.05 J is the table's last shown digit).
  if (r.impact.present && r.impact.energy_loss < -0.05) {
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
  r.trajectory = recorder.finish(state, rules->model());
  r.end = rules->outcome(state);
  r.final_state = state;
  return r;
}

double flat_roll_distance(const ResolvedShot& s, const SurfaceMaterial& surface) {
  const ShotResult r = launch_shot(s, "flat roll");
  const BallProperties ball{s.ball.mass, s.ball.radius, s.ball.inertia};
  const Vec3 start = r.launch_state.position;
  const FlatGround ground(surface, start.y() - s.ball.radius);
  const ShotModel model = make_shot_model(ball, *s.aero, s.spec.environment, &ground, s.spec.flight);
  ShotState state = start_state(r.launch_state);
  while (!state.ended) step(model, state);
  const Vec3 end = state.position();
  return std::hypot(end.x() - start.x(), end.z() - start.z());
}

ShotResult run_scenario(const Scenario& s, const RunOptions& options) {
  try {
    return run_shot(s.resolved, s.name, options);
  } catch (const InputError& e) {
    // Refused only in flight (a ball the aero model cannot carry): say where its keys were set.
    throw InputError(e.what() + origins_named_in(s.doc, e.what()));
  }
}

}  // namespace sweetspot
