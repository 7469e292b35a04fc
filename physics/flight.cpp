// The shot loop of DESIGN §1: ShotModel (read-only) + ShotState (plain data) advanced by
// step(). Sections: 1. model and state   2. step   3. recording   4. simulate_shot
// The steps themselves are in physics/detail (air_step, touch_surface, roll_step).
#include "physics/flight.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "physics/detail/flight_steps.hpp"
#include "physics/error.hpp"

namespace sweetspot {

// ---- 1. model and state --------------------------------------------------------------------
namespace {

/// Air density (kg/m³) times this is the least density of a ball the flight equations hold
/// for: they leave out buoyancy (ρ_air/ρ_ball of the weight) and the air the ball carries
/// along (added mass, half the displaced air's: ρ_air/(2ρ_ball) of the mass), so both stay
/// under 1 %. A golf ball is ~950 times sea-level air, a softball ~330 times; a 10 g ball of
/// radius 10 cm is 2 times, as light as a party balloon, and floats half its weight.
constexpr double kMinDensityOverAir = 100.0;

/// Osmium, the densest element (22.59 g/cm³, CRC Handbook of Chemistry and Physics): no ball
/// of any material is denser (a 500 g ball of radius 10 mm would be 119 g/cm³).
constexpr double kMaxBallDensity = 22590.0;  // kg/m³

std::string grams_per_cm3(double kg_per_m3) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g g/cm³", kg_per_m3 / 1000.0);
  return text;
}

/// A mass and a radius each inside their ranges can still make no ball the models know.
void check_ball_density(const BallProperties& ball, double air_density) {
  const double density = ball.mass / (4.0 / 3.0 * kPi * ball.radius * ball.radius * ball.radius);
  const bool too_dense = density > kMaxBallDensity;
  if (!too_dense && density >= kMinDensityOverAir * air_density) return;
  const std::string what = "flight: a ball of " + std::to_string(std::lround(1000.0 * ball.mass)) +
                           " g (ball.mass) and radius " + std::to_string(std::lround(1000.0 * ball.radius)) +
                           " mm (ball.radius) has a density of " + grams_per_cm3(density);
  if (too_dense) throw InputError(what + ", denser than any material (osmium, the densest, is 22.6 g/cm³)");
  throw InputError(what + ", less than 100 times the air's (" + grams_per_cm3(air_density) +
                   "): the air would carry over 1 % of its weight and mass, which the flight model leaves out; a heavier or smaller ball");
}

}  // namespace

void set_seam_side_force(ShotModel& model, double c_s) {
  check_range("flight.seam_side_force", c_s, ShotModel::kSeamSideForce, "");
  model.seam_side_force = c_s;
}

ShotModel make_shot_model(const BallProperties& ball, const AeroModel& aero, const Environment& environment,
                          const Terrain* terrain, const FlightSettings& settings) {
  if (!(ball.mass > 0.0 && ball.mass <= 1.0)) throw InputError("ball.mass out of range (allowed (0, 1] kg)");
  if (!(ball.radius > 0.0 && ball.radius <= 0.2)) throw InputError("ball.radius out of range (allowed (0, 0.2] m)");
  if (!(ball.inertia > 0.0 && ball.inertia <= ball.mass * ball.radius * ball.radius))
    throw InputError("ball.inertia out of range (allowed (0, mass·radius²] kg·m²)");
  check_environment(environment);
  check_range("flight.rel_tol", settings.rel_tol, FlightSettings::kRelTol, "");
  check_range("flight.abs_tol", settings.abs_tol, FlightSettings::kAbsTol, "");
  check_range("flight.bounce_rel_tol", settings.bounce_rel_tol, FlightSettings::kBounceRelTol, "");
  check_range("flight.position_error_time", settings.position_error_time, FlightSettings::kPositionErrorTime, "s");
  check_range("flight.max_time", settings.max_time, FlightSettings::kMaxTime, "s");
  check_range("flight.max_steps", settings.max_steps, FlightSettings::kMaxSteps, "");
  check_range("flight.roll_speed", settings.roll_speed, FlightSettings::kRollSpeed, "m/s");
  check_range("flight.rest_speed", settings.rest_speed, FlightSettings::kRestSpeed, "m/s");
  check_range("world.firmness", settings.ground_firmness, kFirmness, "");
  if (settings.green_stimp != 0.0) check_range("world.stimp", settings.green_stimp, SurfaceMaterial::kStimp, "m");
  // The flat default ground is immutable, so one instance serves every thread.
  static const FlatGround flat;
  ShotModel m;
  m.ball = ball;
  m.aero = &aero;
  m.environment = environment;
  m.terrain = terrain != nullptr ? terrain : &flat;
  m.settings = settings;
  m.air_density = air_density(environment);
  m.air_viscosity = air_viscosity(environment.temperature);
  check_ball_density(ball, m.air_density);
  return m;
}

