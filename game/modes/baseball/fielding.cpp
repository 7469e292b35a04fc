#include "game/modes/baseball/fielding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "game/modes/baseball/throwing.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr double kFoul = 0.25 * kPi;  // the foul lines at ±45° from the mound line

struct Spot {
  double depth_ft, angle_deg;  // from home plate; angle + toward first base
  double sprint_ftps;          // Statcast 2024 mean sprint speed by position
  double arm_mph;              // Statcast arm strength by position
};
// Depths: RF 294 ft (Petriello, MLB.com 2016), CF ~320 (FanGraphs 2016: league CF ~315-325),
// 3B 115 ft (ESPN 2017); 1B 110, 2B 150, SS 150, LF 295 are the commonly quoted depths
// (ESTIMATES); the pitcher at the rubber, the catcher behind the plate. Angles: ESTIMATES of
// the standard alignment.
constexpr std::array<Spot, 9> kSpots{{
    {60.5, 0.0, 26.0, 85.0},
    {-4.0, 0.0, 25.9, 81.7},
    {110.0, 38.0, 26.3, 75.0},
    {150.0, 14.0, 27.5, 78.2},
    {150.0, -14.0, 27.9, 83.3},
    {115.0, -38.0, 27.2, 83.5},
    {295.0, -28.0, 27.9, 86.2},
    {320.0, 0.0, 28.6, 87.8},
    {294.0, 28.0, 27.7, 89.4},
}};
constexpr double kReaction = 0.3;     // s after contact before an outfielder moves (ESTIMATE)
constexpr double kAccel = 4.0;        // m/s² to top speed: an outfielder covers ~34 ft in the
                                      // 2.55 s after contact of Statcast's 3 s "jump" (2024 mean 34.1 ft)
constexpr double kReach = 1.5;        // m: glove, arm and a dive
constexpr double kInfieldReaction = 0.2, kInfieldAccel = 5.0, kInfieldReach = 1.8;  // see league_defense
constexpr double kCatchable = 2.4;    // m: a ball above this is over the fielder's head
constexpr double kLeap = 3.2;         // m: at the wall he can leap (standing reach + ~0.8 m jump; ESTIMATE)
constexpr double kTransfer = 0.6;     // s to field cleanly and release a throw (ESTIMATE)
constexpr double kHomeToFirst = 4.47; // s, Statcast 2024 mean home-to-first
constexpr double kMeanSprint = 27.0 * 0.3048;  // m/s, Statcast's league-average sprint speed
// An infielder fields a ball standing within an arm and glove of it (~1 m: ESTIMATE of a
// 0.75 m arm and the glove's 0.3 m); past that, out to his reach, he dives, and getting up to
// throw (or throwing from his knees) costs him about a second (ESTIMATE).
constexpr double kStandingReach = 1.0;  // m
constexpr double kDiveRecovery = 1.0;   // s
constexpr double kBatterExtraBaseMargin = 0.2;  // s: the batter takes an extra base only with this to spare (ESTIMATE)
// A running outfielder brakes harder than he starts (ESTIMATE: twice his 4 m/s² start, as
// field-sport sprinters' peak deceleration runs ~1.5-2.5x their acceleration).
constexpr double kOutfieldBraking = 8.0;  // m/s²
constexpr double kOutfieldGather = 0.6;  // s an outfielder loses slowing to pick up a ball on the
                                         // ground and setting his feet (a crow hop) (ESTIMATE)
