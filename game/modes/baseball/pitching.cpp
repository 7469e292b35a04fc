#include "game/modes/baseball/pitching.hpp"

#include <cmath>
#include <string>

#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {

std::vector<PitchType> load_pitch_types(const Assets& assets) {
  const TomlFile f = TomlFile::read(assets.root() / "pitches.toml", "pitch types");
  f.only_keys(f.root(), "", {"pitch"});
  std::vector<PitchType> out;
  static constexpr Range kFraction{0.0, 1.0};
  static constexpr Range kDirection{-kPi, kPi};
  static constexpr Range kHeight{0.5, 3.0};
  static constexpr Range kSide{-1.5, 1.5};
  static constexpr Range kExtension{0.5, 3.0};
  const toml::table* last = nullptr;
  for (const toml::table* t : f.tables(f.root(), "pitch", true)) {
    f.only_keys(*t, "pitch", {"type", "speed", "spin", "active_spin", "movement_direction", "seam_wake_deviation",
                              "release_height", "release_side", "extension", "usage", "zone_share"});
    PitchType p;
    p.type = f.text(f.required(*t, "type", "the pitch's name"), "type");
    p.speed = f.quantity(f.required(*t, "speed", "out-of-hand speed"), "speed", Dimension::Speed, &PitchType::kSpeed);
    p.spin = f.quantity(f.required(*t, "spin", "total spin"), "spin", Dimension::AngularVelocity, &PitchType::kSpin);
    p.active_spin = f.quantity(f.required(*t, "active_spin", "transverse share"), "active_spin", Dimension::Fraction, &kFraction);
    p.movement_direction = f.quantity(f.required(*t, "movement_direction", "deg from up"), "movement_direction",
                                      Dimension::Angle, &kDirection);
    p.seam_wake_deviation = f.quantity(f.required(*t, "seam_wake_deviation", "deg, + counter-clockwise from the catcher"),
                                       "seam_wake_deviation", Dimension::Angle, &PitchType::kSeamWakeDeviation);
    p.release_height = f.quantity(f.required(*t, "release_height", "m"), "release_height", Dimension::Length, &kHeight);
    p.release_side = f.quantity(f.required(*t, "release_side", "m"), "release_side", Dimension::Length, &kSide);
    p.extension = f.quantity(f.required(*t, "extension", "m"), "extension", Dimension::Length, &kExtension);
    p.usage = f.quantity(f.required(*t, "usage", "share of pitches"), "usage", Dimension::Fraction, &kFraction);
    static constexpr Range kZoneShare{0.05, 0.95};
    p.zone_share = f.quantity(f.required(*t, "zone_share", "share in the zone"), "zone_share", Dimension::Fraction, &kZoneShare);
    for (const PitchType& o : out)
      if (o.type == p.type) f.fail(*t->get("type"), "type", "'" + p.type + "' is defined twice");
    out.push_back(p);
    last = t;
  }
  // The pitcher draws each pitch by these shares: with none above zero there is nothing to
  // draw from (and a draw over zeros would throw only the last type).
  double total_usage = 0.0;
  for (const PitchType& p : out) total_usage += p.usage;
  if (last != nullptr && total_usage <= 0.0)
    f.fail(*last->get("usage"), "usage",
           "every pitch type's usage is 0 %: at least one must be thrown (allowed: shares in [0, 100] % summing "
           "above 0)");
  return out;
}

const PitchType& pitch_type(const std::vector<PitchType>& types, std::string_view name) {
  std::string names;
  for (const PitchType& p : types) {
    if (p.type == name) return p;
    names += (names.empty() ? "" : ", ") + p.type;
  }
  throw InputError("unknown pitch type '" + std::string(name) + "' (allowed: " + names + ")");
}

