// Shot state machine: Flight -> (Bounce -> Flight)* -> Roll -> Rest, or an early end
// (water, out of bounds, fence, home run, step limit). Sections:
//   1. the equations of motion   2. root finding on dense output
//   3. flight with contact search   4. bounce   5. roll   6. simulate_shot
#include "physics/flight.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "physics/error.hpp"
#include "physics/integrator.hpp"

namespace sweetspot {
namespace {

using State = Eigen::Matrix<double, 9, 1>;  // position, velocity, spin
using Segment = DenseSegment<9>;

/// Longest stretch of a step swept as one straight chord near the ground (s). At ~30 m/s
/// and ~15 m/s² the chord is within 5 mm of the arc; the landing time itself comes from
/// root finding on the dense output, not from the chord.
constexpr double kChordDuration = 0.05;
/// A surface within kFollowAngle of the one the ball rolls on is followed; a steeper one
/// (wall, bank) is struck.
const double kFollowCos = std::cos(kFollowAngle);
/// Leaving a wall slower than this, the ball drops dead at its foot: caught in the fence.
constexpr double kDeadAtWallSpeed = 1.0;  // m/s
/// Ball bottom more than this above the support plane: the ground fell away, fly.
constexpr double kLeaveGap = 0.01;  // m

// ---- 1. equations of motion ----------------------------------------------------------------
struct Dynamics {
  const AeroModel* aero;
  const Environment* env;
  double density;
  double radius;
  double inv_mass;
  double ground_height;

  State operator()(double /*t*/, const State& y) const {
    const Vec3 v = y.segment<3>(3);
    const Vec3 w = y.segment<3>(6);
    const Vec3 v_rel = v - wind_at(*env, y[1] - ground_height);
    const AeroEffect fx = aero_effect(*aero, density, radius, v_rel, w);
    State d;
    d.segment<3>(0) = v;
    d.segment<3>(3) = fx.force * inv_mass - kGravity * up_axis();
    d.segment<3>(6) = fx.spin_rate;
    return d;
  }
};

// ---- 2. root finding -------------------------------------------------------------------
/// Root of g on [a, b] with g(a) > 0 >= g(b): Illinois-modified regula falsi, which keeps
/// the bracket and converges superlinearly. Returns a time where |g| < 1e-12 or the bracket
/// is below 1e-13 s.
template <class G>
double find_root(const G& g, double a, double b, double ga, double gb) {
  int side = 0;
  for (int i = 0; i < 80; ++i) {
    double c = (a * gb - b * ga) / (gb - ga);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double gc = g(c);
    if (std::abs(gc) < 1e-12) return c;
    if (gc > 0.0) {
      a = c;
      ga = gc;
      if (side == 1) gb *= 0.5;
      side = 1;
    } else {
      b = c;
      gb = gc;
      if (side == -1) ga *= 0.5;
      side = -1;
    }
    if (b - a < 1e-13) break;
  }
  return b;
}

Vec3 position_at(const Segment& s, double t) {
  return Vec3(s.component(t, 0), s.component(t, 1), s.component(t, 2));
}

enum class Next { Fly, Roll, End };

class ShotRunner {
 public:
  ShotRunner(const FlightInput& in, const Terrain& terrain, FlightStats* stats)
      : in_(in),
        set_(in.settings),
        terrain_(&terrain),
        field_level_(default_fairway(), terrain.reference_height()),
        stats_(stats ? stats : &local_stats_),
        dyn_{in.aero, &in.environment, air_density(in.environment), in.ball.radius,
             1.0 / in.ball.mass, terrain.reference_height()},
        dp_(IntegratorTolerances{in.settings.rel_tol, in.settings.abs_tol, 1e-10, 1.0}) {
    y_.segment<3>(0) = in.launch.position;
    y_.segment<3>(3) = in.launch.velocity;
    y_.segment<3>(6) = in.launch.spin;
    max_y_ = in.launch.position.y();
  }

  ShotTrajectory run() {
    if (set_.record_samples) out_.samples.reserve(512);
    Next next = Next::Fly;
    while (next != Next::End) next = next == Next::Fly ? fly() : roll();
    return std::move(out_);
  }

 private:
  double radius() const { return in_.ball.radius; }
  Vec3 pos() const { return y_.segment<3>(0); }
  Vec3 vel() const { return y_.segment<3>(3); }
  Vec3 spin() const { return y_.segment<3>(6); }
  bool out_of_budget() const {
    return t_ >= set_.max_time || stats_->flight_steps + stats_->roll_steps >= set_.max_steps;
  }

