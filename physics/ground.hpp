// How the ball meets the ground: surface materials (turf, sand, dirt, walls), the bounce
// through the impact solver with the ground as an infinite mass, rolling resistance from a
// Stimpmeter reading, and the Terrain interface the flight state machine queries.
//
// Bounce (DESIGN §5): the ground is body 1 with inv_mass 0; the normal is the triangle's
// face normal, optionally tilted against the ball's motion by the turf crater it digs
// (Penner 2002, "The run of a golf ball": θc = 15.4° · (v/18.6 m/s) · (θin/44.4°) on a
// green), which is what lets a wedge check up or spin back. e falls with impact speed.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "physics/impact.hpp"
#include "physics/math.hpp"
#include "physics/range.hpp"

namespace sweetspot {

enum class SurfaceKind : std::uint8_t {
  Tee, Fairway, Rough, Sand, Green, Water, Dirt, Grass, WarningTrack, Wall, OutOfBounds,
  Decoration,  ///< drawn, never collided (flag, chalk lines)
  Tree,        ///< a tree's crown or trunk: struck in flight, never the ground under it
  Path,        ///< a paved path (a golf course's cart path)
};

const char* to_string(SurfaceKind k);
/// Parses "tee", "fairway", ..., "warning_track", "wall", "out_of_bounds"; false if unknown.
bool surface_kind_from_string(const std::string& s, SurfaceKind* out);
/// "tee, fairway, ..." for error messages.
std::string surface_kind_names();

/// A ground or wall material. Immutable parameters, SI.
struct SurfaceMaterial {
  std::string name = "fairway";
  SurfaceKind kind = SurfaceKind::Fairway;
  CorCurve e = CorCurve::constant(0.4);  ///< normal restitution vs normal impact speed (turf: ~0.5 slow, ~0.15 at 20 m/s); each point in ImpactMaterial::kE
  double mu = 0.4;                       ///< ball–surface Coulomb friction (Penner: 0.4 on a green)
  static constexpr Range kMu{0.0, 2.0};
  /// Rolling resistance: the rolling ball decelerates at rolling_resistance · g on the flat.
  /// Green (stimp 10 ft) ~0.055, fairway ~0.16, rough ~0.3, sand ~1. Ignored when stimp > 0.
  double rolling_resistance = 0.12;
  static constexpr Range kRollingResistance{0.0, 5.0};
  /// The least for a surface the ball can roll on (water and decorations excepted): a
  /// stimp-15 green, the fastest surface in golf, is ~0.037; 0.01 still stops any roll.
  static constexpr double kMinRollingResistance = 0.01;
  double stimp = 0.0;                    ///< m; Stimpmeter reading (tour greens 3.0–4.0 m); > 0 sets rolling_resistance
  /// When set (> 0): 0.5 m (shaggy) to 6 m, beyond the fastest greens ever measured (~4.3 m).
  static constexpr Range kStimp{0.5, 6.0};
  /// Turf crater tilt of the bounce normal, rad, at the reference impact (18.6 m/s at 44.4°
  /// incidence); Penner's green 0.269 (15.4°); 0 = rigid surface (walls, cart paths).
  double crater_tilt = 0.0;
  static constexpr Range kCraterTilt{0.0, 0.6};
  /// s/m; the inertia of the turf's surface layer (grass and thatch) that a landing ball
  /// sweeps aside: a bounce takes layer_drag · v_t² off the ball's speed along the surface,
  /// in full once the ball presses through the layer (turf_layer_share()). Poncelet's
  /// inertial term, ½ρ·A·v² over the contact time: see layer_speed_loss(). 0 = none (a
  /// green, whose bounce is Penner's measured crater alone; walls, paths, the ballpark).
  double layer_drag = 0.0;
  static constexpr Range kLayerDrag{0.0, 0.1};
  /// The lie: what the surface does to a strike of a ball resting on it. Grass trapped
  /// between face and ball lubricates the contact (the "flyer": spin falls 60-70 %, the
  /// launch rises), sand or long grass slows the club before it reaches the ball.
  double lie_friction = 1.0;             ///< factor on the face–ball µ; rough ~0.2, clean lies 1
  static constexpr Range kLieFriction{0.0, 1.0};
  double lie_speed_loss = 0.0;           ///< fraction of the club's speed lost before contact; rough ~0.03
  static constexpr Range kLieSpeedLoss{0.0, 0.9};
};

/// Empty when valid, otherwise a message naming the field and its allowed range.
std::string validate_surface_material(const SurfaceMaterial& m);

/// The Stimpmeter releases the ball at 1.83 m/s (6 ft/s); with a constant rolling
/// deceleration c·g the ball rolls v0²/(2cg), so c = v0² / (2 g stimp).
double rolling_resistance_from_stimp(double stimp);
/// The same when the air also slows the rolling ball, its deceleration k·v² (k in 1/m, the
/// along-ground drag per unit mass, 5/7 of it for a rolling sphere): a roll from v0 with
/// c·g + k v² covers ln(1 + k v0²/(c g)) / (2k), so c = k v0² / (g (e^{2k·stimp} − 1)).
/// The reading is what the green does with the air included; k = 0 is the plain formula.
double rolling_resistance_from_stimp(double stimp, double k);
/// rolling_resistance, or the Stimpmeter's value when stimp > 0.
double effective_rolling_resistance(const SurfaceMaterial& m);

/// A mown fairway: the surface of the flat default ground (world == nullptr).
SurfaceMaterial default_fairway();

/// Ball mass properties for flight and ground contact. Defaults: a golf ball (DESIGN §3);
/// a baseball is 0.145 kg, 0.0369 m, 7.90e-5 kg·m².
struct BallProperties {
  double mass = 0.04593;     ///< kg
  double radius = 0.021335;  ///< m
  double inertia = 8.36e-6;  ///< kg·m² (solid sphere 0.4 m R²)
};

/// DESIGN §3 balls as solid spheres: golf 45.93 g, Ø 42.67 mm; baseball 145 g, R 36.9 mm.
inline BallProperties golf_ball_properties() { return {0.04593, 0.021335, 0.4 * 0.04593 * 0.021335 * 0.021335}; }
inline BallProperties baseball_properties() { return {0.145, 0.0369, 0.4 * 0.145 * 0.0369 * 0.0369}; }

struct BounceResult {
  Vec3 velocity = Vec3::Zero();   ///< m/s after the bounce
  Vec3 spin = Vec3::Zero();       ///< rad/s after the bounce
  Vec3 normal = Vec3::UnitY();    ///< normal the impulse used (tilted by the crater)
  ImpactResult impact;
};

/// The crater's tilt of the bounce normal (rad) for an impact at `speed` (m/s) and
/// `incidence` (rad below the surface): crater_tilt · (speed / 18.6 m/s) · sin 2θ / sin 88.8°
/// / √firmness, at most twice crater_tilt and 0.6 rad. Penner 2002's reference impact
/// (18.6 m/s at 44.4°) returns crater_tilt; a vertical drop, 0. `firmness`: the turf's
/// stiffness relative to the material's (1 = as measured, 2 = twice as firm).
double crater_tilt_at(const SurfaceMaterial& m, double speed, double incidence, double firmness = 1.0);

/// The normal approach speed (m/s) at which a landing ball presses through the turf's
/// surface layer and meets all of its inertia. Derivation: a fairway's layer of mown grass
/// and thatch is ~12 mm deep and bears a resting ball (0.45 N) near its top; pressing the
/// ball through it takes ~10 N over those 12 mm, ~0.1 J, which is the normal energy of a
/// 45.93 g ball at ~2 m/s.
inline constexpr double kTurfLayerSpeed = 2.0;

/// The share (0..1) of the layer a touch at normal approach speed `vn` (m/s) sweeps through:
/// against a layer that resists with a steady force the ball presses in as deep as its normal
/// energy takes it, (vn / kTurfLayerSpeed)², all of it from kTurfLayerSpeed on. A rolling
/// ball's last hops (a few cm/s) skim it, so a hop that turns into a roll loses nothing to it
/// that the roll does not.
inline double turf_layer_share(double vn) {
  if (!(vn > 0.0)) return 0.0;
  const double r = vn / kTurfLayerSpeed;
  return r >= 1.0 ? 1.0 : r * r;
}

/// The speed (m/s) a bounce's sweep through the turf's layer takes off a ball meeting it at
/// tangential speed `vt` and normal approach speed `vn`: layer_drag · vt² · share / √firmness
/// (a firmer turf is pressed less deep, as its crater: crater_tilt_at), at most half of vt.
double layer_speed_loss(const SurfaceMaterial& m, double vt, double vn, double firmness = 1.0);

/// One bounce of a ball moving at `velocity` with `spin` onto a surface with unit face
/// normal `face_normal` (pointing out of the ground). Uses solve_impact() with the ground
/// as an infinite mass, e = m.e at the normal approach speed, e_t = 0, Coulomb friction,
/// on the plane tilted by crater_tilt_at() — lowered where it would return a spinless ball
/// backwards (only backspin brings a ball back) — after the turf's layer has taken
/// layer_speed_loss() off the speed along the surface. Never creates energy.
BounceResult bounce_on_surface(const SurfaceMaterial& m, const Vec3& face_normal, const Vec3& velocity,
                               const Vec3& spin, const BallProperties& ball, double firmness = 1.0);

/// Ground firmness range: from turf a quarter as stiff (soaked) to four times (baked).
inline constexpr Range kFirmness{0.25, 4.0};

/// A surface point the ball touches or rests on.
struct SurfaceContact {
  double fraction = 1.0;          ///< along the swept segment, 0..1
  Vec3 point = Vec3::Zero();      ///< m, on the surface
  Vec3 normal = Vec3::UnitY();    ///< unit face normal, out of the surface
  int material = 0;               ///< index into the terrain's materials
  int mesh = -1;                  ///< terrain-specific: collision mesh of the triangle (-1 none)
  int triangle = -1;              ///< terrain-specific: triangle within the mesh (-1 none)
};

/// Surfaces within this angle of the one a ball rolls on are followed, steeper ones struck.
inline constexpr double kFollowAngle = 20.0 * 3.14159265358979323846 / 180.0;

/// What the flight state machine asks of the ground. The flat default ground and the
/// Bullet World implement it. Queries are const but an implementation may keep scratch
/// state: one Terrain per thread.
class Terrain {
 public:
  virtual ~Terrain() = default;
  /// First surface a sphere of `radius` touches moving in a straight line from `from` to
  /// `to`, ignoring surfaces it is moving away from or along, and, when `follow` is given,
  /// surfaces within kFollowAngle of *follow (the ground a ball rolls on). False when none.
  virtual bool sweep(const Vec3& from, const Vec3& to, double radius, SurfaceContact* hit,
                     const Vec3* follow) const = 0;
  /// The surface under a ball resting or rolling at `centre` (within `reach` m below the
  /// ball's bottom). On entry *hit may hold the previous support (a cache hint). False
  /// when there is none (off the edge of the world's ground).
  virtual bool support(const Vec3& centre, double radius, double reach, SurfaceContact* hit) const = 0;
  /// Broad phase: false only when a sphere of `radius` on the segment certainly touches nothing.
  virtual bool may_touch(const Vec3& from, const Vec3& to, double radius) const = 0;
  /// The broad phase's bound itself: no surface under the segment's box grown by `radius`
  /// rises above this height (m; -inf when there is none). may_touch is min(from.y, to.y) -
  /// radius <= top_under. One query bounds every sub-segment inside the box, so a step's
  /// chords need no query of their own while they pass above it. +inf: no bound known.
  virtual double top_under(const Vec3& /*from*/, const Vec3& /*to*/, double /*radius*/) const {
    return std::numeric_limits<double>::infinity();
  }
  /// Broad phase for a rolling ball: false only when no surface steeper than kFollowAngle
  /// (a wall, a bank) can be touched.
  virtual bool may_touch_steep(const Vec3& from, const Vec3& to, double radius) const = 0;
  virtual const SurfaceMaterial& material(int index) const = 0;
  /// False once the ball has left the playable volume.
  virtual bool inside(const Vec3& centre) const = 0;
  /// Height (m) of the ground reference for wind profiles and carry (flat ground: 0).
  virtual double reference_height() const { return 0.0; }
  /// The normal a bounce at contact `c` uses: the surface the facets approximate, smooth
  /// across the edges between faces of one surface (flat ground: c.normal). A ball landing
  /// a hair to either side of an edge between two slightly different facets then bounces
  /// alike, instead of in two directions ~0.1° apart that later hops amplify into cm.
  virtual Vec3 bounce_normal(const SurfaceContact& c) const { return c.normal; }
  /// A touch `c` found by a sweep, given the ball's centre at the touch: where the sweep met
  /// two faces of one surface at their shared edge at the same instant it reports one of
  /// them; the touched face is the one the centre's foot lies on. Moves *c there (its
  /// material, a fairway's or the rough's, with it). Flat ground: nothing to do.
  virtual void refine_contact(const Vec3& /*centre*/, SurfaceContact* /*c*/) const {}
};

/// The ground straight below (x, from_y, z), searching `depth` m down: the surface's contact
/// with its point on that vertical line (Terrain::support's point is the foot along the
/// surface normal, which from far above lies metres aside on a slope). A tree over the spot
/// is looked through (the ground under a crown is the rough it stands in). False when none.
bool ground_under(const Terrain& terrain, double x, double z, double from_y, double depth, SurfaceContact* hit);

/// An infinite flat plane y = height of one material: the ground when no world is loaded.
class FlatGround final : public Terrain {
 public:
  explicit FlatGround(SurfaceMaterial m = default_fairway()) : material_(std::move(m)) {}
  /// `height`: y of the plane (m).
  FlatGround(SurfaceMaterial m, double height) : material_(std::move(m)), height_(height) {}
  bool sweep(const Vec3& from, const Vec3& to, double radius, SurfaceContact* hit,
             const Vec3* follow) const override;
  bool support(const Vec3& centre, double radius, double reach, SurfaceContact* hit) const override;
  bool may_touch(const Vec3& from, const Vec3& to, double radius) const override;
  double top_under(const Vec3&, const Vec3&, double) const override { return height_; }
  bool may_touch_steep(const Vec3&, const Vec3&, double) const override { return false; }
  double reference_height() const override { return height_; }
  const SurfaceMaterial& material(int) const override { return material_; }
  bool inside(const Vec3&) const override { return true; }

 private:
  SurfaceMaterial material_;
  double height_ = 0.0;
};

}  // namespace sweetspot
