// The impact with duration. See compliant_impact.hpp for the contact law.
//
// Integration: velocity Verlet (kick–drift–kick) over a fixed step of the estimated Hertz
// contact time / steps_per_contact. The state is both bodies' poses, momenta and the
// impactor's spin angular momentum, plus the contact patch's elastic tangential
// displacement s; the Coulomb limit caps s after each step (the usual stick–slip treatment
// of discrete-element codes). Each kick applies equal and opposite impulses at one point to
// both bodies, and a drift moves each body force-free (the head turning with its angular
// momentum held), so linear and angular momentum are conserved to round-off whatever the
// step (a Runge–Kutta step conserves them only to its truncation error).
#include "physics/compliant_impact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace sweetspot {
namespace {

// The quaternion turned by the world angular velocity w over dt (exact for constant w).
Quat advance(const Quat& q, const Vec3& w, double dt) {
  const double angle = w.norm() * dt;
  if (angle == 0.0) return q;
  return (Quat(Eigen::AngleAxisd(angle, w.normalized())) * q).normalized();
}

struct State {
  Vec3 c1, v1, spin1;  // impactor: CG, velocity, angular momentum about its CG (world)
  Quat q1;
  Vec3 c2, v2, w2;     // ball: centre, velocity, angular velocity (a sphere)
  Vec3 s = Vec3::Zero();  // tangential elastic displacement of the patch (world)
};

struct Contact {
  bool touching = false;
  double delta = 0.0;      // overlap, m
  Vec3 n = Vec3::UnitX();  // unit, impactor -> ball
  Vec3 p = Vec3::Zero();   // contact centre (world)
};

struct Force {
  Vec3 f = Vec3::Zero();   // on the ball at the contact centre (−f on the impactor)
  Vec3 ut = Vec3::Zero();  // tangential slip velocity, ball relative to impactor
  bool slipping = false;
};

class Solver {
 public:
  explicit Solver(const CompliantImpactInput& in) : in_(in) {
    m1_ = in.impactor.mass;
    m2_ = in.ball.mass;
    i1_body_ = in.impactor.inertia_body;
    i1_body_inv_ = in.impactor.inertia_body.inverse();
    i2_ = in.ball.inertia_body(0, 0);
    r_ = in.ball_radius;
    k_ = in.contact.ball.stiffness;
    kappa_ = in.contact.ball.shear_ratio();
    damping_ratio_ = in.contact.ball.tangential_damping;
    mu_ = in.contact.material.friction == FrictionModel::None ? 0.0 : in.contact.material.mu;
  }

  Vec3 impactor_omega(const State& st) const {
    const Mat3 rot = st.q1.toRotationMatrix();
    return rot * (i1_body_inv_ * (rot.transpose() * st.spin1));
  }

  Contact contact(const State& st) const {
    Contact c;
    const Mat3 rot = st.q1.toRotationMatrix();
    const Mat3 surf_rot = rot * in_.surface_rotation.toRotationMatrix();
    const Vec3 origin = st.c1 + rot * in_.surface_origin;
    const Vec3 local = surf_rot.transpose() * (st.c2 - origin);
    Vec3 sp, sn;
    in_.surface.closest(local, &sp, &sn);
    const Vec3 n = surf_rot * sn;
    const Vec3 p_surf = origin + surf_rot * sp;
    c.n = n;
    c.delta = r_ - n.dot(st.c2 - p_surf);
    c.touching = c.delta > 0.0;
    c.p = st.c2 - (r_ - 0.5 * std::max(c.delta, 0.0)) * n;
    return c;
  }