  void sample(Phase phase) {
    if (!set_.record_samples) return;
    out_.samples.push_back({t_, pos(), vel(), spin(), phase});
  }

  void sample_segment(const Segment& s, double until, Phase phase) {
    if (!set_.record_samples) return;
    while (next_sample_ < until) {
      const State y = s.at(next_sample_);
      out_.samples.push_back({next_sample_, y.segment<3>(0), y.segment<3>(3), y.segment<3>(6), phase});
      next_sample_ += set_.sample_interval;
    }
  }

  Next finish(EndReason reason) {
    FlightSummary& s = out_.summary;
    const Vec3 launch = in_.launch.position;
    if (!landed_) {
      // Never touched ground (out of bounds in the air, step limit): carry is where it went.
      s.carry_m = std::hypot(pos().x() - launch.x(), pos().z() - launch.z());
      s.hang_time_s = t_;
      s.lateral_m = pos().z() - launch.z();
      s.landing_position = pos();
    }
    s.end = reason;
    s.rest_position = pos();
    s.total_m = std::hypot(pos().x() - launch.x(), pos().z() - launch.z());
    s.total_time_s = t_;
    s.apex_m = max_y_ - launch.y();
    if (set_.record_samples) {
      // The last sample is the end state (replacing a sample taken at the same instant).
      if (!out_.samples.empty() && out_.samples.back().t >= t_) out_.samples.pop_back();
      sample(reason == EndReason::Rest ? Phase::Rest : air_phase_);
    }
    return Next::End;
  }

  // ---- 3. flight ---------------------------------------------------------------------------
  struct Hit {
    double t = 0.0;
    SurfaceContact contact;
  };

  /// First contact of the ball with the terrain during the step `s`.
  bool find_contact(const Segment& s, const State& y1, Hit* hit) {
    const Vec3 p0 = s.r1.segment<3>(0);
    const Vec3 p1 = y1.segment<3>(0);
    // The arc strays from its chord by at most |Δv|·h/8 (exact for constant acceleration).
    const double sag = (y1.segment<3>(3) - s.r1.segment<3>(3)).norm() * s.h / 8.0 + 1e-3;
    if (!terrain_->may_touch(p0, p1, radius() + sag)) return false;
    const int chords = std::max(1, static_cast<int>(std::ceil(s.h / kChordDuration)));
    Vec3 pa = p0;
    for (int k = 0; k < chords; ++k) {
      const double ta = s.t0 + s.h * k / chords;
      const double tb = k + 1 == chords ? s.t1() : s.t0 + s.h * (k + 1) / chords;
      const Vec3 pb = k + 1 == chords ? p1 : position_at(s, tb);
      SurfaceContact c;
      // A sub-chord of 1/n of the step strays 1/n² as far.
      const double chord_sag = (sag - 1e-3) / (chords * chords) + 1e-3;
      if (!terrain_->may_touch(pa, pb, radius() + chord_sag)) {
        pa = pb;
        continue;
      }
      ++stats_->sweeps;
      if (terrain_->sweep(pa, pb, radius(), &c, nullptr)) {
        const double t_chord = ta + c.fraction * (tb - ta);
        const auto gap = [&](double t) { return c.normal.dot(position_at(s, t) - c.point) - radius(); };
        const double ga = gap(ta), gb = gap(tb);
        double th = t_chord;
        if (ga > 0.0 && gb <= 0.0) {
          const double tr = find_root(gap, ta, tb, ga, gb);
          // The plane is met no later than the triangle; a root far earlier means the ball
          // grazed the triangle's edge instead of its face: keep the swept time then.
          if ((t_chord - tr) * (pb - pa).norm() / (tb - ta) < 0.01) th = tr;
        }
        hit->t = th;
        hit->contact = c;
        return true;
      }
      pa = pb;
    }
    return false;
  }

