#include "game/tuning/impact_case.hpp"

#include <cmath>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

Vec3 vec(const CheckedDoc& doc, const std::string& key) {
  const auto v = doc.list(key);
  return Vec3(v[0], v[1], v[2]);
}

ImpactBody body_from(const CheckedDoc& doc, const std::string& prefix, bool fixed) {
  ImpactBody b;
  b.r = vec(doc, prefix + ".r");
  b.velocity = vec(doc, prefix + ".velocity");
  b.angular_velocity = vec(doc, prefix + ".angular_velocity");
  if (fixed) return b;  // inv_mass 0, zero inverse inertia: immovable
  b.inv_mass = 1.0 / doc.quantity(prefix + ".mass");
  b.inv_inertia = Mat3::Identity() / doc.quantity(prefix + ".inertia");
  return b;
}

double kinetic(const ImpactBody& b) { return kinetic_energy(b); }

}  // namespace

ImpactInput impact_input_from(const CheckedDoc& doc) {
  ImpactInput in;
  const bool fixed = doc.flag("impactor.fixed");
  if (fixed && (doc.has("impactor.mass") || doc.has("impactor.inertia"))) {
    throw InputError(doc.origin("impactor.fixed") + ": impactor.fixed: a fixed impactor takes no mass or inertia");
  }
  in.impactor = body_from(doc, "impactor", fixed);
  in.ball = body_from(doc, "ball", false);
  const Vec3 n = vec(doc, "normal");
  if (!(n.norm() > 1e-9)) throw InputError(doc.origin("normal") + ": normal: must not be zero");
  in.normal = n.normalized();
  in.material.e = CorCurve::constant(doc.quantity("impact.e"));
  in.material.e_t = doc.quantity("impact.e_t");
  in.material.mu = doc.quantity("impact.mu");
  const std::string f = doc.text("impact.friction");
  in.material.friction = f == "none" ? FrictionModel::None : f == "textbook" ? FrictionModel::Textbook
                                                                             : FrictionModel::Coulomb;
  if (const std::string why = validate_impact(in); !why.empty()) {
    throw InputError(doc.source() + ": " + why);
  }
  return in;
}

ImpactMeasurements measure_impact(const ImpactInput& in, const ImpactResult& out) {
  ImpactMeasurements m;
  const Vec3 v = out.ball_after.velocity;
  auto put = [&](const char* name, const Vec3& x) { m.values[name] = {x.x(), x.y(), x.z()}; };
  put("ball_velocity", v);
  put("impactor_velocity", out.impactor_after.velocity);
  put("ball_spin", out.ball_after.angular_velocity);
  m.values["ball_speed"] = {v.norm()};
  m.values["ball_direction"] = {std::atan2(v.y(), v.x())};
  // Tangential direction: the sliding direction of the approach (zero for a head-on hit).
  const Vec3& n = in.normal;
  const Vec3 u0 = contact_velocity(in.impactor, in.ball);
  const Vec3 ut0 = u0 - u0.dot(n) * n;
  const Vec3 t = ut0.norm() > 1e-12 ? Vec3(ut0.normalized()) : Vec3(Vec3::Zero());
  const Vec3 u1 = contact_velocity(out.impactor_after, out.ball_after);
  const Vec3 vt_ball = v - v.dot(n) * n;
  m.values["ball_tangential_velocity"] = {vt_ball.dot(t)};
  m.values["contact_tangential_velocity"] = {u1.dot(t)};
  const double before = kinetic(in.impactor) + kinetic(in.ball);
  const double after = kinetic(out.impactor_after) + kinetic(out.ball_after);
  m.values["energy_ratio"] = {before > 0.0 ? after / before : 0.0};
  m.contact = to_string(out.contact);
  return m;
}

}  // namespace sweetspot
