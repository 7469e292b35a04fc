// Equipment validation and the bat's profile look-ups.
#include "physics/equipment.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "physics/delivery.hpp"  // GolfSwing::kDynamicLoft: a club's default loft is a swing's
#include "physics/error.hpp"

namespace sweetspot {

namespace {

// Linear interpolation in a table of (x, y) with x increasing, held constant past the ends.
double interpolate(const std::vector<std::pair<double, double>>& t, double x) {
  if (t.empty()) return 1.0;
  if (x <= t.front().first) return t.front().second;
  for (size_t i = 1; i < t.size(); ++i) {
    if (x <= t[i].first) {
      const double f = (x - t[i - 1].first) / (t[i].first - t[i - 1].first);
      return t[i - 1].second + f * (t[i].second - t[i - 1].second);
    }
  }
  return t.back().second;
}

[[noreturn]] void fail(const std::string& who, const std::string& field, const std::string& range, double got,
                       double display_scale = 1.0, const char* unit = "") {
  std::ostringstream os;
  os << who << ": " << field << " must be " << range << ", got " << got * display_scale << unit;
  throw InputError(os.str());
}


}  // namespace

// A turned bat's surface has no corners: its radius is the shape-preserving cubic (Fritsch &
// Carlson, SIAM J. Numer. Anal. 17 (1980) 238; the tangents as Fritsch & Butland, 1984)
// through the profile's points. Its slope, which tilts the contact's normal, is continuous, so
// a contact 1 mm along the barrel turns the ball a little, never by a corner's 3-17 deg; the
// curve never swells past its points (a flat barrel stays flat, a taper never bulges).
double BatSpec::radius_at(double from_knob) const {
  const auto& p = barrel_profile;
  if (p.empty() || from_knob < p.front().first || from_knob > p.back().first) return 0.0;
  if (p.size() == 1) return p.front().second;
  std::size_t k = 0;
  while (k + 2 < p.size() && from_knob > p[k + 1].first) ++k;
  const auto secant = [&](std::size_t i) { return (p[i + 1].second - p[i].second) / (p[i + 1].first - p[i].first); };
  // The tangent at point i: the one-sided secant at the ends; inside, zero at a turn (a peak,
  // a trough, the end of a flat), else the weighted harmonic mean of the two secants.
  const auto tangent = [&](std::size_t i) {
    if (i == 0) return secant(0);
    if (i + 1 == p.size()) return secant(i - 1);
    const double a = secant(i - 1), b = secant(i);
    if (a * b <= 0.0) return 0.0;
    const double h0 = p[i].first - p[i - 1].first, h1 = p[i + 1].first - p[i].first;
    const double w0 = 2.0 * h1 + h0, w1 = h1 + 2.0 * h0;
    return (w0 + w1) / (w0 / a + w1 / b);
  };
  const double h = p[k + 1].first - p[k].first;
  if (!(h > 0.0)) return p[k + 1].second;
  const double t = (from_knob - p[k].first) / h, t2 = t * t, t3 = t2 * t;
  return (2.0 * t3 - 3.0 * t2 + 1.0) * p[k].second + (t3 - 2.0 * t2 + t) * h * tangent(k) +
         (-2.0 * t3 + 3.0 * t2) * p[k + 1].second + (t3 - t2) * h * tangent(k + 1);
}

double BatSpec::cor_factor_at(double from_tip) const { return interpolate(cor_profile, from_tip); }

double ClubSpec::face_cor_factor(double toe, double up) const {
  // A plateau that falls toward the rim, ∝ r⁴: variable-thickness faces keep their
  // spring-like effect over the middle and lose it where the face is welded to the body.
  // ESTIMATE of the shape: the one measured number we have is a robot's ~9 yd lost of 200
  // at 19 mm toe or heel (Golf Laboratories, reported), most of which the head's twist
  // explains by itself (effective mass 204 -> 178 g on a driver).
  const double x = toe / face_half_width, y = up / face_half_height;
  const double r2 = x * x + y * y;
  return std::max(0.05, 1.0 - cor_edge_drop * r2 * r2);
}

void validate_material(const ImpactMaterial& m, const std::string& what) {
  if (auto msg = validate_material_values(m); !msg.empty()) throw InputError(what + ": " + msg);
}

void validate_ball(const BallSpec& b) {
  const std::string who = "ball '" + b.name + "'";
  check_range(who + ": mass", b.mass, BallSpec::kMass, "kg");
  check_range(who + ": compliance.stiffness", b.compliance.stiffness, BallCompliance::kStiffness, "N/m^1.5");
  // Hertz contact time t ≈ 2.87 (m²/(k² v))^{1/5}: for a 46 g ball at 1 m/s (a putt) it
  // stays under ~8 ms only for k ≥ 1e5 N/m^1.5; a softer "ball" never leaves the face
  // within the solver's window and launches at 0 (a hostile balls.toml).
  if (b.compliance.stiffness != 0.0 && b.compliance.stiffness < BallCompliance::kMinStiffness)
    throw InputError(who + ": compliance.stiffness = " + std::to_string(b.compliance.stiffness) +
                     " N/m^1.5 is too soft (allowed: 0 for a rigid ball, or at least 1e5; a golf ball is ~2e7)");
  check_range(who + ": compliance.poisson", b.compliance.poisson, BallCompliance::kPoisson, "");
  check_range(who + ": compliance.shear_stiffness_ratio", b.compliance.shear_stiffness_ratio,
              BallCompliance::kShearStiffnessRatio, "");
  check_range(who + ": compliance.tangential_damping", b.compliance.tangential_damping, BallCompliance::kTangentialDamping, "");
  check_range(who + ": radius", b.radius, BallSpec::kRadius, "m");
  // A sphere's moment of inertia lies between a thin shell (2/3 m R²) and ... any
  // realistic core concentration (0.2 m R²).
  const double mr2 = b.mass * b.radius * b.radius;
  if (!(b.inertia >= 0.2 * mr2 && b.inertia <= (2.0 / 3.0) * mr2)) {
    std::ostringstream os;
    os << who << ": inertia must be in [0.2, 0.667]·m·R² = [" << 0.2 * mr2 << ", " << (2.0 / 3.0) * mr2
       << "] kg·m², got " << b.inertia;
    throw InputError(os.str());
  }
}

void validate_club(const ClubSpec& c) {
  const std::string who = "club '" + c.name + "'";
  check_range(who + ": loft", c.loft, ClubSpec::kLoft, "rad");
  check_range(who + ": lie", c.lie, ClubSpec::kLie, "rad");
  check_range(who + ": dynamic_loft", c.dynamic_loft, GolfSwing::kDynamicLoft, "rad");
  check_range(who + ": strike_height", c.strike_height, GolfSwing::kImpactUp, "m");
  check_range(who + ": shaft_tip_mass", c.shaft_tip_mass, ClubSpec::kShaftTipMass, "kg");
  check_range(who + ": head_mass", c.head_mass, ClubSpec::kHeadMass, "kg");
  if (!c.cg.allFinite() || c.cg.x() > 0.0 || c.cg.norm() > 0.1) {
    std::ostringstream os;
    os << who << ": cg must be finite, behind the face (x <= 0) and within 100 mm of the face centre, got ["
       << c.cg.x() * 1000 << ", " << c.cg.y() * 1000 << ", " << c.cg.z() * 1000 << "] mm";
    throw InputError(os.str());
  }
  if (auto msg = validate_mass_properties(c.head_mass, c.inertia, who); !msg.empty()) throw InputError(msg);
  check_range(who + ": bulge_radius", c.bulge_radius, ClubSpec::kFaceRadius, "m");
  check_range(who + ": roll_radius", c.roll_radius, ClubSpec::kFaceRadius, "m");
  check_range(who + ": length", c.length, ClubSpec::kLength, "m");
  check_range(who + ": face_half_width", c.face_half_width, ClubSpec::kFaceHalfSize, "m");
  check_range(who + ": face_half_height", c.face_half_height, ClubSpec::kFaceHalfSize, "m");
  check_range(who + ": cor_edge_drop", c.cor_edge_drop, ClubSpec::kCorEdgeDrop, "");
  validate_material(c.face, who + " face");
}

void validate_bat(const BatSpec& b) {
  const std::string who = "bat '" + b.name + "'";
  check_range(who + ": length", b.length, BatSpec::kLength, "m");
  check_range(who + ": mass", b.mass, BatSpec::kMass, "kg");
  check_range(who + ": cg_from_knob (inside the bat)", b.cg_from_knob, Range{0.0, b.length}, "m");
  check_range(who + ": inertia_cg", b.inertia_cg, BatSpec::kInertiaCg, "kg*m^2");
  check_range(who + ": inertia_axial (at most inertia_cg)", b.inertia_axial, Range{1e-6, b.inertia_cg}, "kg*m^2");
  check_range(who + ": pivot_from_knob (within half the length)", b.pivot_from_knob, Range{0.0, 0.5 * b.length}, "m");
  check_range(who + ": sweet_spot_from_tip (between the tip and 5 cm beyond the pivot)", b.sweet_spot_from_tip,
              Range{0.0, b.length - b.pivot_from_knob - 0.05}, "m");
  if (b.barrel_profile.size() < 2) throw InputError(who + ": barrel_profile needs at least 2 (from_knob, radius) points");
  for (size_t i = 0; i < b.barrel_profile.size(); ++i) {
    const auto [x, r] = b.barrel_profile[i];
    if (!(r > 0.0 && r <= 0.05)) fail(who, "barrel_profile radius", "in (0, 50] mm", r, 1000.0, " mm");
    if (!std::isfinite(x) || (i > 0 && !(x > b.barrel_profile[i - 1].first))) {
      throw InputError(who + ": barrel_profile distances must be finite and strictly increasing");
    }
  }
  if (std::abs(b.barrel_profile.front().first) > 1e-9 || std::abs(b.barrel_profile.back().first - b.length) > 1e-6) {
    throw InputError(who + ": barrel_profile must run from the knob (0 m) to the tip (length)");
  }
  for (size_t i = 0; i < b.cor_profile.size(); ++i) {
    const auto [x, f] = b.cor_profile[i];
    if (!(f > 0.0 && f <= 1.0)) fail(who, "cor_profile factor", "in (0, 1]", f);
    if (!std::isfinite(x) || (i > 0 && !(x > b.cor_profile[i - 1].first))) {
      throw InputError(who + ": cor_profile distances must be finite and strictly increasing");
    }
  }
  validate_material(b.material, who + " material");
}

}  // namespace sweetspot