ShotState start_state(const LaunchState& launch) {
  ShotState s;
  s.y.segment<3>(0) = launch.position;
  s.y.segment<3>(3) = launch.velocity;
  s.y.segment<3>(6) = launch.spin;
  s.max_height = launch.position.y();
  s.step_size = 0.0;  // the first air step chooses it (launch_step in air_step.cpp)
  return s;
}

const char* to_string(ShotEventKind k) {
  switch (k) {
    case ShotEventKind::Step: return "step";
    case ShotEventKind::Landing: return "landing";
    case ShotEventKind::Bounce: return "bounce";
    case ShotEventKind::Roll: return "roll";
    case ShotEventKind::Airborne: return "airborne";
    case ShotEventKind::Rest: return "rest";
    case ShotEventKind::LeftWorld: return "left_world";
    case ShotEventKind::StepLimit: return "step_limit";
    case ShotEventKind::InCup: return "in_cup";
    case ShotEventKind::LipOut: return "lip_out";
  }
  return "?";
}

// ---- 2. step -------------------------------------------------------------------------------
namespace {

/// The invariant under every step: the ball's centre never passes through a surface from its
/// front. The air step sweeps the whole ball and the roll, skid and crease steps look ahead
/// for the faces they may meet, yet random worlds have corners of V-shaped ditches and
/// creases where a step ends with the centre under a third face (a hop off one face of a
/// corner onto another), after which the ball would fall out of the world (1–2 in 20 000
/// shots of the random-world soak). So the centre's path over the step is swept as a
/// point (the sweep skips faces it leaves or runs along, so only a front-to-back crossing
/// counts), and a crossing is undone: the ball is put back on the face's front where its
/// centre met it and strikes that face (bounce, or roll on). A ball dropped into the cup
/// passes below the green's mesh on purpose and is not swept.
constexpr double kCentrePointRadius = 1e-9;  // m: the centre as a point, for the exact sphere sweep

void keep_centre_above_ground(const ShotModel& m, ShotState& s, const Vec3& from, const Vec3& v_from, double dt,
                              bool airborne, ShotEvent& ev) {
  if (s.ended && s.end == EndReason::InCup) return;
  const Vec3 to = s.position();
  if ((to - from).squaredNorm() == 0.0) return;
  // An air step is an arc, not its chord: under a constant acceleration the path departs
  // from the chord by at most |Δv|·dt/8 (the parabola's sagitta). A long carry's chord cuts
  // through the hill the ball flew over, so an air step is checked only when that departure
  // is under a quarter of the radius — a centre that close to the chord and behind a face
  // crossed it (its sphere, which the air step sweeps, could not have reached there in
  // front of it). A roll, skid or crease step moves along the ground and is short: always.
  // An air step that ended at a touch ended its arc with the velocity it touched with, not
  // the bounce's: a hop that leaves at 0.9 m/s up and bounces off again at 0.7 m/s up has
  // swung through 1.8 m/s, not 0.2 (judged by the velocity after the bounce, every short hop
  // would be swept again here, ~1 200 instructions each).
  const bool touched = ev.kind == ShotEventKind::Landing || ev.kind == ShotEventKind::Bounce;
  const Vec3 v_end = touched ? ev.velocity_in : s.velocity();
  if (airborne && (v_end - v_from).norm() * dt / 8.0 > 0.25 * m.ball.radius) return;
  if (!m.terrain->may_touch(from, to, 0.0)) return;  // far above everything (most of a carry)
  SurfaceContact hit;
  ++s.counters.sweeps;
  if (!m.terrain->sweep(from, to, kCentrePointRadius, &hit, nullptr)) return;
  if (hit.normal.dot(to - hit.point) >= 0.0) return;  // ends in front of the face: touched, not crossed
  const Vec3 at = from + hit.fraction * (to - from);   // where the centre met the face
  s.ended = false;
  s.end = EndReason::Rest;
  s.crease_n1 = s.crease_n2 = Vec3::Zero();
  s.skidding = false;
  s.y.segment<3>(0) = at + (m.ball.radius - hit.normal.dot(at - hit.point)) * hit.normal;
  s.phase = Phase::Bounce;
  s.rate_valid = false;
  hit.fraction = 0.0;
  ev = detail::touch_surface(m, s, hit);
}

}  // namespace

