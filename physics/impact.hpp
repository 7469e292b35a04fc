// The impulse solver (DESIGN §3): two rigid bodies meet at a point; one impulse p on the
// ball (−p on the impactor) resolves the impact under a restitution and friction model.
//
// Conventions: body 1 is the impactor (club head, bat, or the ground with inv_mass 0),
// body 2 the ball. The unit normal n points from the impactor into the ball. r1, r2 run
// from each CG to the contact point. u = (v2 + ω2×r2) − (v1 + ω1×r1) is the ball's
// contact velocity relative to the impactor; the bodies approach when u·n < 0.
//
// solve_impact() is the hot path: allocation-free, no throw, assumes validate_impact()
// passed. Call validate_impact() once where parameters enter (scenario load, UI edit).
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "physics/body.hpp"
#include "physics/math.hpp"
#include "physics/range.hpp"

namespace sweetspot {

enum class FrictionModel {
  None,      ///< frictionless: reproduces the textbook's worked examples exactly
  Textbook,  ///< Bourg ch. 5: tangential impulse µ·jn always, in full; can reverse sliding and CREATE energy
  Coulomb,   ///< default: grip if the sticking impulse fits the friction cone, else slip
};

enum class ContactKind { Grip, Slip, Frictionless };

/// How a delivery resolves the strike: with duration through the ball's compliant contact
/// layer (physics/compliant_impact.hpp, the default), or as one instantaneous impulse
/// (solve_impact below: the textbook's model and the compliant one's limit).
enum class ImpactModel { Compliant, Rigid };
const char* to_string(ImpactModel m);
/// "compliant", "rigid"; false when unknown.
bool impact_model_from_string(std::string_view name, ImpactModel* out);

const char* to_string(FrictionModel m);
const char* to_string(ContactKind k);
/// The one parser of friction model names ("none", "textbook", "coulomb"); false when
/// `name` is none of them (callers refuse it naming their key and friction_model_names()).
bool friction_model_from_string(std::string_view name, FrictionModel* out);
/// "none, textbook, coulomb", for messages and the schema.
std::string friction_model_names();

/// Normal coefficient of restitution as a function of normal approach speed, a piecewise
/// linear table held constant past its ends. Ball COR falls as impact speed rises (a golf
/// ball ~0.83 at 40 m/s and ~0.78 at 55 m/s; turf ~0.6 when dropped, ~0.3 at 20 m/s).
/// A single point is a constant e. Fixed capacity so the solve never allocates.
struct CorCurve {
  static constexpr int kMaxPoints = 8;
  std::array<double, kMaxPoints> speed{};  ///< m/s, strictly increasing
  std::array<double, kMaxPoints> cor{};    ///< e at that speed, each in [0, 1]
  int count = 1;                           ///< number of used points, 1..kMaxPoints