constexpr double kCatchSpread = 0.4; // s, catch_probability's spread
constexpr double kCatchOffset = 0.25; // s: a catch that takes all of his reach and speed is a 5-star play (24 %)
// Chasing a ball in the air: Statcast's route efficiency (the straight-line distance over the
// path run) is ~0.9 for the league's outfielders, and the last steps slow him to gather under
// the ball (ESTIMATE 0.35 s).
constexpr double kRouteEfficiency = 0.9;
constexpr double kGatherUnder = 0.35;  // s
// Misplays per chance: MLB fielding percentage ~.985 (2023), outfielders ~.990 and
// infielders ~.975: a ball caught in the air is dropped 0.5 % of the time; a grounder
// fielded for an out is booted or thrown away 3 % of the time: the fielder's chance (an
// infielder's ~2.5 %) and the first baseman's catch of the throw (~0.5 %) (ESTIMATES from
// those percentages).
constexpr double kDropRate = 0.005, kBootRate = 0.03;
// A ball in the air that a fielder would catch this surely is his to call for, and the order
// of who takes it when several could: CF; RF and LF; SS, 2B; 3B, 1B; C; P (kPositionNames).
constexpr double kRoutineCatch = 0.9;
constexpr std::array<int, 9> kCatchPriority{7, 8, 6, 4, 3, 5, 2, 1, 0};
// m from home to the infield's edge: the grass line's 95 ft arc about the pitcher's plate
// (60.5 ft out) reaches 155.5 ft in straightaway centre (Official Baseball Rules, diagram 1).
constexpr double kInfieldEdge = 47.4;

Vec3 at(double depth_ft, double angle_deg) {
  const double d = depth_ft * 0.3048, a = deg_to_rad(angle_deg);
  return Vec3(d * std::cos(a), 0.0, d * std::sin(a));
}
double horizontal(const Vec3& a, const Vec3& b) { return std::hypot(a.x() - b.x(), a.z() - b.z()); }
// The horizontal unit vector from a toward b; `fallback` where they (nearly) meet.
Vec3 heading(const Vec3& a, const Vec3& b, const Vec3& fallback) {
  const double d = horizontal(a, b);
  return d > 1e-6 ? Vec3(Vec3(b.x() - a.x(), 0.0, b.z() - a.z()) / d) : fallback;
}
double spray(const Vec3& p) { return std::atan2(p.z(), p.x()); }
bool fair_direction(const Vec3& p) { return p.x() > 0.0 && std::abs(spray(p)) <= kFoul; }

// The call and where and when the umpire can make it.
struct FairCall {
  bool fair = false;
  double t = 0.0;  ///< s after contact
  Vec3 at = Vec3::Zero();
};
// Fair or foul (MLB Rule definitions): beyond the bases, where it first lands; before them,
// where it passes the bases' distance, is first touched by a fielder (`touched`: when and
// where, if one reaches it on the ground) or comes to rest.
FairCall fair_call(const ShotTrajectory& t, const std::optional<TrajectorySample>& touched = std::nullopt) {
  const Vec3& land = t.summary.landing_position;
  if (std::hypot(land.x(), land.z()) > kBaseLine) return {fair_direction(land), t.summary.hang_time_s, land};
  for (const TrajectorySample& s : t.samples) {
    if (touched && s.t >= touched->t) return {fair_direction(touched->position), touched->t, touched->position};
    // Bounding past the bases: only once it has come down (a pop-up that drifts out beyond
    // them in the air and falls back short of them is judged where it settles or is touched).
    if (s.t < t.summary.hang_time_s) continue;
    if (std::hypot(s.position.x(), s.position.z()) > kBaseLine) return {fair_direction(s.position), s.t, s.position};
  }
  if (touched) return {fair_direction(touched->position), touched->t, touched->position};
  return {fair_direction(t.summary.rest_position), t.summary.total_time_s, t.summary.rest_position};
}
bool is_fair(const ShotTrajectory& t, const std::optional<TrajectorySample>& touched = std::nullopt) {
  return fair_call(t, touched).fair;
}

// An outfielder chasing a ball down runs a route; an infielder charges it straight.
double route_efficiency(std::size_t fielder) { return fielder >= 6 ? kRouteEfficiency : 1.0; }

