// The airborne step: one Dormand–Prince step, a search for the first contact along it, and
// the landing instant by root finding on the step's dense output.
#include <algorithm>
#include <cmath>
#include <string>

#include "physics/detail/flight_steps.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot::detail {
namespace {

/// Longest stretch of a step swept as one straight chord near the ground (s). At ~30 m/s
/// and ~15 m/s² the chord is within 5 mm of the arc; the landing time itself comes from
/// root finding on the dense output, not from the chord.
constexpr double kChordDuration = 0.05;

Vec3 velocity_at(const Segment& s, double t) {
  return Vec3(s.component(t, 3), s.component(t, 4), s.component(t, 5));
}

struct Hit {
  double t = 0.0;
  SurfaceContact contact;
};

/// The gap between the ball and the plane of a face (normal n through point q) along the
/// step's dense output: the position projected on the normal is one scalar polynomial in θ,
/// so a root-finding evaluation is a few flops and one division instead of three
/// components' worth. Returns the gap (m) and its rate (m/s) at time t.
struct PlaneGap {
  const Segment* s;
  double g1, g2, g3, g4, g5;
  PlaneGap(const Segment& seg, const Vec3& n, const Vec3& q, double radius)
      : s(&seg),
        g1(n.dot(seg.r1.segment<3>(0) - q) - radius),
        g2(n.dot(seg.r2.segment<3>(0))),
        g3(n.dot(seg.r3.segment<3>(0))),
        g4(n.dot(seg.r4.segment<3>(0))),
        g5(n.dot(seg.r5.segment<3>(0))) {}
  std::pair<double, double> operator()(double t) const {
    const double th = (t - s->t0) / s->h;
    const double th1 = 1.0 - th;
    const double a = g4 + th1 * g5, b = g3 + th * a, c2 = g2 + th1 * b;
    const double da = -g5, db = a + th * da, dc = -b + th1 * db;  // d/dθ
    return {g1 + th * c2, (c2 + th * dc) / s->h};
  }
  double gap(double t) const { return (*this)(t).first; }
};

/// The arc past a chord's touch, up to where the arc meets the touched face's plane (t_touch
/// to *t_hit), swept too: a face met there is met first. A ball skimming up a slope nearly
/// along it leaves the chord's straight gap to cross zero near its start while the arc comes
/// back to the plane only near its end, metres on; unswept, the ground past the chord's
/// touch lets a steeper face rising there (a concave bend in the slope) be passed through
/// (in the random-world soak, the centre 3.6 cm under the ground). Stretches under half a
/// radius (1 cm) are left: a face unseen along one can hold the ball at most that deep, and
/// most landings end there (a landing steeper than 30° meets the plane at most the chord's
/// sag, ≤ 5 mm, over the incidence's sine past the chord's touch). From a quarter radius on,
/// the extra sweeps cost 2.6 % of a golf shot's instructions; from half, 1 %.
void sweep_past_touch(const ShotModel& m, ShotState& st, const Segment& s, double t_touch, double* t_hit,
                      SurfaceContact* c) {
  const double radius = m.ball.radius;
  for (int pass = 0; pass < 4; ++pass) {
    const Vec3 a = position_at(s, t_touch), b = position_at(s, *t_hit);
    if (!((b - a).norm() > 0.5 * radius)) return;
    SurfaceContact c2;
    ++st.counters.sweeps;
    if (!m.terrain->sweep(a, b, radius, &c2, nullptr)) return;
    if (c2.mesh == c->mesh && c2.triangle == c->triangle) return;  // the face already touched
    const double t2 = t_touch + c2.fraction * (*t_hit - t_touch);
    const PlaneGap gap(s, c2.normal, c2.point, radius);
    double th = t2;  // the swept time, unless the arc meets the new face's plane inside
    if (gap.gap(t_touch) > 0.0 && gap.gap(*t_hit) <= 0.0) th = find_root_newton(gap, t_touch, *t_hit, t2);
    *c = c2;
    t_touch = std::min(t2, th);
    *t_hit = th;
  }
}

/// First contact of the ball with the terrain during the step `s` (ending at `y1`).
bool find_contact(const ShotModel& m, ShotState& st, const Segment& s, const State9& y1, Hit* hit) {
  const Terrain& terrain = *m.terrain;
  const double radius = m.ball.radius;
  const Vec3 p0 = s.r1.segment<3>(0);
  const Vec3 p1 = y1.segment<3>(0);
  // The arc strays from its chord by at most |Δv|·h/8 (exact for constant acceleration).
  const double sag = (y1.segment<3>(3) - s.r1.segment<3>(3)).norm() * s.h / 8.0 + 1e-3;
  // The highest surface under the whole step (its box grown by the sag): a chord that
  // passes above it cannot touch anything, so most chords of a hop need no query.
  const double top = terrain.top_under(p0, p1, radius + sag);
  if (std::min(p0.y(), p1.y()) - (radius + sag) > top) return false;
  const int chords = std::max(1, static_cast<int>(std::ceil(s.h / kChordDuration)));
  Vec3 pa = p0;
  for (int k = 0; k < chords; ++k) {
    const double ta = s.t0 + s.h * k / chords;
    const double tb = k + 1 == chords ? s.t1() : s.t0 + s.h * (k + 1) / chords;
    const Vec3 pb = k + 1 == chords ? p1 : position_at_fraction(s, static_cast<double>(k + 1) / chords);
    SurfaceContact c;
    // A sub-chord of 1/n of the step strays 1/n² as far.
    const double chord_sag = (sag - 1e-3) / (chords * chords) + 1e-3;
    if (std::min(pa.y(), pb.y()) - (radius + chord_sag) > top || !terrain.may_touch(pa, pb, radius + chord_sag)) {
      pa = pb;
      continue;
    }
    // The sweep of this chord from `from` (time t_from) to pb; on a hit, the touch time on
    // the dense output. A ball that starts the chord on a surface and leaves it (launched
    // off the ground, just bounced) but comes back to that surface's plane within the chord
    // is swept again from the first moment it is clear of the plane: what it meets is then
    // the first face on its way, not that plane where it returns (else a launch at 0.6°
    // toward a step in the ground, its first step 0.25 s, crosses the step's riser and
    // "lands" on the plane of the floor under it, inside the ground).
    bool retried = false;
    Vec3 from = pa;
    double t_from = ta;
    for (;;) {
      ++st.counters.sweeps;
      if (!terrain.sweep(from, pb, radius, &c, nullptr)) break;
      const double t_chord = t_from + c.fraction * (tb - t_from);
      // The gap to the face's plane along the step.
      const PlaneGap plane(s, c.normal, c.point, radius);
      double ga = plane.gap(t_from);
      const double gb = plane.gap(tb);
      double t_lo = t_from;
      if (!(ga > 0.0) && gb <= 0.0 && c.normal.dot(velocity_at(s, t_from)) > 0.0) {
        // The step starts on the surface with the ball leaving it (just bounced) and ends
        // back on it: a hop shorter than the step (a heavy-topspin ball pressed down by
        // Magnus). The touch is where it comes back, not where it left: find the first
        // moment it is clear of the plane, then the root after it.
        for (const double f : {1.0 / 1024, 1.0 / 256, 1.0 / 64, 1.0 / 16, 1.0 / 4, 1.0 / 2, 3.0 / 4}) {
          const double t = t_from + f * (tb - t_from);
          if (plane.gap(t) > 0.0) {
            t_lo = t;
            ga = plane.gap(t);
            break;
          }
        }
        if (t_lo > t_from && !retried) {
          retried = true;
          from = position_at_fraction(s, (t_lo - s.t0) / s.h);
          t_from = t_lo;
          continue;
        }
      }
      double th = t_chord;
      if (ga > 0.0 && gb <= 0.0) {
        const double tr = find_root_newton(plane, t_lo, tb, t_chord);
        // The plane is met no later than the triangle; a root far earlier means the ball
        // grazed the triangle's edge instead of its face: keep the swept time then.
        if (t_lo > t_from || (t_chord - tr) * (pb - from).norm() / (tb - t_from) < 0.01) th = tr;
      }
      if (th > t_chord) {
        // The arc meets the touched face's plane past where the chord met the face: near an
        // edge the ball is over the neighbouring face of the surface by then, and where that
        // face falls away (a slope steepening down) the ball has not reached it yet. It
        // touches that face where the arc meets its plane (read on the first face's plane,
        // a hop onto a bunker's steepening face landed 2 ms early and rested 1 cm off).
        SurfaceContact next = c;
        terrain.refine_contact(position_at(s, th), &next);
        if (next.mesh != c.mesh || next.triangle != c.triangle) {
          const PlaneGap next_plane(s, next.normal, next.point, radius);
          if (next_plane.gap(th) > 0.0 && next_plane.gap(tb) <= 0.0) {
            th = find_root_newton(next_plane, th, tb, th);
            c = next;
          }
        }
        sweep_past_touch(m, st, s, t_chord, &th, &c);
      }
      hit->t = th;
      hit->contact = c;
      return true;
    }
    pa = pb;
  }
  return false;
}

bool finite(const State9& y) { return y.allFinite(); }

/// A short hop after a bounce, in closed form where the physics allows it (as the bounce and
/// the roll are). A ball that leaves the ground at under kShortHopSpeed along the vertical (a
/// hop under 5 cm high and 0.2 s long: half of a tour drive's hops) moves through air that
/// barely changes over the hop: drag and lift change by a few per cent of themselves, a
/// fraction of a per cent of gravity. The equations' rates are taken at the hop's start and
/// middle and let change linearly between (third order in the hop's length), which makes
/// position a cubic in time; the segment `seg` holds that exactly as a dense output (r5 = 0),
/// so the contact search, the apex and the world's bounds read it as they read a DOPRI step.
/// The segment runs 1.25 hops (a hop off an edge goes on as a flight from its end). Two
/// evaluations of the equations instead of seven. False (nothing changed) when the hop is
/// not short.
bool short_hop(const ShotState& s, const Dynamics& f, double t_end, Segment* seg) {
  constexpr double kShortHopSpeed = 1.0;  // m/s up: a 5.1 cm, 0.20 s vacuum hop
  const double up_speed = s.y[4];
  if (!s.landed || s.rate_valid || s.phase != Phase::Bounce || !(up_speed > 0.0) || up_speed > kShortHopSpeed)
    return false;
  const double hop = 2.0 * up_speed / kGravity;  // vacuum flight time back to the height it left
  // A hop shorter than kNoProgress (up at under 0.5 µm/s: a ball at its apex) would not move
  // the clock, over and over; the integrator's step takes it on instead.
  if (!(hop > kNoProgress)) return false;
  const double h = std::min(1.25 * hop, t_end - s.t);
  if (!(h > 0.0)) return false;
  const State9 f0 = f(s.t, s.y);
  const double half = 0.5 * std::min(hop, h);
  const State9 fm = f(s.t + half, State9(s.y + half * f0));
  // The rates change linearly over the hop, at the slope from its start to its middle:
  // velocity and spin then follow a parabola in time and position a cubic (the rate of the
  // position is the velocity). Held constant at the middle's instead (the midpoint rule),
  // they would miss the drag's vertical part, which turns from down to up at the apex: 0.5 mm
  // of height over a 0.2 s hop, 0.6 ms of touch time, 5 mm along.
  const State9 slope = (fm - f0) / half;
  const Vec3 v0 = s.y.segment<3>(3), a0 = f0.segment<3>(3), j = slope.segment<3>(3);
  const Vec3 w_rate0 = f0.segment<3>(6), w_slope = slope.segment<3>(6);
  // y(θ) = r1 + θ r2 + θ(1−θ) r3 + θ²(1−θ) r4 (r5 = 0) holds a cubic A θ + B θ² + C θ³ as
  // r2 = A + B + C, r3 = −(B + C), r4 = −C.
  const auto cubic = [&](const Vec3& A, const Vec3& B, const Vec3& C, int at) {
    seg->r2.segment<3>(at) = A + B + C;
    seg->r3.segment<3>(at) = -(B + C);
    seg->r4.segment<3>(at) = -C;
  };
  seg->t0 = s.t;
  seg->h = h;
  seg->r1 = s.y;
  cubic(v0 * h, 0.5 * a0 * h * h, j * (h * h * h / 6.0), 0);
  cubic(a0 * h, 0.5 * j * h * h, Vec3::Zero(), 3);
  cubic(w_rate0 * h, 0.5 * w_slope * h * h, Vec3::Zero(), 6);
  seg->r5.setZero();
  return true;
}

/// The time inside the step `s` (ending at `y1`) where the spin parameter S crosses a kink
/// of the aero law, or -1 when it crosses none. The law is continuous there but its slope
/// in S jumps: at s_max, where the fit is held constant (tour_fit's Cd slope jumps from
/// -0.098 to 0), and at lift_onset, where the lift turns linear to 0. A Dormand–Prince step
/// across such a kink is first order at it, and its error estimate does not see that: the
/// carries of 1 000 random launches are 1.4 mm off the 1e-13 reference at the 95th
/// percentile (worst 3.5 mm) with the kink inside steps, 0.06 mm (worst 0.16 mm) with the
/// law made smooth there. Ending the step at the kink keeps the law smooth inside every
/// step without changing it. Most carries cross s_max once or not at all.
double aero_kink_crossed(const Dynamics& f, const Segment& s, const State9& y1) {
  const AeroModel& a = *f.model->aero;
  const double s0 = f.spin_parameter(s.r1), s1 = f.spin_parameter(y1);
  double first = -1.0;
  for (const double kink : {a.s_max, a.lift_onset}) {
    // A step that starts on the kink crosses none: the one after a step ended there starts
    // within ~1e-6 of it in S (the root is found on the dense output, the step ends on the
    // step's own fifth-order solution).
    if (!(kink > 0.0) || (s0 < kink) == (s1 < kink) || std::abs(s0 - kink) <= 1e-4 * kink) continue;
    const double sign = s0 > kink ? 1.0 : -1.0;  // find_root wants g(t0) > 0 >= g(t1)
    const auto g = [&](double t) { return sign * (f.spin_parameter(s.at(t)) - kink); };
    const double t = find_root(g, s.t0, s.t1(), sign * (s0 - kink), sign * (s1 - kink));
    if (t > s.t0 && t < s.t1() && (first < 0.0 || t < first)) first = t;
  }
  return first;
}

/// The first trial step of a launch (s). At rel_tol 1e-6 the carry's accepted steps start
/// at ~0.25 s and grow to ~0.9 s (golf and baseball alike: their flights are seconds long
/// and smooth); DOPRI5's local error grows as h⁵, so the step that meets another tolerance
/// scales as its fifth root (1e-13: 10 ms). A first trial that is too long costs one
/// rejected trial; a 10 ms first trial takes two extra steps growing out of it (the step
/// may grow at most 5x a step), ~4 % of a golf shot's time.
double launch_step(double rel_tol) {
  constexpr double kStepAtMicro = 0.25;  // s, at rel_tol = 1e-6
  return std::clamp(kStepAtMicro * std::pow(rel_tol / 1e-6, 0.2), 1e-4, 1.0);
}

/// The aero models are stated up to kMaxReynolds, for the flow past the ball and for the flow
/// its spinning surface drags along: a large, fast ball beyond it (a 20 cm ball at 100 mph),
/// or one whose surface spins faster than any measured ball's (a 20 cm ball at 20 000 rpm: its
/// surface at 209 m/s, 4.7x a golf ball's at the same rate), has no drag, lift or decay law to
/// fly by, and its integration blows up. The surface's Reynolds number is ρ(ωR)D/µ, the same
/// number with the surface speed for the ball's: a golf ball at 20 000 rpm is 1.3e5, a
/// baseball at 20 000 rpm 3.7e5, both inside.
void refuse_beyond_aero_range(const ShotModel& m, const Dynamics& f, const State9& y) {
  const double speed = f.air_velocity(y).norm();
  const double re = speed * f.aero.re_per_speed;
  const double surface_speed = y.segment<3>(6).norm() * m.ball.radius;
  const double re_spin = surface_speed * f.aero.re_per_speed;
  if (re <= kMaxReynolds && re_spin <= kMaxReynolds) return;
  const auto whole = [](double x) { return std::to_string(static_cast<long long>(std::llround(x))); };
  const std::string ball = "flight: a ball of radius " + whole(1000.0 * m.ball.radius) + " mm (ball.radius)";
  const std::string range = ", beyond the aero models' range (at most " + whole(kMaxReynolds) + ": ";
  if (re > kMaxReynolds)
    throw InputError(ball + " at " + whole(speed) + " m/s through the air has a Reynolds number of " + whole(re) + range +
                     "a tour drive is 2.1e5, a 110 mph batted ball 2.4e5); a smaller ball or a slower launch");
  throw InputError(ball + " spinning at " + whole(radps_to_rpm(y.segment<3>(6).norm())) + " rpm moves its surface at " +
                   whole(surface_speed) + " m/s, a spin Reynolds number of " + whole(re_spin) + range +
                   "a golf ball at 20000 rpm is 1.3e5); a smaller ball or less spin");
}

}  // namespace

