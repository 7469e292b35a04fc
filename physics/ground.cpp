#include "physics/ground.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "physics/root_find.hpp"

namespace sweetspot {
namespace {

constexpr double kStimpReleaseSpeed = 1.83;             // m/s (6 ft/s), USGA Stimpmeter
constexpr double kCraterReferenceSpeed = 18.6;          // m/s, Penner 2002
constexpr double kCraterReferenceAngle = 0.77493;       // rad = 44.4°, Penner 2002
const double kCraterReferenceShape = std::sin(2.0 * kCraterReferenceAngle);  // sin 2θ there

struct KindName {
  SurfaceKind kind;
  const char* name;
};
constexpr std::array<KindName, 14> kKindNames{{
    {SurfaceKind::Tee, "tee"},
    {SurfaceKind::Fairway, "fairway"},
    {SurfaceKind::Rough, "rough"},
    {SurfaceKind::Sand, "sand"},
    {SurfaceKind::Green, "green"},
    {SurfaceKind::Water, "water"},
    {SurfaceKind::Dirt, "dirt"},
    {SurfaceKind::Grass, "grass"},
    {SurfaceKind::WarningTrack, "warning_track"},
    {SurfaceKind::Wall, "wall"},
    {SurfaceKind::OutOfBounds, "out_of_bounds"},
    {SurfaceKind::Decoration, "decoration"},
    {SurfaceKind::Tree, "tree"},
    {SurfaceKind::Path, "path"},
}};

}  // namespace

const char* to_string(SurfaceKind k) {
  for (const auto& kn : kKindNames) {
    if (kn.kind == k) return kn.name;
  }
  return "?";
}

bool surface_kind_from_string(const std::string& s, SurfaceKind* out) {
  for (const auto& kn : kKindNames) {
    if (s == kn.name) {
      *out = kn.kind;
      return true;
    }
  }
  return false;
}

std::string surface_kind_names() {
  std::string s;
  for (const auto& kn : kKindNames) s += (s.empty() ? "" : ", ") + std::string(kn.name);
  return s;
}

std::string validate_surface_material(const SurfaceMaterial& m) {
  std::ostringstream s;
  const std::string where = "material '" + m.name + "': ";
  if (m.e.count < 1 || m.e.count > CorCurve::kMaxPoints) {
    s << where << "e has " << m.e.count << " points (allowed 1.." << CorCurve::kMaxPoints << ")";
    return s.str();
  }
  for (int i = 0; i < m.e.count; ++i) {
    const auto k = static_cast<size_t>(i);
    if (auto w = range_refusal(where + "e", m.e.cor[k], ImpactMaterial::kE, ""); !w.empty()) return w;
    if (i > 0 && !(m.e.speed[k] > m.e.speed[k - 1])) {
      s << where << "e curve speeds must increase strictly (" << m.e.speed[k - 1] << " then " << m.e.speed[k] << " m/s)";
      return s.str();
    }
  }
  const auto bad = [&](const char* field, double v, const Range& r, const char* unit) {
    return range_refusal(where + field, v, r, unit);
  };
  if (auto w = bad("mu", m.mu, SurfaceMaterial::kMu, ""); !w.empty()) return w;
  if (auto w = bad("rolling_resistance", m.rolling_resistance, SurfaceMaterial::kRollingResistance, ""); !w.empty())
    return w;
  if (m.stimp != 0.0) {
    if (auto w = bad("stimp", m.stimp, SurfaceMaterial::kStimp, "m"); !w.empty()) return w + " (or 0 = unset)";
  }
  // A surface a ball can roll on must be able to stop it: on a frictionless floor a ball in a
  // hollow swings for ever (a mesh whose faces fall back to the wall material rolls to the
  // time limit). Water takes the ball and a decoration is never touched.
  if (m.kind != SurfaceKind::Water && m.kind != SurfaceKind::Decoration && m.stimp == 0.0 &&
      m.rolling_resistance < SurfaceMaterial::kMinRollingResistance) {
    s << where << "rolling_resistance = " << m.rolling_resistance << " cannot stop a rolling ball (allowed ["
      << SurfaceMaterial::kMinRollingResistance << ", 5] for a surface the ball touches)";
    return s.str();
  }
  if (auto w = bad("crater_tilt", m.crater_tilt, SurfaceMaterial::kCraterTilt, "rad"); !w.empty()) return w;
  if (auto w = bad("layer_drag", m.layer_drag, SurfaceMaterial::kLayerDrag, "s/m"); !w.empty()) return w;
  if (auto w = bad("lie_friction", m.lie_friction, SurfaceMaterial::kLieFriction, ""); !w.empty()) return w;
  if (auto w = bad("lie_speed_loss", m.lie_speed_loss, SurfaceMaterial::kLieSpeedLoss, ""); !w.empty()) return w;
  return {};
}

double rolling_resistance_from_stimp(double stimp) {
  return kStimpReleaseSpeed * kStimpReleaseSpeed / (2.0 * kGravity * stimp);
}

double rolling_resistance_from_stimp(double stimp, double k) {
  if (!(k > 1e-9)) return rolling_resistance_from_stimp(stimp);
  return k * kStimpReleaseSpeed * kStimpReleaseSpeed / (kGravity * std::expm1(2.0 * k * stimp));
}

double effective_rolling_resistance(const SurfaceMaterial& m) {
  return m.stimp > 0.0 ? rolling_resistance_from_stimp(m.stimp) : m.rolling_resistance;
}

SurfaceMaterial default_fairway() {
  SurfaceMaterial m;
  m.name = "fairway";
  m.kind = SurfaceKind::Fairway;
  // A little firmer than Penner's green (e = 0.510 - 0.0375 v + 0.000903 v², 0.12 past 20 m/s).
  m.e.count = 6;
  m.e.speed = {0.0, 5.0, 10.0, 15.0, 20.0, 30.0, 0.0, 0.0};
  m.e.cor = {0.55, 0.42, 0.30, 0.22, 0.17, 0.15, 0.0, 0.0};
  m.mu = 0.4;
  // assets/materials.toml's fairway (its comment has the sources): a tour drive runs out
  // 15-25 yd, a 7-iron a few yards, a PW checks; the layer of grass and thatch keeps a flat
  // landing from running on twice as far as turf lets it.
  m.rolling_resistance = 0.16;
  m.crater_tilt = deg_to_rad(12.0);
  m.layer_drag = 0.01;
  return m;
}

namespace {

// The rigid bounce off a plane with normal n (the ground an infinite mass): solve_impact's
// Coulomb model with e_t = 0, in closed form. For a sphere on a fixed plane the collision
// matrix K = I/m + (R²/I)(I − n nᵀ) does not couple normal and tangent (K n = n/m, K t =
// (1/m + R²/I) t), so the sticking impulse, the cone test and the slip impulse are scalar
// formulas. Same impulse as solve_impact to rounding (test_ground.cpp checks it); a bounce
// costs ~60 flops instead of a 3x3 solve, and the crater's bisection below calls it 40 times.
/// The impulse of a ground bounce (N·s on the ball), and what the result reports of it.
struct GroundImpulse {
  Vec3 p = Vec3::Zero();
  double pn = 0.0;          ///< its normal part
  Vec3 pt = Vec3::Zero();   ///< its tangential part
  double e = 0.0;           ///< the normal COR used
  double gain = 0.0;        ///< p·u + ½ pᵀK p: minus the energy lost
  ContactKind contact = ContactKind::Grip;
  bool energy_limited = false;
};

GroundImpulse ground_impulse(const SurfaceMaterial& m, const Vec3& n, const Vec3& velocity, const Vec3& spin,
                             const BallProperties& ball) {
  GroundImpulse g;
  const double inv_m = 1.0 / ball.mass;
  const double k_t = inv_m + ball.radius * ball.radius / ball.inertia;  // tangential compliance
  const Vec3 r = -ball.radius * n;                                       // centre to contact
  const Vec3 u = velocity + spin.cross(r);
  const double un = u.dot(n);
  const Vec3 ut = u - un * n;
  const double ut_norm = ut.norm();
  g.e = m.e.at(-un);
  const double pn = -(1.0 + g.e) * un / inv_m;  // frictionless normal impulse
  Vec3 pt = -ut / k_t;                           // ends the slip (e_t = 0)
  if (ut_norm / k_t <= m.mu * pn) {
    g.contact = ContactKind::Grip;
  } else {
    pt = ut * (-m.mu * pn / ut_norm);  // at the cone, against the slip
    g.contact = ContactKind::Slip;
  }
  const auto gain = [&](double jn, const Vec3& jt) {  // p·u + ½ pᵀK p
    return jn * un + jt.dot(ut) + 0.5 * (jn * jn * inv_m + jt.squaredNorm() * k_t);
  };
  if (gain(pn, pt) > 0.0) {
    // As solve_impact: back toward the frictionless impulse until no energy is created
    // (unreachable for e <= 1, kept so the two never disagree).
    pt *= energy_limit_fraction(gain(pn, Vec3::Zero()), pt.dot(ut), 0.5 * pt.squaredNorm() * k_t);
    g.energy_limited = true;
  }
  g.p = pn * n + pt;
  g.pn = pn;
  g.pt = pt;
  g.gain = gain(pn, pt);
  return g;
}

ImpactResult bounce_impulse(const SurfaceMaterial& m, const Vec3& n, const Vec3& velocity, const Vec3& spin,
                            const BallProperties& ball) {
  const GroundImpulse g = ground_impulse(m, n, velocity, spin, ball);
  const double inv_m = 1.0 / ball.mass;
  const Vec3 r = -ball.radius * n;
  ImpactResult res;
  res.e_used = g.e;
  res.e_t_used = 0.0;
  res.contact = g.contact;
  res.energy_limited = g.energy_limited;
  res.impulse = g.p;
  res.normal_impulse = g.pn;
  res.tangential_impulse = g.pt.norm();
  res.impactor_after.inv_mass = 0.0;
  res.impactor_after.inv_inertia = Mat3::Zero();
  res.ball_after.inv_mass = inv_m;
  res.ball_after.inv_inertia = Mat3::Identity() * (1.0 / ball.inertia);
  res.ball_after.r = r;
  res.ball_after.velocity = velocity + inv_m * g.p;
  res.ball_after.angular_velocity = spin + r.cross(g.p) / ball.inertia;
  res.energy_loss = -g.gain;
  return res;
}

Vec3 tilted(const Vec3& face_normal, const Vec3& along, double tilt) {
  return std::cos(tilt) * face_normal - std::sin(tilt) * along;
}

}  // namespace

namespace {

/// A ball presses into turf `firmness` times as stiff as the material's own this many times
/// less deep (√stiffness for a turf spring). The crater's tilt and the share of the surface
/// layer a landing sweeps are both divided by it.
double depth_divisor(double firmness) { return firmness == 1.0 ? 1.0 : std::sqrt(firmness); }

/// crater_tilt_at() from sin 2θ of the incidence θ (a bounce has it from the velocity's
/// components without an atan2 and a sine: sin 2θ = 2·v_n·v_t / |v|²).
double crater_tilt_from(const SurfaceMaterial& m, double speed, double sin_2theta, double firmness) {
  if (m.crater_tilt <= 0.0) return 0.0;
  // Penner's tilt grows with speed and with incidence up to his 44.4°; a crater dug
  // straight down (90°) is symmetric and tilts nothing. sin 2θ carries both: linear in θ
  // for shallow landings (Penner's form), 1 at 45°, 0 at 90°. The tilt scales with the
  // crater's depth.
  const double shape = sin_2theta / kCraterReferenceShape;
  const double tilt = m.crater_tilt * (speed / kCraterReferenceSpeed) * shape / depth_divisor(firmness);
  return std::clamp(tilt, 0.0, std::min(2.0 * m.crater_tilt, 0.6));
}

}  // namespace

double crater_tilt_at(const SurfaceMaterial& m, double speed, double incidence, double firmness) {
  return crater_tilt_from(m, speed, std::sin(2.0 * incidence), firmness);
}

double layer_speed_loss(const SurfaceMaterial& m, double vt, double vn, double firmness) {
  if (m.layer_drag <= 0.0 || !(vt > 0.0)) return 0.0;
  return std::min(m.layer_drag * vt * vt * turf_layer_share(vn) / depth_divisor(firmness), 0.5 * vt);
}

BounceResult bounce_on_surface(const SurfaceMaterial& m, const Vec3& face_normal, const Vec3& velocity_in,
                               const Vec3& spin, const BallProperties& ball, double firmness) {
  BounceResult out;
  out.velocity = velocity_in;
  out.spin = spin;
  out.normal = face_normal;
  const double vn = velocity_in.dot(face_normal);
  if (vn >= 0.0) return out;  // not approaching: nothing to resolve

  // The layer of grass and thatch the ball sweeps through as it lands takes speed along the
  // surface first; the crater and the contact's friction then act on what is left.
  Vec3 velocity = velocity_in;
  if (m.layer_drag > 0.0) {
    const Vec3 along = velocity_in - vn * face_normal;
    const double speed_along = along.norm();
    const double loss = layer_speed_loss(m, speed_along, -vn, firmness);
    if (loss > 0.0) velocity -= (loss / speed_along) * along;
  }

  Vec3 n = face_normal;
  const Vec3 vt = velocity - vn * face_normal;
  const double vt_norm = vt.norm();
  if (m.crater_tilt > 0.0 && vt_norm > 1e-9) {
    // The ball digs a crater whose far wall faces back against the motion.
    const Vec3 along = vt / vt_norm;
    const double speed2 = vn * vn + vt_norm * vt_norm;
    const double tilt = crater_tilt_from(m, std::sqrt(speed2), 2.0 * -vn * vt_norm / speed2, firmness);
    // The far wall can stop a ball but not throw it back: only backspin can (Haake's balls
    // spun back only with backspin). Where the tilt would return a spinless ball of this
    // velocity backwards, it is lowered to the tilt that stops it dead.
    // (The impulse alone: the root search asks it ~10 times.)
    const auto forward = [&](const Vec3& normal) {
      const GroundImpulse g = ground_impulse(m, normal, velocity, Vec3::Zero(), ball);
      return (velocity + (1.0 / ball.mass) * g.p).dot(along);
    };
    n = tilted(face_normal, along, tilt);
    // Surely forward, without the impulse (one impulse a bounce is 1 % of a golf
    // shot): on the tilted plane a spinless ball keeps at least 5/7 of a forward tangential
    // speed v_t (grip leaves 5/7, slip more) and leaves along the normal at e·v_n ≤ v_n, so
    // its speed along the motion is at least (5/7)·v_t·cos α − v_n·sin α.
    const double cos_a = n.dot(face_normal), sin_a = -n.dot(along);
    const double v_t = vt_norm * cos_a + vn * sin_a, v_n = -vn * cos_a + vt_norm * sin_a;
    const bool surely_forward = v_t > 0.0 && (5.0 / 7.0) * v_t * cos_a >= v_n * sin_a;
    const double f_hi = tilt > 0.0 && !surely_forward ? forward(n) : 0.0;
    if (f_hi < 0.0) {
      // The tilt that stops it: the forward speed's root in tilt, bracketed by [0, tilt] (the
      // flat face sends a spinless ball forward), by regula falsi (8-12 impulses where 40
      // halvings take 40), within 1e-12 m/s of dead or 1e-13 rad of the root.
      const double stop = find_root([&](double t) { return forward(tilted(face_normal, along, t)); }, 0.0, tilt,
                                    forward(face_normal), f_hi);
      n = tilted(face_normal, along, stop);
    }
  }
  out.normal = n;
  out.impact = bounce_impulse(m, n, velocity, spin, ball);
  // What the layer took is lost to the turf as well.
  out.impact.energy_loss += 0.5 * ball.mass * (velocity_in.squaredNorm() - velocity.squaredNorm());
  out.velocity = out.impact.ball_after.velocity;
  out.spin = out.impact.ball_after.angular_velocity;
  return out;
}

bool ground_under(const Terrain& terrain, double x, double z, double from_y, double depth, SurfaceContact* hit) {
  // Through at most this many tree faces (a crown's top and bottom, a few crowns overlapping).
  constexpr int kMaxTreeFaces = 16;
  const double floor_y = from_y - depth;
  double top = from_y;
  for (int pass = 0; pass <= kMaxTreeFaces; ++pass) {
    if (pass > 0) *hit = SurfaceContact{};  // the cached support is the tree just passed
    if (!terrain.support(Vec3(x, top, z), 0.0, top - floor_y, hit)) return false;
    const Vec3& n = hit->normal;
    if (!(n.y() > 1e-6)) return false;  // a wall: no ground on this vertical
    const Vec3& p = hit->point;
    const double y = p.y() - (n.x() * (x - p.x()) + n.z() * (z - p.z())) / n.y();
    if (terrain.material(hit->material).kind != SurfaceKind::Tree) {
      hit->point = Vec3(x, y, z);
      return true;
    }
    top = std::min(top, y) - 1e-4;  // on down through the crown
    if (top <= floor_y) return false;
  }
  return false;
}

bool FlatGround::sweep(const Vec3& from, const Vec3& to, double radius, SurfaceContact* hit,
                       const Vec3* follow) const {
  if (follow != nullptr && follow->y() >= std::cos(kFollowAngle)) return false;
  if (!(to.y() < from.y())) return false;  // moving up or along the plane
  const double d0 = from.y() - height_ - radius;
  const double d1 = to.y() - height_ - radius;
  if (d1 > 0.0) return false;
  hit->fraction = d0 <= 0.0 ? 0.0 : d0 / (d0 - d1);
  const Vec3 c = from + hit->fraction * (to - from);
  hit->point = Vec3(c.x(), height_, c.z());
  hit->normal = Vec3::UnitY();
  hit->material = 0;
  return true;
}

bool FlatGround::support(const Vec3& centre, double radius, double reach, SurfaceContact* hit) const {
  if (centre.y() - height_ - radius > reach) return false;
  hit->fraction = 0.0;
  hit->point = Vec3(centre.x(), height_, centre.z());
  hit->normal = Vec3::UnitY();
  hit->material = 0;
  return true;
}

bool FlatGround::may_touch(const Vec3& from, const Vec3& to, double radius) const {
  return std::min(from.y(), to.y()) - height_ - radius <= 0.0;
}

}  // namespace sweetspot
