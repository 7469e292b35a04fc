// The impulse solver. See impact.hpp for conventions and DESIGN §3 for the models.
#include "physics/impact.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

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

bool friction_model_from_string(std::string_view name, FrictionModel* out) {
  for (const FrictionModel m : {FrictionModel::None, FrictionModel::Textbook, FrictionModel::Coulomb}) {
    if (name == to_string(m)) {
      *out = m;
      return true;
    }
  }
  return false;
}

std::string friction_model_names() { return "none, textbook, coulomb"; }

const char* to_string(ImpactModel m) { return m == ImpactModel::Compliant ? "compliant" : "rigid"; }

bool impact_model_from_string(std::string_view name, ImpactModel* out) {
  for (const ImpactModel m : {ImpactModel::Compliant, ImpactModel::Rigid}) {
    if (name == to_string(m)) {
      *out = m;
      return true;
    }
  }
  return false;
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

double energy_limit_fraction(double a, double b, double c) {
  const double disc = std::sqrt(std::max(0.0, b * b - 4.0 * a * c));
  double lambda = 0.0;
  if (b > 0.0) {
    lambda = (-2.0 * a) / (b + disc);  // the stable form of the root when b > 0
  } else if (c > 0.0) {
    lambda = (-b + disc) / (2.0 * c);
  }
  return std::clamp(lambda, 0.0, 1.0);
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

namespace {

// K⁻¹ b for the symmetric positive definite collision matrix by the adjugate: a closed
// form with no pivoting and no branches, several times faster than a general
// factorisation on the hot path and as accurate for the well-conditioned K of real bodies.
Vec3 solve_spd3(const Mat3& k, const Vec3& b) {
  const double a00 = k(1, 1) * k(2, 2) - k(1, 2) * k(2, 1);
  const double a01 = k(0, 2) * k(2, 1) - k(0, 1) * k(2, 2);
  const double a02 = k(0, 1) * k(1, 2) - k(0, 2) * k(1, 1);
  const double a11 = k(0, 0) * k(2, 2) - k(0, 2) * k(2, 0);
  const double a12 = k(0, 2) * k(1, 0) - k(0, 0) * k(1, 2);
  const double a22 = k(0, 0) * k(1, 1) - k(0, 1) * k(1, 0);
  const double det = k(0, 0) * a00 + k(0, 1) * a01 + k(0, 2) * a02;
  const double inv_det = 1.0 / det;
  return Vec3(a00 * b.x() + a01 * b.y() + a02 * b.z(),
              a01 * b.x() + a11 * b.y() + a12 * b.z(),
              a02 * b.x() + a12 * b.y() + a22 * b.z()) * inv_det;
}

// Kinetic energy change of the two bodies under impulse p: p·u + ½ pᵀK p (exact for
// rigid bodies; u is the pre-impact contact velocity).
double energy_gain(const Mat3& k, const Vec3& u, const Vec3& p) {
  return p.dot(u) + 0.5 * p.dot(k * p);
}

}  // namespace

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
  res.e_t_used = mat.e_t;
  const double e = res.e_used;
  const Vec3 kn = k * n;
  const double jn_frictionless = -(1.0 + e) * un / n.dot(kn);
  const Vec3 p_frictionless = jn_frictionless * n;

  Vec3 p = Vec3::Zero();
  switch (mat.friction) {
    case FrictionModel::None:
      p = p_frictionless;
      res.contact = ContactKind::Frictionless;
      break;
    case FrictionModel::Textbook: {
      // Bourg's model: µ·jn along −û_t, in full, whatever the sliding speed. Kept for
      // teaching; it can reverse sliding and create energy (tests demonstrate it).
      p = p_frictionless;
      if (ut_norm > 0.0) p -= mat.mu * jn_frictionless * (ut / ut_norm);
      res.contact = ContactKind::Slip;
      break;
    }
    case FrictionModel::Coulomb: {
      // The impulse that ends the impact at normal separation −e·un and tangential
      // velocity −e_t·u_t; keep it if it lies inside the friction cone (grip).
      const Vec3 target_change = -(1.0 + e) * un * n - (1.0 + res.e_t_used) * ut;
      const Vec3 p_stick = solve_spd3(k, target_change);
      const double pn = p_stick.dot(n);
      const Vec3 pt = p_stick - pn * n;
      const double pt_norm = pt.norm();
      if (pt_norm <= mat.mu * pn) {
        p = p_stick;
        res.contact = ContactKind::Grip;
      } else {
        // Slip: friction at its limit µ·jn along the tangential direction the sticking
        // impulse needed, with jn keeping the normal separation at −e·un. When K does not
        // couple normal and tangent (ball on ground, centred hits) that direction is −û_t,
        // DESIGN §3's formula; with the coupled K of an off-centre hit it differs, and this
        // choice keeps the impulse continuous across the grip/slip boundary (on the cone
        // the slip impulse equals the sticking one), so results never jump as µ is tuned.
        const Vec3 t_hat = pt / pt_norm;
        const Vec3 d = n + mat.mu * t_hat;
        const double denom = n.dot(k * d);
        // A non-positive denominator means friction coupling would pull the bodies
        // together (Painlevé-like jam); fall back to a frictionless normal impulse.
        if (denom > 1e-12 * n.dot(kn)) {
          p = (-(1.0 + e) * un / denom) * d;
        } else {
          p = p_frictionless;
        }
        res.contact = ContactKind::Slip;
      }
      // Every impulse on the segment from the frictionless impulse to p gives the same
      // normal separation and lies in the friction cone; the frictionless end never
      // creates energy (its change is ½(1−e)·jn·un ≤ 0). If p would create energy, take
      // the point of the segment furthest toward p that does not: the root of the
      // quadratic energy change along it.
      const double gain = energy_gain(k, u, p);
      if (gain > 0.0) {
        const Vec3 q = p - p_frictionless;
        const double a = energy_gain(k, u, p_frictionless);  // ≤ 0
        const double b = q.dot(u) + p_frictionless.dot(k * q);
        const double c = 0.5 * q.dot(k * q);
        p = p_frictionless + energy_limit_fraction(a, b, c) * q;
        res.energy_limited = true;
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
  res.energy_loss = -energy_gain(k, u, p);
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

std::string validate_material_values(const ImpactMaterial& m) {
  if (m.e.count < 1 || m.e.count > CorCurve::kMaxPoints) return "impact.e: the restitution table needs 1 to 8 points";
  for (int i = 0; i < m.e.count; ++i) {
    const auto k = static_cast<size_t>(i);
    if (auto why = range_refusal("impact.e", m.e.cor[k], ImpactMaterial::kE, ""); !why.empty()) return why;
    if (i > 0 && !(m.e.speed[k] > m.e.speed[k - 1])) return "impact.e: table speeds must be strictly increasing";
  }
  if (auto why = range_refusal("impact.e_t", m.e_t, ImpactMaterial::kEt, ""); !why.empty()) return why;
  if (auto why = range_refusal("impact.mu", m.mu, ImpactMaterial::kMu, ""); !why.empty()) return why;
  return {};
}

std::string validate_impact(const ImpactInput& in) {
  if (auto m = check_body(in.impactor, "impactor"); !m.empty()) return m;
  if (auto m = check_body(in.ball, "ball"); !m.empty()) return m;
  if (in.impactor.inv_mass == 0.0 && in.ball.inv_mass == 0.0) {
    return "impact: at least one body must have finite mass";
  }
  if (!finite(in.normal) || std::abs(in.normal.norm() - 1.0) > 1e-9) {
    return "impact: contact normal must be a unit vector (|n| = 1 within 1e-9)";
  }
  if (auto m = validate_material_values(in.material); !m.empty()) return m;
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

std::string validate_mass_properties(double mass, const Mat3& inertia, const std::string& what) {
  std::ostringstream os;
  if (!std::isfinite(mass) || mass <= 0.0) {
    os << what << ".mass: must be > 0 kg and finite, got " << mass;
    return os.str();
  }
  if (!inertia.allFinite()) return what + ".inertia: must be finite";
  if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-9 * inertia.cwiseAbs().maxCoeff()) {
    return what + ".inertia: the tensor must be symmetric (I_ij = I_ji)";
  }
  Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
  if (!(eig.eigenvalues().minCoeff() > 0.0)) {
    os << what << ".inertia: the tensor must be positive definite (smallest principal moment "
       << eig.eigenvalues().minCoeff() << " kg·m² given, must be > 0)";
    return os.str();
  }
  return {};
}

ImpactBody make_impact_body(const RigidBody& body, const Vec3& contact, const std::string& what) {
  if (auto msg = validate_mass_properties(body.mass, body.inertia_body, what); !msg.empty()) {
    throw InputError(msg);
  }
  ImpactBody b;
  b.inv_mass = 1.0 / body.mass;
  b.inv_inertia = body.inverse_inertia_world();
  b.inv_inertia = 0.5 * (b.inv_inertia + b.inv_inertia.transpose());  // exact symmetry
  b.r = contact - body.position;
  b.velocity = body.velocity;
  b.angular_velocity = body.angular_velocity;
  return b;
}

}  // namespace sweetspot