namespace {

struct Crossing {
  double t = 0.0;
  Vec3 p = Vec3::Zero(), v = Vec3::Zero(), w = Vec3::Zero();
  ShotTrajectory trajectory;
};

// Flies a ball from `release` at `velocity` with `spin` until it crosses the plane x = `plane`
// (the plate's back point: 0).
Crossing fly_to(const ShotModel& model, const Vec3& release, const Vec3& velocity, const Vec3& spin, bool record,
                double plane = 0.0) {
  LaunchState l;
  l.position = release;
  l.velocity = velocity;
  l.spin = spin;
  ShotState s = start_state(l);
  TrajectoryRecorder rec(s, record, 1.0 / 240.0);
  Crossing c;
  for (int i = 0; i < 2000 && !s.ended; ++i) {
    const ShotState before = s;
    const ShotEvent ev = step(model, s, s.t + 0.002);
    rec.add(before, s, ev);
    if (s.position().x() <= plane) {
      // Between the two states: the crossing by Hermite interpolation (bisection on x).
      double lo = before.t, hi = s.t;
      for (int k = 0; k < 50; ++k) {
        const double mid = 0.5 * (lo + hi);
        const Vec3 p = flight_position_between(before.position(), before.velocity(), before.t, s.position(), s.velocity(),
                                               s.t, mid);
        (p.x() > plane ? lo : hi) = mid;
      }
      c.t = 0.5 * (lo + hi);
      c.p = flight_position_between(before.position(), before.velocity(), before.t, s.position(), s.velocity(), s.t, c.t);
      const double f = (c.t - before.t) / std::max(s.t - before.t, 1e-12);
      c.v = before.velocity() + f * (s.velocity() - before.velocity());
      c.w = before.spin() + f * (s.spin() - before.spin());
      c.trajectory = rec.finish(s);
      return c;
    }
  }
  throw InputError("the pitch never reached the plate (it landed short): check its speed and target");
}

// The baseball in the default air over ground far below the plate: a pitch is read where it
// crosses the plate, in the air, so a pitch in the dirt or a trial aim that falls short still
// reaches the plane.
ShotModel pitch_model(const Assets& assets) {
  static const FlatGround ground(default_fairway(), -50.0);
  const BallSpec& ball = assets.equipment().ball("mlb");
  return make_shot_model(BallProperties{ball.mass, ball.radius, ball.inertia},
                         assets.aero(assets.sport("baseball").default_aero), Environment{}, &ground);
}

// The seam-shifted wake's side-force coefficient that turns the pitch's Magnus force by its
// type's measured deviation at release: across the Magnus force, C_s = C_L·tan δ, with C_L
// the lift the transverse spin gives there (the aero law's C_L(R|ω|/v) times the transverse
// share, as physics/aero.hpp reads it). Signed for ShotModel's v̂ × m̂: that side is the arm
// side of a right-hander's pitch; a left-hander's mirrors it.
double seam_side_force(const ShotModel& model, const PitchType& t, double hand) {
  const double s = model.ball.radius * t.spin / t.speed;
  const double re = model.air_density * t.speed * 2.0 * model.ball.radius / model.air_viscosity;
  const double cl = model.aero->coefficients(s, t.spin, re).cl * t.active_spin;
  return hand * cl * std::tan(t.seam_wake_deviation);
}

}  // namespace