  Force force(const State& st, const Contact& c, double lambda) const {
    Force out;
    if (!c.touching) return out;
    const Vec3& n = c.n;
    const Vec3 vb = st.v2 + st.w2.cross(c.p - st.c2);
    const Vec3 vi = st.v1 + impactor_omega(st).cross(c.p - st.c1);
    const Vec3 u = vb - vi;
    const double un = u.dot(n);
    out.ut = u - un * n;
    const double d32 = c.delta * std::sqrt(c.delta);
    const double fn = std::max(0.0, k_ * d32 * (1.0 - lambda * un));  // δ̇ = −un
    // Tangential: the patch's elastic displacement, kept in the tangent plane.
    const Vec3 s = st.s - st.s.dot(n) * n;
    const double kt = kappa_ * 1.5 * k_ * std::sqrt(c.delta);
    // The shear spring's damping: the normal law's (λ k δ^{3/2} per m/s), Mindlin-scaled.
    const double ct = damping_ratio_ * kappa_ * lambda * k_ * d32;
    Vec3 ft = -kt * s - ct * out.ut;
    const double limit = mu_ * fn;
    const double ftn = ft.norm();
    if (ftn > limit) {
      ft *= ftn > 0.0 ? limit / ftn : 0.0;
      out.slipping = true;
    }
    out.f = fn * n + ft;
    return out;
  }

  // Equal and opposite impulses j (on the ball) and −j (on the impactor) at point p.
  void kick(State& st, const Vec3& j, const Vec3& p) const {
    st.v2 += j / m2_;
    st.w2 += (p - st.c2).cross(j) / i2_;
    st.v1 -= j / m1_;
    st.spin1 -= (p - st.c1).cross(j);
  }

  // Force-free motion: both centres move straight, the head turns with its angular momentum
  // held (its world angular velocity follows its orientation, I_world⁻¹ L).
  void drift(State& st, double dt) const {
    st.c1 += dt * st.v1;
    st.c2 += dt * st.v2;
    // Midpoint rotation: ω at the half-turned pose, so a tumbling head keeps its L.
    const Quat half = advance(st.q1, impactor_omega(st), 0.5 * dt);
    State mid = st;
    mid.q1 = half;
    st.q1 = advance(st.q1, impactor_omega(mid), dt);
  }

  // The shear law is incremental (Mindlin & Deresiewicz): the patch's force changes by
  // k_t(δ) × its stretch, dF_t = −k_t u_t dt, and unloads along the stiffness it has. Stored
  // as F_t = −k_t(δ) s, a patch pressed harder (δ up, k_t ∝ √δ up) at the same stretch would
  // gain force it was never stretched for: energy from nowhere, enough for a soft shear
  // spring to return more tangential speed than came in (e_t > 1). Loading therefore holds the
  // force: s shrinks by k_t(before)/k_t(after) = √(δ_before/δ_after). Unloading scales the
  // force down with k_t, which F_t = −k_t(δ) s already does (Thornton's rule).
  void hold_shear_force(State& st, double delta_before, const Contact& c) const {
    if (c.delta > delta_before && delta_before > 0.0) st.s *= std::sqrt(delta_before / c.delta);
  }

  // The Coulomb cap of the stored shear displacement at zero rate (stick–slip).
  void cap_shear(State& st, const Contact& c) const {
    st.s -= st.s.dot(c.n) * c.n;
    if (!c.touching) {
      st.s.setZero();
      return;
    }
    const double kt = kappa_ * 1.5 * k_ * std::sqrt(c.delta);
    const double limit = mu_ * k_ * c.delta * std::sqrt(c.delta);
    const double sn = st.s.norm();
    if (kt > 0.0 && kt * sn > limit) st.s *= limit / (kt * sn);
  }

  double stiffness() const { return k_; }
  double mu() const { return mu_; }

  double kinetic(const State& st) const {
    return 0.5 * m1_ * st.v1.squaredNorm() + 0.5 * st.spin1.dot(impactor_omega(st)) + 0.5 * m2_ * st.v2.squaredNorm() +
           0.5 * i2_ * st.w2.squaredNorm();
  }