  Next fly() {
    dp_.restart(t_ == 0.0 ? 0.01 : hop_step());
    sample(air_phase_);
    next_sample_ = t_ + set_.sample_interval;
    for (;;) {
      if (out_of_budget()) return finish(EndReason::StepLimit);
      Segment s;
      double t1 = t_;
      State y1 = y_;
      stats_->rejected_steps += dp_.step(dyn_, t1, y1, set_.max_time, s);
      ++stats_->flight_steps;
      // Apex: vertical velocity crossing zero inside the step.
      if (s.r1[4] > 0.0 && y1[4] <= 0.0) {
        const double ta = find_root([&](double t) { return s.component(t, 4); }, s.t0, s.t1(), s.r1[4], y1[4]);
        max_y_ = std::max(max_y_, s.component(ta, 1));
      }
      Hit hit;
      if (find_contact(s, y1, &hit)) {
        sample_segment(s, hit.t, air_phase_);
        t_ = hit.t;
        y_ = s.at(hit.t);
        max_y_ = std::max(max_y_, y_[1]);
        const Next n = impact(hit.contact);
        if (n != Next::Fly) return n;
        dp_.restart(hop_step());
        continue;
      }
      sample_segment(s, t1, air_phase_);
      const Vec3 p0 = pos();
      t_ = t1;
      y_ = y1;
      max_y_ = std::max(max_y_, y_[1]);
      if (ghost_end_ == EndReason::Rest && terrain_->over_fence(p0, pos())) {
        // Cleared the fence: fly on to field level for the batted-ball distance, then end.
        ghost_end_ = EndReason::HomeRun;
        terrain_ = &field_level_;
      }
      if (!terrain_->inside(pos())) return finish(EndReason::OutOfBounds);
    }
  }

  // ---- 4. bounce -------------------------------------------------------------------------
  /// First trial step after a bounce: a tenth of the hop's vacuum flight time.
  double hop_step() const {
    const double hop = 2.0 * std::max(vel().y(), 0.0) / kGravity;
    return std::clamp(0.1 * hop, 1e-3, 0.05);
  }

  Next impact(const SurfaceContact& c) {
    const SurfaceMaterial& m = terrain_->material(c.material);
    if (!landed_) {
      landed_ = true;
      dp_.set_tolerances(IntegratorTolerances{std::max(set_.rel_tol, set_.bounce_rel_tol), set_.abs_tol, 1e-10, 1.0});
      FlightSummary& s = out_.summary;
      const Vec3 l = in_.launch.position;
      s.carry_m = std::hypot(pos().x() - l.x(), pos().z() - l.z());
      s.hang_time_s = t_;
      s.lateral_m = pos().z() - l.z();
      s.landing_position = pos();
      s.landing_angle_deg = rad_to_deg(std::atan2(-vel().y(), std::hypot(vel().x(), vel().z())));
    }
    if (ghost_end_ != EndReason::Rest) return finish(ghost_end_);
    if (m.kind == SurfaceKind::Water) return finish(EndReason::Water);
    if (m.kind == SurfaceKind::OutOfBounds) return finish(EndReason::OutOfBounds);
    const BounceResult b = bounce_on_surface(m, c.normal, vel(), spin(), in_.ball);
    ++out_.summary.bounces;
    Vec3 v = b.velocity;
    const double vn = v.dot(c.normal);
    if (vn < 0.0) v -= vn * c.normal;  // the crater tilt never sends the ball into the ground
    y_.segment<3>(3) = v;
    y_.segment<3>(6) = b.spin;
    air_phase_ = Phase::Bounce;
    sample(Phase::Bounce);
    if (m.kind == SurfaceKind::Wall && v.norm() < kDeadAtWallSpeed) return finish(EndReason::Fence);
    const bool walkable = c.normal.dot(up_axis()) > kFollowCos * 0.5;  // < ~63° slope
    if (walkable && std::max(vn, 0.0) < set_.roll_speed) {
      support_ = c;
      return Next::Roll;
    }
    return Next::Fly;
  }