struct GroundTouch {
  TrajectorySample at;
  std::size_t fielder = 0;
};
// The first moment any fielder can get to the ball on the ground (after its first landing,
// low enough to field), running flat out from his spot: where a chopper that would roll foul
// is touched over fair ground, and so is fair. None when nobody reaches it before it stops.
std::optional<GroundTouch> first_ground_touch(const ShotTrajectory& t, const std::array<Vec3, 9>& start,
                                              const Defense& defense) {
  std::optional<GroundTouch> first;
  for (std::size_t i = 0; i < 9; ++i) {
    for (const TrajectorySample& s : t.samples) {
      if (first && s.t >= first->at.t) break;
      if (s.t < t.summary.hang_time_s || s.position.y() > kCatchable) continue;
      if (fielder_run_time(defense.ability[i], horizontal(start[i], s.position) / route_efficiency(i)) <= s.t) {
        first = GroundTouch{s, i};
        break;
      }
    }
  }
  return first;
}

// A foul ball in the field of play (not yet in the stands): within 60 ft of a foul line
// beyond the bases, or in front of the backstop.
bool in_foul_ground(const Vec3& p) {
  if (std::hypot(p.x(), p.z()) > kFoulGround && p.x() < 0.0 && std::abs(p.z()) < -p.x()) return false;  // past the backstop
  const double u = (p.x() + p.z()) / std::sqrt(2.0), w = (p.x() - p.z()) / std::sqrt(2.0);  // along the lines
  // Distance outside the nearer foul line (negative inside fair ground).
  const double out = std::max(-w, -u);
  return out <= kFoulGround && std::hypot(p.x(), p.z()) < 140.0;
}

// From having the ball at `from` to the ball at base `base`: the transfer, then the throw.
double transfer_and_throw(const Thrower& thrower, const Vec3& from, int base) {
  return kTransfer + thrower.to(std::min(horizontal(from, base_position(base)), 999.0)).time;
}

const char* field_part(const Vec3& p) {
  const double a = rad_to_deg(spray(p));
  return a < -15.0 ? "LF" : a > 15.0 ? "RF" : "CF";
}

std::string describe(const FieldingPlay& f, const Vec3& toward) {
  const std::string who = f.fielder >= 0 ? kPositionNames[static_cast<std::size_t>(f.fielder)] : "";
  const bool outfield = f.fielder >= 6;
  switch (f.outcome) {
    case BattedOutcome::HomeRun: return std::string("Home run to ") + field_part(toward);
    case BattedOutcome::Foul: return "Foul";
    case BattedOutcome::Error: return "Reached on an error by " + who;
    case BattedOutcome::Single:
      // A ball an infielder runs down past the infield is a single to the outfield there.
      if (!outfield && std::hypot(toward.x(), toward.z()) > kInfieldEdge) return std::string("Single to ") + field_part(toward);
      return std::string("Single to ") + (outfield ? who : who + " (infield hit)");
    case BattedOutcome::Double: return "Double to " + std::string(field_part(toward));
    case BattedOutcome::Triple: return "Triple to " + std::string(field_part(toward));
    case BattedOutcome::Out:
      if (f.caught) {
        if (f.foul) return "Foul out to " + who;
        // A fly an infielder (or the pitcher or catcher) catches is popped up, whatever its angle.
        if (!outfield && (f.type == BattedBallType::FlyBall || f.type == BattedBallType::PopUp)) return "Pop out to " + who;
        switch (f.type) {
          case BattedBallType::PopUp: return (outfield ? "Fly out to " : "Pop out to ") + who;
          case BattedBallType::LineDrive: return "Line out to " + who;
          case BattedBallType::GroundBall: return "Line out to " + who;
          case BattedBallType::FlyBall: return "Fly out to " + who;
        }
      }
      if (f.out_at_first_by == f.fielder) return "Ground out to " + who + " unassisted";
      return "Ground out, " + who + " to " + kPositionNames[static_cast<std::size_t>(std::max(f.out_at_first_by, 0))];
    case BattedOutcome::Strike: return "Strike";
  }
  return "";
}

}  // namespace

const char* to_string(BattedOutcome o) {
  switch (o) {
    case BattedOutcome::Strike: return "strike";
    case BattedOutcome::Foul: return "foul";
    case BattedOutcome::Out: return "out";
    case BattedOutcome::Single: return "single";
    case BattedOutcome::Double: return "double";
    case BattedOutcome::Triple: return "triple";
    case BattedOutcome::HomeRun: return "home_run";
    case BattedOutcome::Error: return "error";
  }
  return "?";
}

