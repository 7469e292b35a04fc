// The shot after launch: flight under gravity, drag, Magnus lift and spin decay (DESIGN §4),
// then bounces and roll on the ground (DESIGN §5) until the ball rests or leaves the world.
//
// Model and data are apart (as MuJoCo's mjModel / mjData): a ShotModel holds what does not
// change during a shot (ball, air, aero, ground, settings); a ShotState is the small plain
// state that step() advances. simulate_shot() is nothing but a loop over step(), so a game
// mode can run the same loop and read every event (landing, bounce, rest) as it happens,
// a replay can restart from any saved state, and a test can hash the state's bytes.
//
// The ball is moved by our own Dormand–Prince 5(4) integrator; the landing instant is the
// root of the ball's distance to the contact plane on the step's dense output, so carry
// converges to micrometres at the default tolerance instead of depending on a frame rate.
//
// Physics knows surfaces and geometry only. Game rules (a home run over the fence, out of
// bounds, a water hazard, a holed putt) read the events and the final state (game/rules).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "physics/aero.hpp"
#include "physics/cup.hpp"
#include "physics/atmosphere.hpp"
#include "physics/ground.hpp"
#include "physics/launch.hpp"
#include "physics/range.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

/// Integration and termination settings. The defaults aim at what a player sees, not at
/// round-off: carry within 4 mm of a 1e-13 reference, and the rest position
/// within 1 cm for every launch of a 1 000-launch random sample on golf_hole (worst 5.5 mm)
/// and for the tour launches (tests/unit/physics/test_flight_accuracy.cpp). With the carry's
/// steps ended at the aero law's kinks (air_step.cpp), rel_tol 4e-6 carries that sample
/// within 1.7 mm (95th percentile 0.8 mm); 1e-6 with a kink inside a step gives 3.5 mm.
struct FlightSettings {
  double rel_tol = 4e-6;         ///< integrator relative tolerance per step (the carry)
  static constexpr Range kRelTol{1e-14, 1e-2};
  double abs_tol = 1e-9;         ///< integrator absolute tolerance (m, m/s, rad/s)
  static constexpr Range kAbsTol{1e-15, 1e-2};
  /// Relative tolerance once the ball has landed (the hops after the carry); the carry
  /// itself always uses rel_tol. The bounces' own model error (turf e, µ) is ~1e-2; at
  /// 1e-3 a hop is one step and its rest error under a millimetre (the sample above).
  double bounce_rel_tol = 1e-3;
  static constexpr Range kBounceRelTol{1e-14, 1e-2};
  /// s; a step's position error is judged against the tolerance × the ball's speed × this
  /// time (at 70 m/s and 4e-6: 0.14 mm), not × its distance from the world's origin, so a
  /// shot is the same wherever the world sits. 0.5 s: carry error 0.9 mm worst over the
  /// accuracy sample (1.7 mm judged by the position), 1 % fewer instructions (README).
  double position_error_time = 0.5;
  static constexpr Range kPositionErrorTime{1e-6, 100.0};
  /// s; a shot that has not ended by then ends with StepLimit. Five minutes: a ball creeping
  /// down a long slope whose pull barely beats the turf's rolling resistance (a = g(sinθ −
  /// c cosθ) of a few mm/s²) takes minutes to stop or leave (random-world soak).
  double max_time = 300.0;
  static constexpr Range kMaxTime{0.0, 600.0, true};
  int max_steps = 200000;        ///< integrator + roll steps bound
  static constexpr Range kMaxSteps{1.0, 1e7};
  double roll_speed = 0.25;      ///< m/s; a bounce leaving slower than this along the normal starts the roll
  static constexpr Range kRollSpeed{0.0, 5.0};
  double rest_speed = 0.02;      ///< m/s; below it a ball that the slope cannot move is at rest
  static constexpr Range kRestSpeed{0.0, 1.0, true};
  /// The turf's stiffness relative to the world's materials (1 = as measured): firmer turf
  /// digs shallower craters (crater_tilt_at). 0.25 soaked ... 4 baked; range kFirmness.
  double ground_firmness = 1.0;
  /// m; the greens' Stimpmeter reading for this shot, 0 = the world's own.
  double green_stimp = 0.0;      ///< range SurfaceMaterial::kStimp when set
};