ShotEvent step(const ShotModel& model, ShotState& state, double until) {
  if (state.ended) return ShotEvent{state.end == EndReason::Rest ? ShotEventKind::Rest : ShotEventKind::Step, {}, {}};
  const bool airborne = state.phase == Phase::Flight || state.phase == Phase::Bounce;
  const Vec3 from = state.position();
  const Vec3 v_from = state.velocity();
  const double t0 = state.t;
  ShotEvent ev = airborne ? detail::air_step(model, state, until) : detail::roll_step(model, state, until);
  keep_centre_above_ground(model, state, from, v_from, state.t - t0, airborne, ev);
  const auto put_to_rest = [&] {
    state.y.segment<6>(3).setZero();
    state.phase = Phase::Rest;
    state.ended = true;
    state.end = EndReason::Rest;
    ev.kind = ShotEventKind::Rest;
  };
  // Held: a ball passed between a touch, a roll and the air at one instant, over and over,
  // makes no progress (a knife-edge crease or a corner of steep faces that each send it to
  // the other, which would spin to the step limit). The faces hold it,
  // so it is at rest there, as a rigid-body engine puts a body to sleep once its motion
  // stops (Box2D, Jolt). 64 instants: a real touch-and-roll takes a handful.
  // A step shorter than 0.1 µs is no progress (the integrator's smallest useful step at a
  // touch is ~1e-6 s; a loop that advances by round-off counts as held: a ball skidding
  // off one face of a steep pit and touching it again 2e-8 s later, 2 500 times, in the
  // random-world soak). (Free flight that stops advancing is refused in air_step instead.)
  state.stalled = state.t > t0 + detail::kNoProgress ? 0 : state.stalled + 1;
  if (!state.ended && state.stalled >= detail::kStalledSteps) put_to_rest();
  // Asleep: a ball rolling slower than rest_speed for half a second is at rest where it is,
  // as a rigid-body engine puts a body to sleep (Box2D: linear sleep tolerance 1 cm/s, time
  // to sleep 0.5 s). A slope too steep to hold a ball still speeds it past rest_speed well
  // within that time unless its pull exceeds the turf's resistance by under rest_speed/0.5 s
  // = 0.04 m/s² (a few hundredths of a degree of slope), and such a ball would creep for the
  // whole 300 s at 6-16 mm/s (random-world soak). Faces that each cannot hold a ball alone
  // can between them: at a pit where several facets meet, a ball shuffles from one to the
  // next at 0.1 mm/s (a faceted bowl's bottom, test_roll_step.cpp).
  constexpr double kTimeToSleep = 0.5;  // s
  const double rest_speed = model.settings.rest_speed;
  if (!state.ended && state.phase == Phase::Roll && state.velocity().squaredNorm() < rest_speed * rest_speed) {
    if (state.t - state.sleep_since >= kTimeToSleep) put_to_rest();
  } else {
    state.sleep_since = state.t;
  }
  if (airborne && !state.ended && state.phase == Phase::Roll && ev.kind == ShotEventKind::Bounce) {
    ev.kind = ShotEventKind::Roll;  // a later touch that put the ball on the ground for good
  }
  return ev;
}