 private:
  const CompliantImpactInput& in_;
  double m1_ = 1, m2_ = 1, i2_ = 1, r_ = 0.02, k_ = 1, kappa_ = 0.67, damping_ratio_ = 1, mu_ = 0;
  Mat3 i1_body_ = Mat3::Identity(), i1_body_inv_ = Mat3::Identity();
};

// The Hunt–Crossley law F = k δ^{3/2} (1 + λ δ̇) in the units δ ~ (m v²/k)^{2/5},
// t ~ δ/v is x'' = −x^{3/2} (1 + c x') with c = λ v_in, x(0) = 0, x'(0) = 1; the rebound
// speed −x'(end) is the restitution it returns, whatever the mass, stiffness or speed.
// Flores et al.'s closed form for c(e) is an approximation (it returns 0.820 for a
// requested 0.830); this integrates the scaled contact instead.
double restitution_of_damping(double c) {
  const int n = 2000;
  const double dt = 4.0 / n;  // the undamped scaled contact lasts 3.22
  double x = 0.0, v = 1.0;
  for (int i = 0; i < 4 * n; ++i) {
    auto acc = [c](double xx, double vv) { return xx > 0.0 ? -xx * std::sqrt(xx) * std::max(0.0, 1.0 + c * vv) : 0.0; };
    const double xm = x + 0.5 * dt * v, vm = v + 0.5 * dt * acc(x, v);
    x += dt * vm;
    v += dt * acc(xm, vm);
    if (x <= 0.0 && v < 0.0) break;
  }
  return -v;
}

// The scaled damping c = λ v_in that returns restitution e, from a table built once
// (101 points in e, interpolated linearly; e below 0.05 or at 1 are clamped to their ends).
double damping_for_restitution(double e) {
  struct Table {
    std::array<double, 101> c{};
    Table() {
      for (int i = 0; i <= 100; ++i) {
        const double target = std::max(0.01 * i, 0.02);
        double lo = 0.0, hi = 200.0;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (restitution_of_damping(mid) > target ? lo : hi) = mid;
        }
        c[static_cast<size_t>(i)] = i == 100 ? 0.0 : 0.5 * (lo + hi);
      }
    }
  };
  static const Table table;
  const double x = std::clamp(e, 0.02, 1.0) * 100.0;
  const int i = std::min(static_cast<int>(x), 99);
  const double f = x - i;
  return (1.0 - f) * table.c[static_cast<size_t>(i)] + f * table.c[static_cast<size_t>(i + 1)];
}


}  // namespace

void ImpactSurface::closest(const Vec3& p, Vec3* point, Vec3* normal) const {
  switch (kind) {
    case Kind::Plane:
      *point = Vec3(0.0, p.y(), p.z());
      *normal = Vec3::UnitX();
      return;
    case Kind::Face: {
      // x = -(z²/2Rb + y²/2Rr), outward normal ∝ (1, y/Rr, z/Rb). Fixed-point on the foot
      // of the perpendicular: converges in a few steps for radii ≫ the offsets.
      double y = p.y(), z = p.z();
      Vec3 q, n;
      for (int i = 0; i < 3; ++i) {
        q = Vec3(-(z * z / (2.0 * bulge_radius) + y * y / (2.0 * roll_radius)), y, z);
        n = Vec3(1.0, y / roll_radius, z / bulge_radius).normalized();
        const double d = n.dot(p - q);
        y = p.y() - d * n.y();
        z = p.z() - d * n.z();
      }
      *point = Vec3(-(z * z / (2.0 * bulge_radius) + y * y / (2.0 * roll_radius)), y, z);
      *normal = Vec3(1.0, y / roll_radius, z / bulge_radius).normalized();
      return;
    }
    case Kind::Barrel: {
      // Around the +x axis with radius r(x); the normal leans with the taper. Past either end
      // the bat is closed by a flat cap, whose face or rim a ball there touches: without it a
      // ball met at the very tip would jump from no overlap to a deep one within a step.
      const Vec3 radial(0.0, p.y(), p.z());
      const double rn = radial.norm();
      const Vec3 dir = rn > 0.0 ? Vec3(radial / rn) : Vec3::UnitY();
      const double knob = bat->barrel_profile.front().first, tip = bat->barrel_profile.back().first;
      if (p.x() > tip || p.x() < knob) {
        const double end = p.x() > tip ? tip : knob;
        const Vec3 out = p.x() > tip ? Vec3::UnitX() : Vec3(-Vec3::UnitX());
        const double r_end = bat->radius_at(end);
        if (rn <= r_end) {
          *point = Vec3(end, p.y(), p.z());
          *normal = out;
        } else {
          *point = Vec3(end, 0.0, 0.0) + r_end * dir;
          const Vec3 to = p - *point;
          *normal = to.norm() > 0.0 ? Vec3(to.normalized()) : Vec3(dir);
        }
        return;
      }
      const double x = p.x();
      const double r = bat->radius_at(x);
      const double h = 1e-4;
      const double x0 = std::max(knob, x - h), x1 = std::min(tip, x + h);
      const double slope = (bat->radius_at(x1) - bat->radius_at(x0)) / (x1 - x0);
      *point = Vec3(x, 0.0, 0.0) + r * dir;
      *normal = (dir - slope * Vec3::UnitX()).normalized();
      return;
    }
  }
}