/// What a shot flies through and lands on: read-only while it runs. Make it with
/// make_shot_model(), which validates the inputs and derives the air density once.
struct ShotModel {
  BallProperties ball;                ///< golf ball by default
  const AeroModel* aero = nullptr;    ///< required
  Environment environment;            ///< air and wind
  const Terrain* terrain = nullptr;   ///< never null after make_shot_model (flat fairway by default)
  FlightSettings settings;
  std::optional<Cup> cup;             ///< the hole on the green, when the world has one (golf)
  double air_density = 0.0;           ///< kg/m³, from environment
  double air_viscosity = 1.81e-5;     ///< Pa·s, from environment (Sutherland)
  /// Side force of a seam-shifted wake (a pitched baseball): ½ρA·C_s·|v_r|² along v̂_r × m̂,
  /// m̂ the Magnus force's direction, so across both the flow and the Magnus force. A pitch
  /// thrown with its seams held in one orientation to the flow separates asymmetrically
  /// whatever its spin (Smith, Nathan & Pavlidis, "Not just about Magnus anymore", Baseball
  /// Prospectus 2020); the orientation rides on the spin axis, so the force keeps its place
  /// beside the Magnus force. 0 = none (a golf ball's dimples have no orientation, and no grip
  /// sets a batted ball's seams to the flow). Set with set_seam_side_force().
  double seam_side_force = 0.0;
  /// No larger than a baseball's largest Magnus coefficient (Nathan's saturating C_L tends to
  /// 0.48) turned by 45°: a wake as strong as the Magnus force.
  static constexpr Range kSeamSideForce{-0.5, 0.5};
};

/// Sets a pitch's seam-wake coefficient (ShotModel::seam_side_force); InputError naming
/// flight.seam_side_force and its range when out of it.
void set_seam_side_force(ShotModel& model, double c_s);

/// Validates (throws InputError naming the field and its range) and builds the model.
/// `terrain` == nullptr is an infinite flat fairway at y = 0 (flight without a world); the
/// terrain and aero model must outlive the model.
ShotModel make_shot_model(const BallProperties& ball, const AeroModel& aero, const Environment& environment,
                          const Terrain* terrain, const FlightSettings& settings = {});

/// Where the ball is and what it is doing. Plain data: copy it, save it, hash its bytes,
/// restart from it. Advanced only by step().
struct ShotState {
  double t = 0.0;                     ///< s since launch
  Eigen::Matrix<double, 9, 1> y = Eigen::Matrix<double, 9, 1>::Zero();  ///< position m, velocity m/s, spin rad/s
  Phase phase = Phase::Flight;        ///< Flight until the first touch, Bounce while airborne after it
  bool ended = false;                 ///< true once at rest, out of the world, or out of budget
  EndReason end = EndReason::Rest;    ///< valid once ended
  bool landed = false;                ///< has touched the ground
  bool skidding = false;              ///< Roll: the skid to pure rolling is still to come
  bool over_cup = false;              ///< rolled over the hole and out: ignore it until clear of it
  int bounces = 0;
  int slow_touches = 0;               ///< consecutive touches slower than roll_speed (a wedged ball)
  /// Crease detection: consecutive gentle touches alternating between two faces (airborne),
  /// or crossings back and forth over one edge (rolling); the face the ball was last on.
  int chatter = 0;
  Vec3 last_touch_normal = Vec3::Zero();
  /// The velocity of the last such crossing while rolling: a ball rocks in a valley when it
  /// crosses back (against its last crossing's direction), not when it rolls on across a
  /// run of facets whose slopes alternate (a terrain mesh's two triangles a grid cell).
  Vec3 last_cross_velocity = Vec3::Zero();
  /// Consecutive steps that did not advance the clock (a ball the faces hold, passed from a
  /// touch to a roll and back at one instant): see step().
  int stalled = 0;
  /// Consecutive air steps in free flight (no surface touched) that did not advance the
  /// clock: see air_step().
  int stalled_in_air = 0;
  /// s; the last time the ball was in the air or rolling at rest_speed or faster (a ball
  /// slower than that for half a second is asleep: see step()).
  double sleep_since = 0.0;
  /// Roll in a crease: the two faces that hold the ball (both zero when not in one). The
  /// ball moves along their line n1 × n2 only (physics/detail/roll_step.cpp).
  Vec3 crease_n1 = Vec3::Zero(), crease_n2 = Vec3::Zero();
  double max_height = 0.0;            ///< m, highest ball centre so far (exact, on the dense output)
  /// Bounce: the share (0..1) of the roll's resistance this hop still feels in the surface's
  /// contact layer, fixed at the bounce from its apex (physics/detail/flight_steps.hpp).
  double hop_layer = 0.0;
  SurfaceContact support;             ///< Roll/Rest: the surface under the ball
  // Integrator carry (DopriCarry<9>): next trial step and the first-same-as-last derivative.
  double step_size = 0.01;            ///< s; 0: the next air step chooses its own (a launch)
  Eigen::Matrix<double, 9, 1> rate = Eigen::Matrix<double, 9, 1>::Zero();
  bool rate_valid = false;
  FlightStats counters;               ///< work done so far (budget and benchmarks)