bool is_fair_ball(const ShotResult& shot, const Defense* defense, bool batter_left) {
  if (shot.end == ShotEnd::HomeRun) return true;
  // Into the stands: foul, unless it first came down fair beyond the bases (a bounce over
  // the fence, a ground-rule double) — is_fair decides from where it came down.
  if (defense == nullptr) return is_fair(shot.trajectory);
  const auto touch = first_ground_touch(shot.trajectory, fielder_spots(batter_left), *defense);
  return is_fair(shot.trajectory, touch ? std::optional<TrajectorySample>(touch->at) : std::nullopt);
}

BattedBallType batted_ball_type(double la) {
  const double d = rad_to_deg(la);
  return d < 10.0 ? BattedBallType::GroundBall : d < 25.0 ? BattedBallType::LineDrive
                                               : d <= 50.0 ? BattedBallType::FlyBall : BattedBallType::PopUp;
}

const char* to_string(BattedBallType t) {
  switch (t) {
    case BattedBallType::GroundBall: return "ground_ball";
    case BattedBallType::LineDrive: return "line_drive";
    case BattedBallType::FlyBall: return "fly_ball";
    case BattedBallType::PopUp: return "popup";
  }
  return "?";
}

Vec3 base_position(int base) {
  switch (base & 3) {
    case 1: return at(90.0, 45.0);
    case 2: return at(90.0 * std::sqrt(2.0), 0.0);
    case 3: return at(90.0, -45.0);
    default: return Vec3::Zero();
  }
}

Defense league_defense() {
  Defense d;
  for (std::size_t i = 0; i < 9; ++i)
    d.ability[i] = i >= 6 ? FielderAbility{kReaction, kAccel, kSpots[i].sprint_ftps * 0.3048, kReach, mph_to_mps(kSpots[i].arm_mph)}
                          : FielderAbility{kInfieldReaction, kInfieldAccel, kSpots[i].sprint_ftps * 0.3048, kInfieldReach,
                                           mph_to_mps(kSpots[i].arm_mph)};
  return d;
}

Defense draw_defense(Rng& rng) {
  Defense d = league_defense();
  for (FielderAbility& f : d.ability) {
    f.reaction = std::clamp(f.reaction + rng.normal(0.05), 0.05, 0.5);
    f.sprint = std::clamp(f.sprint + rng.normal(1.2 * 0.3048), 6.5, 9.5);
    f.arm = std::clamp(f.arm + rng.normal(mph_to_mps(2.5)), 28.0, 46.0);
  }
  return d;
}

std::array<Vec3, 9> fielder_spots(bool batter_left) {
  const double pull = batter_left ? 1.0 : -1.0;  // a right-hander pulls toward third (−)
  std::array<Vec3, 9> out;
  for (std::size_t i = 0; i < 9; ++i) {
    const double shade = i >= 6 ? 4.0 : (i == 3 || i == 4) ? 3.0 : 0.0;
    out[i] = at(kSpots[i].depth_ft, kSpots[i].angle_deg + pull * shade);
  }
  return out;
}

double fielder_run_time(const FielderAbility& f, double distance) {
  const double d = std::max(0.0, distance - f.reach);
  const double d_acc = f.sprint * f.sprint / (2.0 * f.accel);
  if (d <= d_acc) return f.reaction + std::sqrt(2.0 * d / f.accel);
  return f.reaction + f.sprint / f.accel + (d - d_acc) / f.sprint;
}

double run_speed(const FielderAbility& f, double distance) {
  const double d = std::max(0.0, distance - f.reach);
  return std::min(f.sprint, std::sqrt(2.0 * f.accel * d));
}

