// The impulse solver. See impact.hpp for conventions and DESIGN §3 for the models.
#include "physics/impact.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "physics/error.hpp"

namespace sweetspot {

const char* to_string(FrictionModel m) {
  switch (m) {
    case FrictionModel::None: return "none";
    case FrictionModel::Textbook: return "textbook";
    case FrictionModel::Coulomb: return "coulomb";
  }
  return "?";
}

const char* to_string(ContactKind k) {
  switch (k) {
    case ContactKind::Grip: return "grip";
    case ContactKind::Slip: return "slip";
    case ContactKind::Frictionless: return "none";
  }
  return "?";
}

double CorCurve::at(double vn) const {
  if (count <= 1 || vn <= speed[0]) return cor[0];
  for (int i = 1; i < count; ++i) {
    const auto k = static_cast<size_t>(i);
    if (vn <= speed[k]) {
      const double t = (vn - speed[k - 1]) / (speed[k] - speed[k - 1]);
      return cor[k - 1] + t * (cor[k] - cor[k - 1]);
    }
  }
  return cor[static_cast<size_t>(count - 1)];
}

Mat3 collision_matrix(const ImpactBody& impactor, const ImpactBody& ball) {
  const Mat3 r1x = cross_matrix(impactor.r);
  const Mat3 r2x = cross_matrix(ball.r);
  return Mat3::Identity() * (impactor.inv_mass + ball.inv_mass) -
         r1x * impactor.inv_inertia * r1x - r2x * ball.inv_inertia * r2x;
}

Vec3 contact_velocity(const ImpactBody& impactor, const ImpactBody& ball) {
  return (ball.velocity + ball.angular_velocity.cross(ball.r)) -
         (impactor.velocity + impactor.angular_velocity.cross(impactor.r));
}

ImpactResult solve_impact(const ImpactInput& in) noexcept {
  const Vec3& n = in.normal;
  const ImpactMaterial& mat = in.material;
  const Mat3 k = collision_matrix(in.impactor, in.ball);
  const Vec3 u = contact_velocity(in.impactor, in.ball);
  const double un = u.dot(n);  // < 0 approaching
  const Vec3 ut = u - un * n;
  const double ut_norm = ut.norm();

  ImpactResult res;
  res.e_used = mat.e.at(-un);
  const double e = res.e_used;
  const Vec3 kn = k * n;
  const double jn_frictionless = -(1.0 + e) * un / n.dot(kn);

  Vec3 p = Vec3::Zero();
  switch (mat.friction) {
    case FrictionModel::None:
      p = jn_frictionless * n;
      res.contact = ContactKind::Frictionless;
      break;
    case FrictionModel::Textbook: {
      // Bourg's model: µ·jn along −û_t, in full, whatever the sliding speed. Kept for
      // teaching; it can reverse sliding and create energy (tests demonstrate it).
      p = jn_frictionless * n;
      if (ut_norm > 0.0) p -= mat.mu * jn_frictionless * (ut / ut_norm);
      res.contact = ContactKind::Slip;
      break;
    }
    case FrictionModel::Coulomb: {
      // The impulse that ends the impact at normal separation −e·un and tangential
      // velocity −e_t·u_t; keep it if it lies inside the friction cone (grip).
      const Vec3 target_change = -(1.0 + e) * un * n - (1.0 + mat.e_t) * ut;
      const Vec3 p_stick = k.ldlt().solve(target_change);
      const double pn = p_stick.dot(n);
      const Vec3 pt = p_stick - pn * n;
      const double pt_norm = pt.norm();
      if (pt_norm <= mat.mu * pn) {
        p = p_stick;
        res.contact = ContactKind::Grip;
      } else {
        // Slip: friction at its limit, opposing the tangential push the stick impulse
        // needed. With an isotropic K this is −û_t exactly (DESIGN §3); with the coupled
        // K of an off-centre club hit it is the direction sliding actually takes.
        const Vec3 t_hat = pt / pt_norm;
        const Vec3 d = n + mat.mu * t_hat;
        const double denom = n.dot(k * d);
        // A non-positive denominator means friction coupling would pull the bodies
        // together (Painlevé-like jam); fall back to a frictionless normal impulse.
        if (denom > 1e-12 * n.dot(kn)) {
          p = (-(1.0 + e) * un / denom) * d;
        } else {
          p = jn_frictionless * n;
        }
        res.contact = ContactKind::Slip;
      }
      break;
    }
  }

  res.impulse = p;
  res.normal_impulse = p.dot(n);
  res.tangential_impulse = (p - res.normal_impulse * n).norm();

  res.impactor_after = in.impactor;
  res.ball_after = in.ball;
  res.ball_after.velocity += in.ball.inv_mass * p;
  res.ball_after.angular_velocity += in.ball.inv_inertia * in.ball.r.cross(p);
  res.impactor_after.velocity -= in.impactor.inv_mass * p;
  res.impactor_after.angular_velocity -= in.impactor.inv_inertia * in.impactor.r.cross(p);

  // For rigid bodies the work done by an impulse is p·(u⁻ + u⁺)/2 exactly.
  const Vec3 u_after = u + k * p;
  res.energy_loss = -0.5 * p.dot(u + u_after);
  return res;
}

namespace {

bool finite(const Vec3& v) { return v.allFinite(); }

std::string check_body(const ImpactBody& b, const char* name) {
  std::ostringstream os;
  if (!std::isfinite(b.inv_mass) || b.inv_mass < 0.0) {
    os << name << ": mass must be > 0 (inverse mass " << b.inv_mass << " given; 0 = immovable)";
    return os.str();
  }
  if (!b.inv_inertia.allFinite() || !finite(b.r) || !finite(b.velocity) || !finite(b.angular_velocity)) {
    return std::string(name) + ": inertia, contact arm and velocities must be finite";
  }
  const Mat3& i = b.inv_inertia;
  if ((i - i.transpose()).cwiseAbs().maxCoeff() > 1e-9 * (1.0 + i.cwiseAbs().maxCoeff())) {
    return std::string(name) + ": inertia tensor must be symmetric";
  }
  if (!i.isZero(0.0)) {
    Eigen::SelfAdjointEigenSolver<Mat3> eig(i);
    if (eig.eigenvalues().minCoeff() <= 0.0) {
      return std::string(name) + ": inertia tensor must be positive definite";
    }
  }
  return {};
}

}  // namespace

std::string validate_impact(const ImpactInput& in) {
  if (auto m = check_body(in.impactor, "impactor"); !m.empty()) return m;
  if (auto m = check_body(in.ball, "ball"); !m.empty()) return m;
  if (in.impactor.inv_mass == 0.0 && in.ball.inv_mass == 0.0) {
    return "impact: at least one body must have finite mass";
  }
  if (!finite(in.normal) || std::abs(in.normal.norm() - 1.0) > 1e-9) {
    return "impact: contact normal must be a unit vector (|n| = 1 within 1e-9)";
  }
  const ImpactMaterial& m = in.material;
  if (m.e.count < 1 || m.e.count > CorCurve::kMaxPoints) {
    return "impact.e: the restitution table needs 1 to 8 points";
  }
  for (int i = 0; i < m.e.count; ++i) {
    const auto k = static_cast<size_t>(i);
    if (!(m.e.cor[k] >= 0.0 && m.e.cor[k] <= 1.0)) {
      return "impact.e: restitution must be in [0, 1], got " + std::to_string(m.e.cor[k]);
    }
    if (i > 0 && !(m.e.speed[k] > m.e.speed[k - 1])) {
      return "impact.e: table speeds must be strictly increasing";
    }
  }
  if (!(m.e_t >= 0.0 && m.e_t <= 1.0)) {
    return "impact.e_t: tangential restitution must be in [0, 1], got " + std::to_string(m.e_t);
  }
  if (!(m.mu >= 0.0) || !std::isfinite(m.mu)) {
    return "impact.mu: friction coefficient must be >= 0 and finite, got " + std::to_string(m.mu);
  }
  if (contact_velocity(in.impactor, in.ball).dot(in.normal) >= 0.0) {
    return "impact: bodies are separating or at rest along the normal (u·n >= 0); nothing to solve";
  }
  return {};
}

ImpactResult solve_impact_checked(const ImpactInput& in) {
  if (auto msg = validate_impact(in); !msg.empty()) throw InputError(msg);
  return solve_impact(in);
}

double kinetic_energy(const ImpactBody& b) {
  double ke = 0.0;
  if (b.inv_mass > 0.0) ke += 0.5 * b.velocity.squaredNorm() / b.inv_mass;
  if (!b.inv_inertia.isZero(0.0)) {
    ke += 0.5 * b.angular_velocity.dot(b.inv_inertia.inverse() * b.angular_velocity);
  }
  return ke;
}

}  // namespace sweetspot