void refuse_unrepresentable(const ShotModel& m, const std::string& what) {
  throw InputError("flight: " + what + ", for a ball of " + std::to_string(1000.0 * m.ball.mass) + " g (ball.mass) and " +
                   std::to_string(1000.0 * m.ball.radius) +
                   " mm (ball.radius); the inputs are outside what the flight models can represent");
}

ShotEvent air_step(const ShotModel& m, ShotState& s, double until) {
  ShotEvent ev;
  if (out_of_budget(m, s)) {
    end_shot(s, EndReason::StepLimit);
    ev.kind = ShotEventKind::StepLimit;
    return ev;
  }
  const FlightSettings& set = m.settings;
  // The carry is integrated at rel_tol; the hops after it at the looser bounce tolerance.
  const IntegratorTolerances tol{s.landed ? std::max(set.rel_tol, set.bounce_rel_tol) : set.rel_tol, set.abs_tol,
                                 1e-10, 1.0, set.position_error_time};
  DopriCarry<9> carry;
  carry.h = s.step_size;
  carry.k1 = s.rate;
  carry.have_k1 = s.rate_valid;
  Segment seg;
  double t1 = s.t;
  State9 y1 = s.y;
  const Dynamics f(m, s.landed, s.support.point.dot(up_axis()), ContactLayer::of(m, s));
  if (!(carry.h > 0.0)) {  // a launch (or a restart after a bounce): no step taken yet
    refuse_beyond_aero_range(m, f, s.y);
    carry.h = launch_step(tol.rel_tol);
  }
  const double t_end = std::min(until, set.max_time);
  if (short_hop(s, f, t_end, &seg)) {
    y1 = seg.at(seg.t1());
    t1 = seg.t1();
    s.rate_valid = false;  // the next step (if the hop ran off an edge) starts afresh
  } else {
    const DopriCarry<9> before = carry;
    s.counters.rejected_steps += dopri_step(f, tol, carry, t1, y1, t_end, seg);
    // A carry step across a kink of the aero law is taken again, ending at the kink.
    if (!s.landed) {
      const double kink = aero_kink_crossed(f, seg, y1);
      if (kink > seg.t0) {
        carry = before;
        t1 = s.t;
        y1 = s.y;
        s.counters.rejected_steps += 1 + dopri_step(f, tol, carry, t1, y1, kink, seg);
      }
    }
    s.step_size = carry.h;
    s.rate = carry.k1;
    s.rate_valid = carry.have_k1;
  }
  ++s.counters.flight_steps;
  if (!finite(y1) || !std::isfinite(carry.h)) {
    refuse_unrepresentable(m, "the ball's state became non-finite at t = " + std::to_string(s.t) + " s, from " +
                                  std::to_string(s.y.segment<3>(3).norm()) + " m/s and " +
                                  std::to_string(radps_to_rpm(s.y.segment<3>(6).norm())) + " rpm");
  }
  // Apex: vertical velocity crossing zero inside the step. The dense output's height is at
  // most r1 + |r2| + |r3| + |r4| + |r5| (θ and 1 − θ lie in [0, 1]); a step that cannot rise
  // above the highest point so far (every hop after a carry) needs no root.
  const double height_bound = seg.r1[1] + std::abs(seg.r2[1]) + std::abs(seg.r3[1]) + std::abs(seg.r4[1]) +
                              std::abs(seg.r5[1]);
  if (seg.r1[4] > 0.0 && y1[4] <= 0.0 && height_bound > s.max_height) {
    const double ta = find_root([&](double t) { return seg.component(t, 4); }, seg.t0, seg.t1(), seg.r1[4], y1[4]);
    s.max_height = std::max(s.max_height, seg.component(ta, 1));
  }
  Hit hit;
  const bool touches = find_contact(m, s, seg, y1, &hit);
  // A touch outside the world's bounds is not reached: the shot ended where the ball left
  // them. (Checked first, the touch would let a ball land past the bounds when one step both
  // left them and came down, and not when the steps fell otherwise: Denver's 450 ft home run
  // would "land" at 137 m in a ballpark whose bounds end at 130 m.)
  const double t_out = touches ? hit.t : seg.t1();
  const bool inside_at_end = m.terrain->inside(touches ? position_at(seg, hit.t) : Vec3(y1.segment<3>(0)));
  if (!inside_at_end && m.terrain->inside(seg.r1.segment<3>(0))) {
    // Left the world during the step: end where it crossed the bounds, found by bisection
    // on the dense output, so where a shot leaves does not depend on the step size (the
    // step's end lies metres past the bounds at the tolerance's step lengths).
    double lo = seg.t0, hi = t_out;
    for (int i = 0; i < 60 && hi - lo > 1e-12; ++i) {
      const double mid = 0.5 * (lo + hi);
      (m.terrain->inside(position_at(seg, mid)) ? lo : hi) = mid;
    }
    s.t = hi;
    s.y = seg.at(hi);
    s.max_height = std::max(s.max_height, s.y[1]);
    end_shot(s, EndReason::LeftWorld);
    ev.kind = ShotEventKind::LeftWorld;
    return ev;
  }
  if (touches) {
    s.stalled_in_air = 0;
    s.t = hit.t;
    s.y = seg.at(hit.t);
    s.max_height = std::max(s.max_height, s.y[1]);
    // The contact point is the foot of the ball's centre at the touch on the face's plane,
    // not the foot of the straight chord's centre where the chord met it: the chords, and
    // with them that point (up to their sag, ~5 mm, away), depend on where the integrator's
    // steps fall. The smooth bounce normal is read at this point, so a bounce does not
    // change with the tolerance (read at the chord's foot, it puts rests of the 1 000-launch
    // sample over 1 cm from the 1e-13 reference). Where two faces of one surface that share
    // an edge meet at that point, the one under the centre is the one touched (which side of
    // a fairway/rough seam it landed on; meshes that share no vertices are not matched).
    SurfaceContact c = hit.contact;
    const Vec3 centre = s.y.segment<3>(0);
    c.point = centre - c.normal * c.normal.dot(centre - c.point);
    m.terrain->refine_contact(centre, &c);
    return touch_surface(m, s, c);
  }
  // Free flight, no surface touched, that stops advancing is no ball held by faces: the
  // equations are too stiff to integrate (an aero law that explodes). Put to rest as a held
  // ball is, it would end the shot in mid-air at an arbitrary instant: refused instead.
  s.stalled_in_air = t1 > s.t + kNoProgress ? 0 : s.stalled_in_air + 1;
  if (s.stalled_in_air >= kStalledSteps)
    refuse_unrepresentable(m, "the flight equations stopped advancing at t = " + std::to_string(t1) + " s, at " +
                                  std::to_string(y1.segment<3>(3).norm()) + " m/s");
  s.t = t1;
  s.y = y1;
  s.max_height = std::max(s.max_height, s.y[1]);
  if (!inside_at_end) {  // started outside too (an input placed out of bounds)
    end_shot(s, EndReason::LeftWorld);
    ev.kind = ShotEventKind::LeftWorld;
  }
  return ev;
}

}  // namespace sweetspot::detail