double plant_time(const FielderAbility& f, double arrive_speed, double slack, const Vec3& run_dir, const Vec3& throw_dir) {
  const double speed = std::max(0.0, arrive_speed - f.accel * std::max(0.0, slack));
  // Running straight at his target he throws on the run; straight away from it he must stop
  // dead; across it, half way (ESTIMATE: the share of his run he must check grows as the
  // run turns from the throw, 1 - cos of the angle between them, halved).
  const double turn = 0.5 * (1.0 - std::clamp(run_dir.dot(throw_dir), -1.0, 1.0));
  return turn * speed / f.accel;
}

double catch_probability(double spare) {
  return 0.5 * std::erfc(-(spare - kCatchOffset) / (kCatchSpread * std::sqrt(2.0)));
}

int covering_fielder(int base, int fielder) {
  switch (base) {
    case 4: return 1;
    case 3: return fielder == 5 ? 4 : 5;
    case 2: return fielder == 4 || fielder == 5 || fielder == 6 ? 3 : 4;
    default: return 2;
  }
}

Thrower fielder_thrower(const FielderAbility& f, const AeroModel& aero, const Environment& env) {
  return Thrower(aero, env, f.arm, kTransfer);
}

double throw_time(const FielderAbility& f, const AeroModel& aero, const Environment& env, const Vec3& from, int base) {
  return transfer_and_throw(fielder_thrower(f, aero, env), from, base);
}

double throw_time(const Thrower& thrower, const Vec3& from, int base) { return transfer_and_throw(thrower, from, base); }