std::string validate_compliant_impact(const CompliantImpactInput& in) {
  std::ostringstream os;
  if (!(in.impactor.mass > 0.0) || !std::isfinite(in.impactor.mass)) return "impactor: mass must be > 0";
  if (!(in.ball.mass > 0.0) || !std::isfinite(in.ball.mass)) return "ball: mass must be > 0";
  if (!in.impactor.inertia_body.allFinite() || !in.ball.inertia_body.allFinite()) return "inertia must be finite";
  if (!(in.ball.inertia_body(0, 0) > 0.0)) return "ball: inertia must be > 0";
  if (!(in.ball_radius > 0.0)) return "ball: radius must be > 0";
  if (!in.impactor.velocity.allFinite() || !in.impactor.angular_velocity.allFinite() ||
      !in.ball.velocity.allFinite() || !in.ball.angular_velocity.allFinite() || !in.impactor.position.allFinite() ||
      !in.ball.position.allFinite())
    return "positions and velocities must be finite";
  if (auto w = range_refusal("ball.stiffness", in.contact.ball.stiffness, Range{0.0, 1e12, true}, "N/m^1.5");
      !w.empty())
    return w;
  if (auto w = range_refusal("ball.poisson", in.contact.ball.poisson, BallCompliance::kPoisson, ""); !w.empty()) return w;
  if (auto w = range_refusal("ball.shear_stiffness_ratio", in.contact.ball.shear_stiffness_ratio,
                             BallCompliance::kShearStiffnessRatio, "");
      !w.empty())
    return w;
  if (auto w = range_refusal("ball.tangential_damping", in.contact.ball.tangential_damping,
                             BallCompliance::kTangentialDamping, "");
      !w.empty())
    return w;
  if (auto w = validate_material_values(in.contact.material); !w.empty()) return w;
  if (auto w = range_refusal("cor_factor", in.contact.cor_factor, Range{0.0, 1.0, true}, ""); !w.empty()) return w;
  if (in.surface.kind == ImpactSurface::Kind::Barrel && in.surface.bat == nullptr) return "barrel surface without a bat";
  if (!(in.contact.steps_per_contact >= 10 && in.contact.steps_per_contact <= 100000))
    return "steps_per_contact out of range (allowed [10, 100000])";
  return {};
}