Vec3 flight_position_between(const Vec3& p0, const Vec3& v0, double t0, const Vec3& p1, const Vec3& v1, double t1,
                             double t) {
  const double h = t1 - t0;
  if (!(h > 0.0)) return p1;
  const double u = (t - t0) / h;
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * h * v0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * h * v1;
}

// ---- 3. recording --------------------------------------------------------------------------
namespace {

// The summary's landing figures from the state at the first touch and the velocity it came in with.
void note_landing(FlightSummary& sum, const Vec3& launch, const ShotState& after, const Vec3& v) {
  const Vec3 p = after.position();
  sum.carry_m = std::hypot(p.x() - launch.x(), p.z() - launch.z());
  sum.hang_time_s = after.t;
  sum.lateral_m = p.z() - launch.z();
  sum.landing_position = p;
  sum.landing_angle_deg = rad_to_deg(std::atan2(-v.y(), std::hypot(v.x(), v.z())));
}

}  // namespace

TrajectoryRecorder::TrajectoryRecorder(const ShotState& launch, bool record_samples, double interval)
    : launch_(launch.position()), record_(record_samples), interval_(interval) {
  if (record_) {
    out_.samples.reserve(512);
    out_.samples.push_back({launch.t, launch.position(), launch.velocity(), launch.spin(), launch.phase});
  }
  next_sample_ = launch.t + interval_;
}

void TrajectoryRecorder::add(const ShotState& before, const ShotState& after, const ShotEvent& ev) {
  FlightSummary& sum = out_.summary;
  const bool touched = ev.kind == ShotEventKind::Landing || ev.kind == ShotEventKind::Bounce ||
                       ev.kind == ShotEventKind::Roll;
  if (ev.kind == ShotEventKind::Landing) note_landing(sum, launch_, after, ev.velocity_in);
  if (!record_) return;
  const bool was_airborne = before.phase == Phase::Flight || before.phase == Phase::Bounce;
  if (was_airborne) {
    const Vec3 v_end = touched ? ev.velocity_in : after.velocity();
    while (next_sample_ < after.t) {
      const double t = next_sample_;
      const double u = (t - before.t) / (after.t - before.t);
      const Vec3 p = flight_position_between(before.position(), before.velocity(), before.t, after.position(), v_end,
                                             after.t, t);
      const Vec3 v = before.velocity() + u * (v_end - before.velocity());
      const Vec3 w = before.spin() + u * (after.spin() - before.spin());
      out_.samples.push_back({t, p, v, w, before.phase});
      next_sample_ += interval_;
    }
    if (touched) out_.samples.push_back({after.t, after.position(), after.velocity(), after.spin(), Phase::Bounce});
    return;
  }
  // Rolling: every step is a sample; leaving the ground restarts the airborne grid.
  out_.samples.push_back({after.t, after.position(), after.velocity(), after.spin(),
                          after.phase == Phase::Rest ? Phase::Rest
                          : after.phase == Phase::Roll ? Phase::Roll
                                                        : Phase::Bounce});
  if (after.phase == Phase::Bounce) next_sample_ = after.t + interval_;
}