FieldingPlay field_play(const ShotResult& shot, const AeroModel& aero, const Environment& env, const Defense& defense,
                        bool batter_left, double batter_sprint, Rng* rng) {
  FieldingPlay play;
  const ShotTrajectory& t = shot.trajectory;
  play.type = batted_ball_type(shot.launch.vertical_angle);
  play.batter_to_first = kHomeToFirst * kMeanSprint / std::max(batter_sprint, 1.0);
  play.start = fielder_spots(batter_left);
  play.goal = play.start;
  const Vec3& land = t.summary.landing_position;
  const double hang = t.summary.hang_time_s;
  const auto drawn = [&](double p) { return rng ? rng->uniform() < p : p >= 0.5; };
  if (shot.end == ShotEnd::HomeRun) {
    play.outcome = BattedOutcome::HomeRun;
    play.description = describe(play, land);
    return play;
  }
  // Who first gets to it on the ground: the foul line's call before the bases, and the
  // grounder's fielder below.
  const std::optional<GroundTouch> touch = first_ground_touch(t, play.start, defense);
  const FairCall call = fair_call(t, touch ? std::optional<TrajectorySample>(touch->at) : std::nullopt);
  play.foul = !call.fair;
  if (play.foul) {
    play.called_time = call.t;
    play.called_at = call.at;
  }
  // In the air: the fielder with the most time to spare anywhere along its path below his
  // reach (at the wall, a leap) gets under it; a foul fly only while it is over foul ground.
  const bool near_wall = land.y() > 0.3;  // its first touch was the fence
  double best_spare = -std::numeric_limits<double>::infinity();
  int best = -1;
  // A ball in the air is read and chased as an outfielder does: an infielder's ready hop
  // gains him nothing going back on a fly.
  std::array<FielderAbility, 9> in_air = defense.ability;
  for (FielderAbility& f : in_air) {
    f.reaction = std::max(f.reaction, kReaction);
    f.accel = std::min(f.accel, kAccel);
    f.reach = std::min(f.reach, kReach);
  }
  std::array<double, 9> own_spare;
  own_spare.fill(-std::numeric_limits<double>::infinity());
  std::array<Vec3, 9> own_at;
  std::array<double, 9> own_t{};
  for (std::size_t i = 0; i < 9; ++i) {
    for (const TrajectorySample& s : t.samples) {
      if (s.t > hang) break;
      const double reach = near_wall && horizontal(s.position, land) < 3.0 ? kLeap : kCatchable;
      // Nothing he can react to: a ball past him, or down, before he can move is no catch.
      // (The catcher's glove in a foul tip's path makes a strike of it, not an out.)
      if (s.position.y() > reach || s.t < in_air[i].reaction) continue;
      if (play.foul && !in_foul_ground(s.position)) continue;
      const double run = fielder_run_time(in_air[i], horizontal(play.start[i], s.position) / kRouteEfficiency);
      const double spare = s.t - run - kGatherUnder;
      if (spare > own_spare[i]) {
        own_spare[i] = spare;
        own_at[i] = s.position;
        own_t[i] = s.t;
      }
    }
    if (own_spare[i] > best_spare) {
      best_spare = own_spare[i];
      best = static_cast<int>(i);
    }
  }
  // The catch is called for (every club's priority rule): among those with a routine catch,
  // the centre fielder over the corner outfielders, any outfielder over an infielder, the
  // middle infielders over the corners, anyone over the catcher and the pitcher.
  if (best >= 0 && catch_probability(best_spare) >= kRoutineCatch) {
    for (int who : kCatchPriority) {
      const std::size_t i = static_cast<std::size_t>(who);
      if (catch_probability(own_spare[i]) >= kRoutineCatch) {
        best = who;
        best_spare = own_spare[i];
        break;
      }
    }
  }
  if (best >= 0) {
    const Vec3 best_at = own_at[static_cast<std::size_t>(best)];
    const double best_t = own_t[static_cast<std::size_t>(best)];
    play.catch_probability = catch_probability(best_spare);
    play.goal[static_cast<std::size_t>(best)] = best_at;
    if (drawn(play.catch_probability)) {
      // A ball touched in the air is fair or foul by where it is over when he touches it
      // (Rule definitions: fair ball, foul ball), wherever it would have come down.
      play.foul = !fair_direction(best_at);
      if (!play.foul) play.called_time = 0.0;  // caught over fair ground: no foul to call
      play.fielder = best;
      play.caught = true;
      play.fielded_at = best_at;
      play.fielded_time = best_t;
      play.ready_time = best_t;
      play.outcome = BattedOutcome::Out;
      if (rng && rng->uniform() < kDropRate) {
        // Dropped: a fair ball puts the batter on by the error; a foul one is only a foul.
        play.outcome = play.foul ? BattedOutcome::Foul : BattedOutcome::Error;
        play.caught = false;
        if (play.foul) {
          play.called_time = best_t;
          play.called_at = best_at;
        }
      }
      play.description = describe(play, land);
      return play;
    }
  }
  if (play.foul) {
    play.outcome = BattedOutcome::Foul;
    play.description = describe(play, land);
    return play;
  }
  // Fair, not caught, then over the fence or into the stands on a bounce with no fielder's
  // hand on it first: two bases (Rule 5.05(a)(6)). One a fielder reaches on the ground over
  // fair ground (what made it fair) he plays.
  if (shot.end == ShotEnd::OutOfBounds && !(touch && call.t == touch->at.t)) {
    play.outcome = BattedOutcome::Double;
    play.description = std::string("Ground-rule double to ") + field_part(land);
    return play;
  }
  // On the ground: the fielder who first reaches the ball low enough to field it, or at rest.
  double first_t = std::numeric_limits<double>::infinity();
  Vec3 first_p = t.summary.rest_position;
  std::size_t first_f = 0;
  if (touch) {
    first_t = touch->at.t;
    first_p = touch->at.position;
    first_f = touch->fielder;
  }
  for (std::size_t i = 0; i < 9; ++i) {
    const double run = horizontal(play.start[i], t.summary.rest_position) / route_efficiency(i);
    const double arrive = std::max(t.summary.total_time_s, fielder_run_time(defense.ability[i], run));
    if (arrive < first_t) {
      first_t = arrive;
      first_p = t.summary.rest_position;
      first_f = i;
    }
  }
  const FielderAbility& f = defense.ability[first_f];
  double ready = first_t;
  if (first_f >= 6) {
    // He picks it up, and, where his run carried him away from the infield (a ball over his
    // head, one into the gap rolling to the wall), stops that part of his run before he can
    // throw, as an infielder does (plant_time): the ball past him gives the batter time.
    first_t += kOutfieldGather;
    ready = first_t;
    const double d = horizontal(play.start[first_f], first_p);
    if (d > 1e-6) {
      const Vec3 run_dir = heading(play.start[first_f], first_p, Vec3::UnitX());
      const Vec3 throw_dir = heading(first_p, base_position(2), run_dir);
      const double run = fielder_run_time(f, d / kRouteEfficiency);
      FielderAbility braking = f;
      braking.accel = kOutfieldBraking;
      ready += plant_time(braking, run_speed(f, d), std::max(0.0, first_t - kOutfieldGather - run), run_dir, throw_dir);
    }
  } else {
    // An infielder does not take every ball at the first point he can reach: where he would
    // get there flat out, or only with a dive, he lets it come on to where he can field it
    // under control, whichever puts his throw at first soonest (the throw's time taken as
    // its distance over his arm for the choice).
    const Vec3 first_base = base_position(1);
    double best = std::numeric_limits<double>::infinity();
    const auto consider = [&](const Vec3& p, double t) {
      const double d = horizontal(play.start[first_f], p);
      const double run = fielder_run_time(f, d);
      if (run > t) return;
      FielderAbility standing = f;
      standing.reach = std::min(f.reach, kStandingReach);
      double set = t;
      if (fielder_run_time(standing, d) > t) {
        set += kDiveRecovery;
      } else if (d > 1e-6) {
        const Vec3 run_dir = heading(play.start[first_f], p, Vec3::UnitX());
        const Vec3 throw_dir = heading(p, first_base, run_dir);
        set += plant_time(f, run_speed(f, d), t - run, run_dir, throw_dir);
      }
      const double at_first = set + horizontal(p, first_base) / f.arm;
      if (at_first < best) {
        best = at_first;
        first_t = t;
        first_p = p;
        ready = set;
      }
    };
    const double picked = first_t;
    for (const TrajectorySample& s : t.samples)
      if (s.t >= picked && s.t >= hang && s.position.y() <= kCatchable) consider(s.position, s.t);
    consider(t.summary.rest_position, std::max(t.summary.total_time_s, picked));
  }
  play.fielder = static_cast<int>(first_f);
  play.fielded_at = first_p;
  play.fielded_time = first_t;
  play.ready_time = ready;
  play.goal[first_f] = first_p;
  const Thrower thrower(aero, env, f.arm, kTransfer);  // once for the bases he may throw to
  const auto defence = [&](int base) { return ready + transfer_and_throw(thrower, first_p, base); };
  const double to_first = play.batter_to_first;
  const double base_to_base = kBaseLine / std::max(batter_sprint, 1.0) + kBaseRoundingTime;
  // The ball at first: thrown to the man covering it. The first baseman with his own ground
  // ball runs it to the bag when that is sooner (unassisted); from farther off he tosses it
  // to the pitcher, who breaks for the bag at contact, once the pitcher can be there (3-1).
  double at_first = defence(1);
  play.out_at_first_by = covering_fielder(1, play.fielder);
  if (play.fielder == kFirstBaseman) {
    const Vec3 bag = base_position(1);
    const double carried = ready + fielder_run_time(f, horizontal(first_p, bag)) - f.reaction;
    const double tossed =
        std::max(at_first, fielder_run_time(defense.ability[kPitcher], horizontal(play.start[kPitcher], bag)));
    play.out_at_first_by = carried <= tossed ? kFirstBaseman : kPitcher;
    at_first = std::min(carried, tossed);
  }
  if (at_first < to_first) {
    play.outcome = BattedOutcome::Out;
    if (rng && rng->uniform() < kBootRate) play.outcome = BattedOutcome::Error;
    play.description = describe(play, first_p);
    return play;
  }
  // He takes each further base he should beat the throw to by kBatterExtraBaseMargin; the
  // throw as it comes (kThrowSpread) can still get him there.
  int reached = 1;
  for (int base = 2; base <= 3; ++base) {
    const double spare = defence(base) + kTagTime - (to_first + (base - 1) * base_to_base);
    if (spare < kBatterExtraBaseMargin) break;
    if (rng && spare + rng->normal(kThrowSpread) < 0.0) {
      play.batter_out_at = base;
      break;
    }
    reached = base;
  }
  play.outcome = reached == 1 ? BattedOutcome::Single : reached == 2 ? BattedOutcome::Double : BattedOutcome::Triple;
  play.description = describe(play, first_p);
  return play;
}