CompliantImpactResult solve_compliant_impact(const CompliantImpactInput& in) noexcept {
  Solver solver(in);
  State st;
  {
    const Mat3 rot = in.impactor.orientation.toRotationMatrix();
    st.c1 = in.impactor.position;
    st.v1 = in.impactor.velocity;
    st.q1 = in.impactor.orientation;
    st.spin1 = rot * in.impactor.inertia_body * rot.transpose() * in.impactor.angular_velocity;
    st.c2 = in.ball.position;
    st.v2 = in.ball.velocity;
    st.w2 = in.ball.angular_velocity;
  }
  const double ke0 = solver.kinetic(st);

  // Normal approach speed, effective mass and the Hertz contact time set the damping and step.
  const Contact c0 = solver.contact(st);
  const Vec3 n0 = c0.n;
  const ImpactBody b1 = make_impact_body(in.impactor, c0.p, "impactor");
  const ImpactBody b2 = make_impact_body(in.ball, c0.p, "ball");
  const double v_in = std::max(-contact_velocity(b1, b2).dot(n0), 1e-6);
  const double m_eff = 1.0 / n0.dot(collision_matrix(b1, b2) * n0);
  CompliantImpactResult res;
  res.first_contact = c0.p;
  res.e_used = std::clamp(in.contact.material.e.at(v_in) * in.contact.cor_factor, 1e-3, 1.0);
  // Hunt–Crossley damping for a restitution e (the scaled law above; Flores, Machado, Silva
  // & Martins 2011 give the approximation λ ≈ 8(1 − e)/(5 e v_in)).
  const double lambda = damping_for_restitution(res.e_used) / v_in;
  const double k = solver.stiffness();
  // Hertz contact time of an elastic sphere: 2.94 (m*² / (k² v))^{1/5}.
  const double t_hertz = 2.9432 * std::pow(m_eff * m_eff / (k * k * v_in), 0.2);
  const int n_steps = in.contact.steps_per_contact;
  const double dt = t_hertz / n_steps;

  Vec3 impulse = Vec3::Zero();
  Vec3 normal_sum = Vec3::Zero();
  double t = 0.0;
  bool ever_stuck = false;
  const int max_steps = 20 * n_steps;  // a contact lasting 20 Hertz times is not a ball impact
  Contact c = c0;
  Force f = solver.force(st, c, lambda);
  int i = 0;
  for (; i < max_steps; ++i) {
    const Vec3 j0 = 0.5 * dt * f.f;
    solver.kick(st, j0, c.p);
    // The patch stretches with the slip velocity at the half step.
    const Vec3 ut_half = solver.force(st, c, lambda).ut;
    solver.drift(st, dt);
    st.s += dt * ut_half;
    const double loaded_at = c.delta;
    c = solver.contact(st);
    solver.hold_shear_force(st, loaded_at, c);
    solver.cap_shear(st, c);
    f = solver.force(st, c, lambda);
    const Vec3 j1 = 0.5 * dt * f.f;
    solver.kick(st, j1, c.p);
    t += dt;
    impulse += j0 + j1;
    normal_sum += (j0 + j1).dot(c.n) * c.n;
    res.max_compression = std::max(res.max_compression, c.delta);
    if (c.touching && !f.slipping) ever_stuck = true;
    if (!c.touching) break;  // separated
    // The velocity-dependent force is evaluated again with the kicked velocities.
    f = solver.force(st, c, lambda);
  }
  res.steps = i + 1;
  res.duration = t;
  res.impulse = impulse;
  res.mean_normal = normal_sum.norm() > 0.0 ? Vec3(normal_sum.normalized()) : n0;
  res.normal_impulse = impulse.dot(res.mean_normal);
  res.tangential_impulse = (impulse - res.normal_impulse * res.mean_normal).norm();
  res.contact = ever_stuck ? ContactKind::Grip : ContactKind::Slip;
  if (solver.mu() == 0.0) res.contact = ContactKind::Frictionless;
  res.impactor_after = in.impactor;
  res.impactor_after.position = st.c1;
  res.impactor_after.orientation = st.q1;
  res.impactor_after.velocity = st.v1;
  res.impactor_after.angular_velocity = solver.impactor_omega(st);
  res.ball_after = in.ball;
  res.ball_after.position = st.c2;
  res.ball_after.velocity = st.v2;
  res.ball_after.angular_velocity = st.w2;
  res.energy_loss = ke0 - solver.kinetic(st);
  return res;
}

}  // namespace sweetspot