PitchFlight throw_pitch(const Assets& assets, const PitchCall& call) {
  const PitchType& t = call.type;
  check_range("pitch.speed", t.speed, PitchType::kSpeed, "m/s");
  check_range("pitch.spin", t.spin, PitchType::kSpin, "rad/s");
  check_range("pitch.seam_wake_deviation", t.seam_wake_deviation, PitchType::kSeamWakeDeviation, "rad");
  ShotModel model = pitch_model(assets);
  const double hand = call.left_handed ? -1.0 : 1.0;
  const double c_s = seam_side_force(model, t, hand);
  if (!ShotModel::kSeamSideForce.contains(c_s))
    throw InputError("pitch '" + t.type + "': its seam_wake_deviation, with the aero model's lift at its speed and spin, " +
                     "gives a seam-wake coefficient " + std::to_string(c_s) + " (allowed " +
                     range_text(ShotModel::kSeamSideForce, "") + ": a baseball's C_L turned by at most 45 deg)");
  set_seam_side_force(model, c_s);
  PitchFlight out;
  out.seam_side_force = model.seam_side_force;
  out.release = Vec3(kRubberToPlate - t.extension, t.release_height, hand * t.release_side);
  // The spin: its transverse part pushes the ball toward the spin-based direction, the
  // movement's turned back by the seam wake's deviation (seen from the catcher: from up,
  // + toward first base), for a ball travelling toward −x; the rest is gyro spin along the
  // flight, which makes no Magnus force. The wake's side force turns the movement on to its
  // measured direction. A left-hander's pitch is the mirror image (z -> -z) of a
  // right-hander's: spin is an axial vector, so its x and y parts change sign, the gyro part
  // too (a falling pitch's flow is not quite along x, and the gyro part then turns the
  // Magnus force: left unmirrored it would run a left-hander's sinker 0.5 in farther and
  // 1.0 in lower than the mirror image of a right-hander's).
  const double dir = hand * (t.movement_direction + t.seam_wake_deviation);
  const double wt = t.spin * t.active_spin;
  const double wg = t.spin * std::sqrt(std::max(0.0, 1.0 - t.active_spin * t.active_spin));
  out.spin = Vec3(-hand * wg, wt * std::sin(dir), -wt * std::cos(dir));
  const Vec3 target(0.0, call.target_height, call.target_side);
  // Aim: the release direction that crosses the plate at the target, by a few corrections
  // of the straight line (gravity, drag and break bend it).
  Vec3 aim = target;
  Crossing c;
  for (int i = 0; i < 8; ++i) {
    const Vec3 v = t.speed * (aim - out.release).normalized();
    c = fly_to(model, out.release, v, out.spin, false);
    const Vec3 miss = c.p - target;
    if (std::abs(miss.y()) < 1e-5 && std::abs(miss.z()) < 1e-5) break;
    aim -= Vec3(0.0, miss.y(), miss.z());  // the aim point moves by the miss: a near-unit Jacobian
  }
  out.release_velocity = t.speed * (aim - out.release).normalized();
  c = fly_to(model, out.release, out.release_velocity, out.spin, true);
  out.flight_time = c.t;
  out.plate = c.p;
  out.plate_velocity = c.v;
  out.plate_spin = c.w;
  out.trajectory = std::move(c.trajectory);
  // The whole flight's break: against the same release without spin.
  const Crossing still = fly_to(model, out.release, out.release_velocity, Vec3::Zero(), false);
  out.flight_break_vertical = c.p.y() - still.p.y();
  out.flight_break_horizontal = c.p.z() - still.p.z();
  return out;
}

PitchMovement statcast_movement(const Assets& assets, const PitchFlight& pitch) {
  ShotModel model = pitch_model(assets);
  model.seam_side_force = pitch.seam_side_force;
  const Crossing at_start = fly_to(model, pitch.release, pitch.release_velocity, pitch.spin, false, kMovementStart);
  const Crossing front = fly_to(model, at_start.p, at_start.v, at_start.w, false, kPlateFront);
  AeroModel liftless = *model.aero;
  liftless.lift = LiftLaw::Quadratic;
  liftless.l0 = liftless.l1 = liftless.l2 = 0.0;
  ShotModel no_lift = model;
  no_lift.aero = &liftless;
  no_lift.seam_side_force = 0.0;  // Statcast's movement is all that is not gravity and drag
  const Crossing plain = fly_to(no_lift, at_start.p, at_start.v, at_start.w, false, kPlateFront);
  PitchMovement out{front.p.y() - plain.p.y(), front.p.z() - plain.p.z()};
  if (model.seam_side_force != 0.0) {
    ShotModel magnus_only = model;
    magnus_only.seam_side_force = 0.0;
    const Crossing spun = fly_to(magnus_only, at_start.p, at_start.v, at_start.w, false, kPlateFront);
    out.seam_wake_vertical = front.p.y() - spun.p.y();
    out.seam_wake_horizontal = front.p.z() - spun.p.z();
  }
  return out;
}

}  // namespace sweetspot
