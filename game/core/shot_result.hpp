// The plain result of one simulated shot: what the reports print, the UI shows and the game
// modes score. Filled by run_shot (game/rules/run_shot.hpp); reports only read it. All SI,
// angles in radians; display units are applied by the report writers.
#pragma once

#include <string>
#include <vector>

#include "physics/delivery.hpp"
#include "physics/flight.hpp"
#include "physics/impact.hpp"
#include "physics/launch.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

/// How the play ended, by the sport's rules (game/rules): the DESIGN §6 `flight.end`.
enum class ShotEnd : std::uint8_t {
  Rest,         ///< at rest in play
  Holed,        ///< golf: in the cup
  Water,        ///< golf: in a water hazard
  OutOfBounds,  ///< beyond the course's boundary or the world (golf), into the stands (baseball)
  HomeRun,      ///< baseball: over the fence in fair territory
  StepLimit,    ///< the physics ran out of time or steps (should not happen)
};
const char* to_string(ShotEnd e);

/// What the impact solve did. Absent (present = false) for launch-only shots.
struct ImpactSummary {
  bool present = false;
  double e = 0.0;                   ///< restitution the solver used at this approach speed (driver ~0.80)
  double e_t = 0.0;                 ///< tangential restitution: the rigid model's, or what the compliant contact produced
  double e_t_nominal = 0.0;         ///< the material's stated (rigid-model) e_t
  double mu = 0.0;                  ///< friction coefficient
  FrictionModel friction = FrictionModel::Coulomb;
  ContactKind contact = ContactKind::Frictionless;
  double normal_impulse = 0.0;      ///< N·s, a driver ~3.4 N·s
  double tangential_impulse = 0.0;  ///< N·s
  double energy_loss = 0.0;         ///< J lost in the impact (negative = created, textbook model)
  double contact_time = 0.0;        ///< s the ball was on the face or bat (impact with duration; 0 for the instantaneous impulse)
  /// The face µ above which the launch stops changing (game/modes/lab/grip.hpp); a tour driver
  /// ~0.2. Negative when not computed (it costs ~16 launches: `shot`, the Tuning panel and
  /// `sweep` ask for it, the game loop does not).
  double mu_grip = -1.0;
};

/// Golf delivery, in TrackMan's conventions (DESIGN §2); the ClubData of a GSPro message.
struct ClubNumbers {
  std::string club;                 ///< equipment name, "driver"
  double speed = 0.0;               ///< m/s club head speed (face centre), tour driver ~50.5
  double speed_at_impact = 0.0;     ///< m/s of the face at the contact point
  double attack_angle = 0.0;        ///< rad, + up
  double path = 0.0;                ///< rad, + in-to-out (right)
  double face_to_target = 0.0;      ///< rad, + open (right), at the face centre
  /// rad, + open, the face's direction where it meets the ball (the face-centre angle turned
  /// by the bulge at the strike): what TrackMan and the launch-monitor table call "face angle".
  double strike_face_angle = 0.0;
  double dynamic_loft = 0.0;        ///< rad, at the face centre
  /// rad, the face's loft where it meets the ball (the face-centre loft tilted by the roll at
  /// the strike): what TrackMan and the launch-monitor table call "dynamic loft".
  double strike_loft = 0.0;
  /// rad, the angle between the head's direction and the face's normal at the strike (3D:
  /// strike loft less attack for a face square to the path, more when it is open or shut).
  double spin_loft = 0.0;
  double lie = 0.0;                 ///< rad, the club's lie angle
  double impact_toe = 0.0;          ///< m from the face centre, + toward the toe
  double impact_up = 0.0;           ///< m from the face centre, + up
  double closure_rate = 0.0;        ///< rad/s, + closing
  double sand_entry = 0.0;          ///< m behind the ball where a splash entered the sand; 0: none
};

/// Baseball delivery.
struct BatNumbers {
  std::string bat;                  ///< equipment name, "maple"
  double speed = 0.0;               ///< m/s at the sweet spot, MLB average ~31.3 (70 mph)
  double speed_at_impact = 0.0;     ///< m/s of the bat at the contact point
  double attack_angle = 0.0;        ///< rad, swing plane, + up
  double direction = 0.0;           ///< rad, + toward right field
  double impact_from_tip = 0.0;     ///< m
  double undercut = 0.0;            ///< m, + ball centre above the bat axis
  double pitch_speed = 0.0;         ///< m/s, MLB fastball ~40 (90 mph)
  double pitch_spin = 0.0;          ///< rad/s
};

struct ShotResult {
  std::string scenario;             ///< built-in name or path
  std::string sport;                ///< the sport profile's name: "golf", "baseball"
  std::string world;                ///< world the shot flew on ("golf_hole", "ballpark", "none")
  double aim = 0.0;                 ///< rad, the target line turned right of the world's +x
  LaunchState launch_state;         ///< ball at separation (world frame)
  LaunchMetrics launch;             ///< launch-monitor numbers, relative to the aim line
  double smash_factor = 0.0;        ///< ball speed / impactor speed (0 for launch-only)
  ImpactSummary impact;
  ClubNumbers club;                 ///< club strikes only
  BatNumbers bat;                   ///< bat strikes only
  ShotTrajectory trajectory;        ///< sampled path and the physics summary
  ShotEnd end = ShotEnd::Rest;      ///< how the play ended, by the sport's rules
  /// Club head / bat at the instant of impact (mesh frame -> world), for rendering.
  ImpactorPose impactor_at_impact;
  bool has_impactor = false;        ///< false for launch-only shots
  std::string impactor_mesh;        ///< assets/meshes name of the club head or bat; "" when none
  ShotState final_state;            ///< the physics state the shot ended in (replays, the golden hash)
  /// What a player or coach should know about how far to trust this shot: the textbook
  /// friction model created energy, the launch is beyond what the aero model was fitted on.
  std::vector<std::string> warnings;
  std::string lie;                  ///< club strikes: the surface the ball was struck from ("tee", "rough", ...)
};

/// m right (+) of the target line (through the launch point, r.aim right of the world's +x)
/// at `p`: TrackMan's Side (landing) and Side Total (rest).
double side_of_aim(const ShotResult& r, const Vec3& p);

}  // namespace sweetspot