  // ---- 5. roll ---------------------------------------------------------------------------
  Next roll() {
    const double r = radius();
    SurfaceContact c = support_;
    Vec3 n = c.normal;
    Vec3 p = pos();
    Vec3 v = vel();
    Vec3 w = spin();
    p -= (n.dot(p - c.point) - r) * n;
    v -= v.dot(n) * n;
    const SurfaceMaterial* m = &terrain_->material(c.material);
    // Skid until the contact point grips: friction µ g cosθ acts against the slip, which
    // changes at (1 + m R²/I) µ g cosθ = 3.5 µ g cosθ for a solid sphere. The slope is
    // ignored for this short stretch.
    const Vec3 slip = v + w.cross(-r * n);
    const double slip_speed = slip.norm();
    const double cos_slope = std::max(n.dot(up_axis()), 0.1);
    if (slip_speed > 1e-6 && m->mu > 0.0) {
      const double k = 1.0 + in_.ball.mass * r * r / in_.ball.inertia;
      const double decel = m->mu * kGravity * cos_slope;
      const double tg = slip_speed / (k * decel);
      const Vec3 a = -decel * (slip / slip_speed);
      p += v * tg + 0.5 * a * tg * tg;
      v += a * tg;
      t_ += tg;
    }
    w = w.dot(n) * n + n.cross(v) / r;
    y_.segment<3>(0) = p;
    y_.segment<3>(3) = v;
    y_.segment<3>(6) = w;
    sample(Phase::Roll);

    for (;;) {
      if (out_of_budget()) return finish(EndReason::StepLimit);
      ++stats_->roll_steps;
      const double cos_t = n.dot(up_axis());
      const Vec3 slope_acc = (5.0 / 7.0) * -kGravity * (up_axis() - cos_t * n);  // rolling sphere
      const double resist = effective_rolling_resistance(*m) * kGravity * cos_t;
      const double speed = v.norm();
      const bool holds = slope_acc.norm() <= resist;  // static: the slope cannot start it
      if (speed == 0.0 && holds) {
        y_.segment<3>(6) = Vec3::Zero();
        return finish(EndReason::Rest);
      }
      const Vec3 dir = speed > 0.0 ? Vec3(v / speed) : Vec3(slope_acc.normalized());
      // Air drag matters on a fast roll (a ball skidding out at 80 m/s loses more to the air
      // than to the turf); its part along the surface acts through the centre, so a rolling
      // sphere feels 5/7 of it. Lift on the topspin only presses into the ground.
      Vec3 drag_acc = Vec3::Zero();
      if (speed > 0.0) {
        const Vec3 v_rel = v - wind_at(*dyn_.env, r);
        const Vec3 f = aero_effect(*dyn_.aero, dyn_.density, r, v_rel, n.cross(v) / r).force;
        drag_acc = (5.0 / 7.0) * dyn_.inv_mass * (f - f.dot(n) * n);
      }
      const Vec3 a = slope_acc + drag_acc - resist * dir;
      const double dt = std::min(std::clamp(0.25 / std::max(speed, 1e-3), 1.0 / 240.0, 0.1), set_.max_time - t_);
      Vec3 v1 = v + a * dt;
      Vec3 p1 = p + 0.5 * (v + v1) * dt;
      double step_t = dt;
      bool stops = false;
      const double along = -a.dot(dir);  // deceleration along the motion
      if (holds && speed > 0.0 && along > 0.0 && (v1.dot(v) <= 0.0 || speed < set_.rest_speed)) {
        // Comes to rest inside the step: advance exactly to the stop.
        step_t = speed / along;
        p1 = p + v * step_t + 0.5 * a * step_t * step_t;
        v1 = Vec3::Zero();
        stops = true;
      }
      // Walls and banks in the way.
      SurfaceContact hit;
      if (terrain_->may_touch_steep(p, p1, r) && (++stats_->sweeps, terrain_->sweep(p, p1, r, &hit, &n))) {
        const double f = hit.fraction;
        t_ += f * step_t;
        y_.segment<3>(0) = p + f * (p1 - p);
        y_.segment<3>(3) = v + f * (v1 - v);
        y_.segment<3>(6) = n.cross(Vec3(y_.segment<3>(3))) / r;
        air_phase_ = Phase::Bounce;
        const Next nx = impact(hit);
        return nx == Next::End ? nx : Next::Fly;
      }
      // Follow the ground under the new position.
      SurfaceContact under = c;  // the current support is the cache hint
      if (!terrain_->support(p1, r, kLeaveGap + 0.1 * speed * step_t, &under)) {
        t_ += step_t;
        y_.segment<3>(0) = p1;
        y_.segment<3>(3) = v1;
        air_phase_ = Phase::Bounce;
        return Next::Fly;  // rolled off the edge of the world's ground
      }
      const double gap = under.normal.dot(p1 - under.point) - r;
      if (gap > kLeaveGap || under.normal.dot(n) < kFollowCos) {
        // The ground fell away (or turned sharply): the ball leaves it and flies.
        t_ += step_t;
        y_.segment<3>(0) = p1;
        y_.segment<3>(3) = v1;
        air_phase_ = Phase::Bounce;
        return Next::Fly;
      }
      p1 -= gap * under.normal;
      if (under.normal != n) {
        // Onto a differently sloped facet: turn the velocity into its plane, keeping speed.
        const double s1 = v1.norm();
        v1 -= v1.dot(under.normal) * under.normal;
        const double s2 = v1.norm();
        if (s2 > 0.0) v1 *= s1 / s2;
        n = under.normal;
      }
      c = under;
      m = &terrain_->material(c.material);
      t_ += step_t;
      p = p1;
      v = v1;
      y_.segment<3>(0) = p;
      y_.segment<3>(3) = v;
      y_.segment<3>(6) = n.cross(v) / r;
      sample(stops ? Phase::Rest : Phase::Roll);
      if (m->kind == SurfaceKind::Water) return finish(EndReason::Water);
      if (m->kind == SurfaceKind::OutOfBounds || !terrain_->inside(p)) return finish(EndReason::OutOfBounds);
      if (stops) {
        y_.segment<3>(6) = Vec3::Zero();
        return finish(EndReason::Rest);
      }
    }
  }