  static CorCurve constant(double e) {
    CorCurve c;
    c.cor[0] = e;
    return c;
  }
  /// e at normal approach speed `vn` (m/s, ≥ 0).
  double at(double vn) const;
};

/// Contact material pair: restitution and friction between impactor and ball.
struct ImpactMaterial {
  CorCurve e = CorCurve::constant(0.83);  ///< normal restitution; USGA limit for a driver face is 0.830
  static constexpr Range kE{0.0, 1.0};     ///< every point of the curve; 1 = perfectly elastic
  /// Tangential restitution of the instantaneous (rigid) model: 0 = the ball rolls off the
  /// face, > 0 it leaves over-spinning. The impact with duration does not read it: there the
  /// tangential rebound comes out of the contact's shear spring (compliant_impact.hpp).
  double e_t = 0.0;
  static constexpr Range kEt{0.0, 1.0};
  ImpactModel model = ImpactModel::Compliant;  ///< the textbook friction model is always rigid
  double mu = 0.4;    ///< Coulomb friction coefficient; club face/ball ~0.35–0.45, ball/bat ~0.5
  /// Rubber on rough rock reaches ~1; 2 leaves room for tests of the grip limit.
  static constexpr Range kMu{0.0, 2.0};
  FrictionModel friction = FrictionModel::Coulomb;
};

/// One body as the solver sees it, all world frame. Use inv_mass 0 and a zero inverse
/// inertia for an immovable body (the ground).
struct ImpactBody {
  double inv_mass = 0.0;                     ///< 1/kg
  Mat3 inv_inertia = Mat3::Zero();           ///< world-frame inverse inertia about the CG, 1/(kg·m²)
  Vec3 r = Vec3::Zero();                     ///< m; CG → contact point
  Vec3 velocity = Vec3::Zero();              ///< m/s of the CG
  Vec3 angular_velocity = Vec3::Zero();      ///< rad/s
};

struct ImpactInput {
  ImpactBody impactor;        ///< body 1
  ImpactBody ball;            ///< body 2
  Vec3 normal = Vec3::UnitX();///< unit, from impactor into ball
  ImpactMaterial material;
};

struct ImpactResult {
  Vec3 impulse = Vec3::Zero();     ///< N·s, applied to the ball (−impulse to the impactor)
  double normal_impulse = 0.0;     ///< N·s, impulse·n (≥ 0)
  double tangential_impulse = 0.0; ///< N·s, magnitude of the tangential part
  double e_used = 0.0;             ///< the restitution the curve gave at this approach speed
  double e_t_used = 0.0;           ///< the tangential restitution: e_t (rigid) or what the contact produced (compliant)
  ContactKind contact = ContactKind::Frictionless;
  double energy_loss = 0.0;        ///< J, kinetic energy before − after (negative = created)
  /// Coulomb only. True when the model's impulse would have CREATED kinetic energy and was
  /// pulled back toward the frictionless impulse until it did not. Independent normal and
  /// tangential restitution (e ≠ e_t) are not energy-consistent when K couples the normal
  /// and tangential directions strongly (a far off-centre CG, Kane's paradox); for club,
  /// bat and ground impacts this does not happen (tests check it). When set, a "grip"
  /// contact leaves the tangential velocity between −e_t·u_t and the frictionless value.
  bool energy_limited = false;
  ImpactBody impactor_after;       ///< post-impact velocities (r and inertia unchanged)
  ImpactBody ball_after;
};

/// The energy limit of a Coulomb impulse: along p(λ) = p_frictionless + λ q the kinetic
/// energy gain is a + bλ + cλ² with a ≤ 0 (the frictionless end never creates energy);
/// returns the largest λ in [0, 1] where the gain is still ≤ 0 (solve_impact and the closed-
/// form ground bounce both pull an energy-creating impulse back by it).
double energy_limit_fraction(double a, double b, double c);

/// Collision matrix K: an impulse p on the ball changes u by K p.
Mat3 collision_matrix(const ImpactBody& impactor, const ImpactBody& ball);

/// Relative contact velocity u of the ball with respect to the impactor.
Vec3 contact_velocity(const ImpactBody& impactor, const ImpactBody& ball);

/// Solves one impact. Requires validate_impact(in) to have passed.
ImpactResult solve_impact(const ImpactInput& in) noexcept;

/// Returns an empty string when `in` is a valid impact, otherwise a message naming the
/// offending field and its allowed range (mass ≤ 0, inertia not symmetric positive
/// definite, e or e_t outside [0, 1], µ < 0, non-unit normal, bodies separating, NaN).
std::string validate_impact(const ImpactInput& in);

/// Empty when every value of `m` is in its range (e curve points in kE, e_t in kEt, mu in
/// kMu, table speeds increasing); otherwise a message naming the impact.* key and range.
std::string validate_material_values(const ImpactMaterial& m);

/// validate_impact() + solve_impact(); throws InputError with the message on bad input.
ImpactResult solve_impact_checked(const ImpactInput& in);

/// Kinetic energy of an ImpactBody given its inverse mass properties (0 for immovable).
double kinetic_energy(const ImpactBody& b);

/// Empty when `mass` (kg) is > 0 and finite and `inertia` (kg·m²) is finite, symmetric and
/// positive definite; otherwise a message naming `what` and the violated condition.
std::string validate_mass_properties(double mass, const Mat3& inertia, const std::string& what);

/// The solver's view of a rigid body touching the contact point `contact` (world, m):
/// inverse mass, world-frame inverse inertia, r = contact − CG and the body's velocities.
/// Throws InputError naming `what` when the mass properties are invalid.
ImpactBody make_impact_body(const RigidBody& body, const Vec3& contact, const std::string& what);

}  // namespace sweetspot