  Vec3 position() const { return y.segment<3>(0); }
  Vec3 velocity() const { return y.segment<3>(3); }
  Vec3 spin() const { return y.segment<3>(6); }
};

/// The state at launch.
ShotState start_state(const LaunchState& launch);

enum class ShotEventKind : std::uint8_t {
  Step,       ///< moved; nothing else happened
  Landing,    ///< first touch of the ground (carry ends here); the bounce is already applied
  Bounce,     ///< a later touch of a surface while airborne (or a wall while rolling)
  Roll,       ///< the bounce left the ball on the ground: it rolls from here
  Airborne,   ///< a rolling ball left the ground (an edge, a crest)
  Rest,       ///< came to rest (or sank: a water surface holds the ball where it lands)
  LeftWorld,  ///< left the world's bounds, or rolled off its ground
  StepLimit,  ///< ran out of time or steps (should not happen for sane input)
  InCup,      ///< dropped into the hole
  LipOut,     ///< crossed the hole too fast, or struck the flagstick, and went on
};
const char* to_string(ShotEventKind k);

struct ShotEvent {
  ShotEventKind kind = ShotEventKind::Step;
  SurfaceContact contact;             ///< Landing, Bounce, Roll, Rest: the surface touched
  Vec3 velocity_in = Vec3::Zero();    ///< Landing, Bounce: the ball's velocity just before the touch
};

/// Advances `state` by one integrator step (airborne) or one roll step, stopping early at
/// a contact, a rest or time `until` (s). Returns what happened. Never throws for a model
/// made by make_shot_model() except InputError when the state turns non-finite (input far
/// outside the models' validity). Deterministic.
ShotEvent step(const ShotModel& model, ShotState& state,
               double until = std::numeric_limits<double>::infinity());

/// The position on one airborne step's path at time t in [t0, t1], from the positions and
/// velocities at its ends (cubic Hermite; exact while the acceleration is constant, within
/// ~1 mm over a 0.3 s step of a real flight). Rules use it to place a crossing (the fence).
Vec3 flight_position_between(const Vec3& p0, const Vec3& v0, double t0, const Vec3& p1, const Vec3& v1,
                             double t1, double t);

/// Builds the sampled path and the summary of DESIGN §6 from the states a loop over step()
/// visits. Samples every `interval` s on airborne stretches (rendering) plus every roll
/// step and event; `record_samples` false keeps only the summary (sweeps, benchmarks).
class TrajectoryRecorder {
 public:
  TrajectoryRecorder(const ShotState& launch, bool record_samples, double interval = 1.0 / 60.0);
  /// After each step: the state before it, after it, and its event.
  void add(const ShotState& before, const ShotState& after, const ShotEvent& event);
  /// The trajectory ending at `last` (its end reason and rest position).
  ShotTrajectory finish(const ShotState& last);
  /// The same, and a ball that left the world's bounds in the air is flown on over open,
  /// flat ground at the field's level (the terrain's reference height) with `model`'s air:
  /// its carry, hang time, landing angle and apex are where it would have come down, as
  /// Statcast projects a home run's distance to field level. Its rest position stays where
  /// it left the world; its total is that carry.
  ShotTrajectory finish(const ShotState& last, const ShotModel& model);

 private:
  ShotTrajectory out_;
  Vec3 launch_;
  bool record_;
  double interval_;
  double next_sample_ = 0.0;
};

/// Flies, bounces and rolls the ball to the end: start_state + step() until ended, recorded.
/// Throws InputError for an invalid launch (speed or spin beyond LaunchState's ranges).
ShotTrajectory simulate_shot(const ShotModel& model, const LaunchState& launch, bool record_samples = true);

/// Empty when `launch` is flyable (finite, within LaunchState's ranges), otherwise a message
/// naming the launch value and its range.
std::string validate_launch(const LaunchState& launch);

}  // namespace sweetspot