namespace {
// When and where the play ends the ball's path before the physics does: in a fielder's
// glove, or where a foul no one caught is called (it is dead there). None: the whole path
// (a home run or a ground-rule double has no fielder, -1; a ball at rest before he gets there).
struct PlayEnd {
  double t = 0.0;
  Vec3 at = Vec3::Zero();
};
std::optional<PlayEnd> play_end(const ShotTrajectory& t, const FieldingPlay& play) {
  const bool fielded = play.caught || (play.fielder >= 0 && !play.foul);
  const bool called_foul = play.foul && !play.caught && play.called_time > 0.0;
  const double end_t = fielded ? play.fielded_time : play.called_time;
  if (!(fielded || called_foul) || t.samples.empty() || end_t >= t.summary.total_time_s) return std::nullopt;
  return PlayEnd{end_t, fielded ? play.fielded_at : play.called_at};
}
}  // namespace

ShotTrajectory as_played(const ShotTrajectory& t, const FieldingPlay& play) {
  const std::optional<PlayEnd> end = play_end(t, play);
  if (!end) return t;
  const double end_t = end->t;
  const Vec3& end_at = end->at;
  ShotTrajectory out = t;
  out.samples.clear();
  for (const TrajectorySample& s : t.samples) {
    if (s.t >= end_t) break;
    out.samples.push_back(s);
  }
  // In the glove: the ball stays where he caught it or picked it up (or where it was called).
  TrajectorySample held;
  held.t = end_t;
  held.position = end_at;
  held.phase = Phase::Rest;
  out.samples.push_back(held);
  if (out.samples.size() < 2) out.samples.insert(out.samples.begin(), t.samples.front());
  out.summary.rest_position = end_at;
  out.summary.total_time_s = end_t;
  // Its distance is to where he had it: the label on the scene's rest pin.
  out.summary.total_m = horizontal(t.samples.front().position, end_at);
  if (play.caught || end_t < t.summary.hang_time_s) {
    // Caught (or a foul fly touched and dropped) before it came down: the glove is its
    // landing too (no ring where it never fell).
    out.summary.landing_position = end_at;
    out.summary.carry_m = out.summary.total_m;
    out.summary.hang_time_s = end_t;
  }
  return out;
}