  const FlightInput& in_;
  const FlightSettings& set_;
  const Terrain* terrain_;        // the world, or field_level_ once a ball has cleared the fence
  FlatGround field_level_;        // y = the world's reference height, for the home-run distance
  EndReason ghost_end_ = EndReason::Rest;  // HomeRun once over the fence
  FlightStats local_stats_;
  FlightStats* stats_;
  Dynamics dyn_;
  DormandPrince45<9> dp_;
  ShotTrajectory out_;
  State y_;
  double t_ = 0.0;
  double next_sample_ = 0.0;
  double max_y_ = 0.0;
  bool landed_ = false;
  Phase air_phase_ = Phase::Flight;
  SurfaceContact support_;
};

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

}  // namespace

std::string validate_flight_input(const FlightInput& in) {
  std::ostringstream s;
  if (!finite(in.launch.position) || !finite(in.launch.velocity) || !finite(in.launch.spin))
    return "launch: position, velocity and spin must be finite numbers";
  if (!(in.launch.velocity.norm() <= 150.0))
    return "launch: ball speed " + std::to_string(in.launch.velocity.norm()) + " m/s out of range (allowed 0..150 m/s)";
  if (!(in.launch.spin.norm() <= 1500.0))
    return "launch: spin " + std::to_string(in.launch.spin.norm()) + " rad/s out of range (allowed 0..1500 rad/s, ~14300 rpm)";
  if (!(in.ball.mass > 0.0 && in.ball.mass <= 1.0)) return "ball.mass out of range (allowed 0..1 kg)";
  if (!(in.ball.radius > 0.0 && in.ball.radius <= 0.2)) return "ball.radius out of range (allowed 0..0.2 m)";
  if (!(in.ball.inertia > 0.0 && in.ball.inertia <= in.ball.mass * in.ball.radius * in.ball.radius))
    return "ball.inertia out of range (allowed 0..mass·radius²)";
  if (in.aero == nullptr) return "flight: no aero model given (allowed: " + std::string("ferguson2022, smits_smith1994, nathan") + ")";
  const std::string env = validate_environment(in.environment);
  if (!env.empty()) return env;
  const FlightSettings& f = in.settings;
  if (!(f.rel_tol >= 1e-14 && f.rel_tol <= 1e-2)) return "flight.rel_tol out of range (allowed 1e-14..1e-2)";
  if (!(f.abs_tol >= 1e-15 && f.abs_tol <= 1e-2)) return "flight.abs_tol out of range (allowed 1e-15..1e-2)";
  if (!(f.bounce_rel_tol >= 1e-14 && f.bounce_rel_tol <= 1e-2)) return "flight.bounce_rel_tol out of range (allowed 1e-14..1e-2)";
  if (!(f.max_time > 0.0 && f.max_time <= 600.0)) return "flight.max_time out of range (allowed 0..600 s)";
  if (!(f.max_steps > 0)) return "flight.max_steps must be positive";
  if (!(f.sample_interval >= 1e-4 && f.sample_interval <= 1.0)) return "flight.sample_interval out of range (allowed 1e-4..1 s)";
  if (!(f.roll_speed >= 0.0 && f.roll_speed <= 5.0)) return "flight.roll_speed out of range (allowed 0..5 m/s)";
  if (!(f.rest_speed > 0.0 && f.rest_speed <= 1.0)) return "flight.rest_speed out of range (allowed 0..1 m/s)";
  return {};
}

ShotTrajectory simulate_shot(const FlightInput& in, const Terrain* terrain, FlightStats* stats) {
  const std::string why = validate_flight_input(in);
  if (!why.empty()) throw InputError(why);
  if (stats) *stats = FlightStats{};
  if (terrain == nullptr) {
    static const FlatGround flat;  // immutable, so shared safely between threads
    ShotRunner runner(in, flat, stats);
    return runner.run();
  }
  ShotRunner runner(in, *terrain, stats);
  return runner.run();
}

}  // namespace sweetspot
