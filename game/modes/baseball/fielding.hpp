// Fielders who field (DESIGN §9): nine fielders at their positions (shaded toward the
// batter's pull side), each with a reaction, a sprint speed and an arm from Statcast's
// distributions, run to the ball; a catch in the air is decided by the time the ball gives
// against the time the fielder needs (catch probability, calibrated to Statcast's star
// bands); a ball on the ground is an out when the first fielder to reach it can throw to
// first before the batter arrives, and otherwise the batter takes the bases the throws
// cannot beat him to. Misplays at the league's error rate.
#pragma once

#include <array>
#include <string>

#include "game/modes/baseball/throwing.hpp"
#include "game/rules/run_shot.hpp"
#include "game/util/rng.hpp"
#include "physics/aero.hpp"
#include "physics/atmosphere.hpp"

namespace sweetspot {

enum class BattedOutcome { Strike, Foul, Out, Single, Double, Triple, HomeRun, Error };
const char* to_string(BattedOutcome o);

/// Statcast's batted-ball types by launch angle: ground ball < 10°, line drive 10–25°, fly
/// ball 25–50°, pop-up > 50°.
enum class BattedBallType { GroundBall, LineDrive, FlyBall, PopUp };
BattedBallType batted_ball_type(double launch_angle);
const char* to_string(BattedBallType t);

/// The field: 90 ft between the bases (MLB Rule 2.01), home plate at the origin, +x toward
/// the mound, first base toward +z.
inline constexpr double kBaseLine = 27.432;  // m
/// Home (0), first (1), second (2), third (3) base.
Vec3 base_position(int base);
/// Rule 2.01: 60 ft or more from the base lines to the stands in foul ground, and from home
/// plate to the backstop: a foul fly that lands past this is in the stands.
inline constexpr double kFoulGround = 18.288;  // m

struct FielderAbility {
  double reaction = 0.3;  ///< s after contact before he moves
  double accel = 4.0;     ///< m/s² up to his top speed
  double sprint = 8.23;   ///< m/s top speed
  double reach = 1.5;     ///< m his glove covers with a dive
  double arm = 38.0;      ///< m/s release speed of a throw
};

/// A team's nine in scorer's order: P, C, 1B, 2B, SS, 3B, LF, CF, RF.
struct Defense {
  std::array<FielderAbility, 9> ability;
};
inline constexpr std::array<const char*, 9> kPositionNames{"P", "C", "1B", "2B", "SS", "3B", "LF", "CF", "RF"};
inline constexpr int kPitcher = 0;       ///< kPositionNames' index of the pitcher
inline constexpr int kFirstBaseman = 2;  ///< and of the first baseman

/// The league's means: Statcast 2024 sprint speed and arm strength by position. Outfielders
/// react in 0.3 s and accelerate at 4 m/s² (Statcast's 3 s "jump", 34 ft on average);
/// infielders, in their ready hop at contact, in 0.2 s at 5 m/s² with a 1.8 m dive (ESTIMATES:
/// a sprinter's first-second acceleration is 6-8 m/s²).
Defense league_defense();
/// A team drawn around the league's means with Statcast's spreads (sprint speed sd ~1.2 ft/s,
/// arm strength sd ~2.5 mph, reaction sd 0.05 s; ESTIMATES of the leaderboards' spreads).
Defense draw_defense(Rng& rng);

/// Where each fielder stands for a batter: standard depths, shaded toward his pull side
/// (outfielders 4°, middle infielders 3°: ESTIMATE of a straight-up alignment's shade under
/// the 2023 shift rules, Rule 5.02(c), two infielders each side of second base).
std::array<Vec3, 9> fielder_spots(bool batter_left);

struct FieldingPlay {
  BattedOutcome outcome = BattedOutcome::Foul;
  BattedBallType type = BattedBallType::GroundBall;
  int fielder = -1;              ///< 0..8 (kPositionNames), -1 for none (a home run, a foul in the stands)
  bool caught = false;           ///< caught in the air: an out (fair or foul)
  bool foul = false;
  /// A foul no one catches: when (s after contact) and where the umpire calls it (where it
  /// first lands beyond the bases; before them, where it passes them, is touched or stops).
  /// The ball is dead there (Rule 5.06(c)(5)): its roll on up the line is no play.
  double called_time = 0.0;
  Vec3 called_at = Vec3::Zero();
  double catch_probability = 0.0;///< the best fielder's chance on a ball in the air
  bool error = false;
  Vec3 fielded_at = Vec3::Zero();///< where the fielder has the ball
  double fielded_time = 0.0;     ///< s after contact
  /// s after contact when he is set to throw: when he has the ball if he got there with time
  /// to settle, later when he must first stop his run or get up from a dive (ground_pickup).
  double ready_time = 0.0;
  double batter_to_first = 4.47; ///< s, his home-to-first time
  /// The base (2 or 3) where the throw gets the batter stretching his hit, 0 when it does not:
  /// the hit is his (`outcome`), and the out (the game's base running records it).
  int batter_out_at = 0;
  /// Who has the ball at first on a ground out (kPositionNames' index): the first baseman
  /// (unassisted on his own ball), or the pitcher he tossed it to; -1 when no play was made.
  int out_at_first_by = -1;
  std::array<Vec3, 9> start{}, goal{};  ///< each fielder's spot and where he runs (drawing)
  std::string description;       ///< "Fly out to CF", "Double to RF", ...
};

/// Fair or foul (MLB Rule definitions): beyond the bases, where it first lands; before them,
/// where it passes the bases, is first touched by a fielder of `defense` (standing at his spot
/// for a batter on that side; none: untouched) or comes to rest; into the stands, by where it
/// came down (a fair ball bounced into them is a ground-rule double, field_play).
bool is_fair_ball(const ShotResult& shot, const Defense* defense = nullptr, bool batter_left = false);

/// s: how far the defence's real time for a throw and tag runs from what a runner or coach
/// can judge at the moment he goes: the throw's line and hop, the catch and the tag (ESTIMATE:
/// a catcher's pop time to second spreads ~0.1 s, Statcast 2023; an outfielder's throw from
/// the run, its bounce and the tag sweep add about as much again). A runner sent on the
/// estimate is out when the throw as it comes beats him.
inline constexpr double kThrowSpread = 0.2;

/// s from the throw in the glove at a base to the tag on a sliding runner: the glove sweeps
/// from the catch down to his hand or foot, ~0.5 m at the ~4 m/s of a quick tag, and the
/// fielder must see where he slides (ESTIMATE). A force play needs only the ball at the bag.
inline constexpr double kTagTime = 0.15;

/// Who takes a throw at `base` (1..3, 4 = home) on a ball `fielder` played (kPositionNames'
/// index): the catcher at home; at third the third baseman, the shortstop when the third
/// baseman fielded it; at second the second baseman on a ball to the left side (SS, 3B, LF)
/// and the shortstop otherwise; at first the first baseman. It can be the fielder himself (the
/// first baseman at first): an unassisted play.
int covering_fielder(int base, int fielder);

/// Seconds a runner loses rounding a base (ESTIMATE), for the batter and the runners alike.
inline constexpr double kBaseRoundingTime = 0.3;

/// How long a fielder needs to cover `distance` m (reaction, acceleration, top speed, the
/// glove's reach).
double fielder_run_time(const FielderAbility& f, double distance);
/// His speed when he has covered `distance` m from a standstill (to within his reach).
double run_speed(const FielderAbility& f, double distance);
/// Statcast's catch probability as a function of the time to spare (s, + ahead of the ball,
/// against the run the fielder's reaction, acceleration and top speed allow): a normal ogive
/// with a 0.4 s spread (kCatchSpread) centred a quarter-second ahead, so a catch that takes
/// everything he has is about a 5-star play (Statcast: ≤ 25 %; here 27 %), half a second short
/// is near hopeless (3 %) and a second to spare is routine (97 %). The quarter-second: the route's
/// inefficiency and the last steps' slowing under the ball (ESTIMATE).
double catch_probability(double time_to_spare);

/// A ball on the ground fielded on the run (`arrive_speed` m/s along `run_dir`, unit, horizontal)
/// with `slack` s to spare: he spends the slack slowing down, then must stop the part of his
/// run that carries him away from his throw (`throw_dir`) before he can throw. Seconds lost.
double plant_time(const FielderAbility& f, double arrive_speed, double slack, const Vec3& run_dir, const Vec3& throw_dir);

/// Fields a batted ball on the ballpark. `batter_sprint` (m/s) sets his home-to-first time
/// (Statcast's 4.47 s league mean at 27 ft/s). With `rng`, catches and misplays are drawn;
/// without it the likelier result is taken (a catch at ≥ 50 %, no errors).
FieldingPlay field_play(const ShotResult& shot, const AeroModel& aero, const Environment& env, const Defense& defense,
                        bool batter_left, double batter_sprint, Rng* rng);

/// field_play() for the league's defense and a right-handed batter of average speed, no
/// draws: the outcome and who made the play.
BattedOutcome field_ball(const ShotResult& shot, const AeroModel& aero, const Environment& env,
                         std::string* fielder = nullptr);

/// The batted ball's path as the play went: a ball caught in the air ends in the fielder's
/// glove at the catch, a fair ball he fields on the ground where he picks it up (the physics'
/// path past him, rolling to the wall or into the seats, was never played); a home run, a
/// foul no one catches ends where it is called (FieldingPlay::called_at), and a ball at rest
/// before he gets there keeps the physics' whole path.
ShotTrajectory as_played(const ShotTrajectory& t, const FieldingPlay& play);
/// as_played(t, play).summary.rest_position, without the copy: where the play left the ball.
Vec3 play_rest_position(const ShotTrajectory& t, const FieldingPlay& play);

/// A foul tip's path as the play went: into the catcher's mitt where it comes level with him
/// behind the plate (the physics' flight on to the backstop was never played).
ShotTrajectory into_the_mitt(const ShotTrajectory& t);

/// The time a throw by `f` from `from` to base `base` takes, with the fielder's transfer.
double throw_time(const FielderAbility& f, const AeroModel& aero, const Environment& env, const Vec3& from, int base);
/// A fielder's arm (his throws, relays with his transfer) worked out once, for several throws.
Thrower fielder_thrower(const FielderAbility& f, const AeroModel& aero, const Environment& env);
/// throw_time() with the fielder's arm from fielder_thrower().
double throw_time(const Thrower& thrower, const Vec3& from, int base);

}  // namespace sweetspot