ShotTrajectory TrajectoryRecorder::finish(const ShotState& last, const ShotModel& model) {
  ShotTrajectory out = finish(last);
  const double field = model.terrain->reference_height();
  if (last.landed || last.end != EndReason::LeftWorld || last.phase != Phase::Flight ||
      !(last.position().y() > field + model.ball.radius)) {
    return out;  // landed, stopped for another reason, or left below the field's level
  }
  // The rest of the flight over open ground: the same air, ball and settings, no world.
  const FlatGround open_ground(default_fairway(), field);
  ShotModel open = model;
  open.terrain = &open_ground;
  open.cup.reset();
  // The flight so far was judged against its own tolerance; its rest, a few hundred metres
  // more air, is flown at a twentieth of it so the projected carry holds flight's 1 cm
  // contract (at the shot's tolerance the default-tolerance carries of long drives that
  // leave golf_hole drift 8 mm from the tight reference). It runs only for such shots.
  open.settings.rel_tol = model.settings.rel_tol / 20.0;
  ShotState s = last;
  s.ended = false;
  // Bounded: a ball a few hundred metres up comes down within a minute of air time.
  constexpr double kMaxExtraTime = 120.0;  // s
  while (!s.ended && s.t < last.t + kMaxExtraTime) {
    const ShotEvent ev = step(open, s);
    if (ev.kind != ShotEventKind::Landing) continue;
    note_landing(out.summary, launch_, s, ev.velocity_in);
    out.summary.total_m = out.summary.carry_m;
    out.summary.apex_m = std::max(out.summary.apex_m, s.max_height - launch_.y());
    break;
  }
  return out;
}

ShotTrajectory TrajectoryRecorder::finish(const ShotState& last) {
  FlightSummary& s = out_.summary;
  const Vec3 p = last.position();
  if (!last.landed) {
    // Never touched ground (left the world in the air, step limit): carry is where it went.
    s.carry_m = std::hypot(p.x() - launch_.x(), p.z() - launch_.z());
    s.hang_time_s = last.t;
    s.lateral_m = p.z() - launch_.z();
    s.landing_position = p;
  }
  s.end = last.end;
  s.rest_position = p;
  s.total_m = std::hypot(p.x() - launch_.x(), p.z() - launch_.z());
  s.total_time_s = last.t;
  s.apex_m = last.max_height - launch_.y();
  s.bounces = last.bounces;
  out_.stats = last.counters;
  if (record_) {
    // The last sample is the end state (replacing a sample taken at the same instant).
    if (!out_.samples.empty() && out_.samples.back().t >= last.t) out_.samples.pop_back();
    const Phase ph = last.end == EndReason::Rest ? Phase::Rest : last.phase;
    out_.samples.push_back({last.t, p, last.velocity(), last.spin(), ph});
  }
  return std::move(out_);
}

// ---- 4. simulate_shot ----------------------------------------------------------------------
std::string validate_launch(const LaunchState& l) {
  if (!l.position.allFinite() || !l.velocity.allFinite() || !l.spin.allFinite())
    return "launch: position, velocity and spin must be finite numbers";
  if (auto w = range_refusal("launch ball speed", l.velocity.norm(), LaunchNumbers::kBallSpeed, "m/s"); !w.empty())
    return w;
  if (auto w = range_refusal("launch spin", l.spin.norm(), LaunchNumbers::kSpin, "rad/s"); !w.empty())
    return w + " (20000 rpm)";
  return {};
}

ShotTrajectory simulate_shot(const ShotModel& model, const LaunchState& launch, bool record_samples) {
  if (const std::string why = validate_launch(launch); !why.empty()) throw InputError(why);
  ShotState s = start_state(launch);
  TrajectoryRecorder rec(s, record_samples);
  while (!s.ended) {
    const ShotState before = s;
    const ShotEvent ev = step(model, s);
    rec.add(before, s, ev);
  }
  return rec.finish(s, model);
}

}  // namespace sweetspot