Vec3 play_rest_position(const ShotTrajectory& t, const FieldingPlay& play) {
  const std::optional<PlayEnd> end = play_end(t, play);
  return end ? end->at : t.summary.rest_position;
}

ShotTrajectory into_the_mitt(const ShotTrajectory& t) {
  if (t.samples.empty()) return t;
  const double mitt = ft_to_m(std::abs(kSpots[1].depth_ft));  // m behind the plate: the catcher's spot
  const Vec3& from = t.samples.front().position;
  ShotTrajectory out = t;
  out.samples.clear();
  for (const TrajectorySample& s : t.samples) {
    out.samples.push_back(s);
    if (horizontal(from, s.position) >= mitt) break;
  }
  if (out.samples.size() == t.samples.size()) return t;  // it never got that far back
  TrajectorySample held = out.samples.back();
  held.phase = Phase::Rest;
  out.samples.push_back(held);
  out.summary.rest_position = out.summary.landing_position = held.position;
  out.summary.total_time_s = out.summary.hang_time_s = held.t;
  out.summary.total_m = out.summary.carry_m = horizontal(from, held.position);
  return out;
}

BattedOutcome field_ball(const ShotResult& shot, const AeroModel& aero, const Environment& env, std::string* who) {
  const FieldingPlay p = field_play(shot, aero, env, league_defense(), false, kMeanSprint, nullptr);
  if (who) *who = p.fielder >= 0 ? kPositionNames[static_cast<std::size_t>(p.fielder)] : "";
  return p.outcome;
}

}  // namespace sweetspot
