#include "game/modes/baseball/batting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "game/modes/baseball/throwing.hpp"
#include "physics/delivery.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
namespace {

// ---- the field ----------------------------------------------------------------------------
constexpr double kBaseLine = 27.432;  // m, 90 ft between the bases (MLB Rule 2.01)
constexpr double kFoul = 0.25 * kPi;  // the foul lines at ±45° from the mound line

struct Fielder {
  const char* name;
  double depth_ft, angle_deg;  // from home plate; angle + toward first base
  double sprint_ftps;          // Statcast 2024 mean sprint speed by position
  double arm_mph;              // Statcast arm strength by position
};
// Depths: RF 294 ft (Petriello, MLB.com 2016), CF ~320 (FanGraphs 2016: league CF ~315-325),
// 3B 115 ft (ESPN 2017); 1B 110, 2B 150, SS 150, LF 295 are the commonly quoted depths
// (ESTIMATES); the pitcher at the rubber, the catcher behind the plate. Angles: ESTIMATES of
// the standard alignment.
constexpr std::array<Fielder, 9> kFielders{{
    {"P", 60.5, 0.0, 26.0, 85.0},
    {"C", -4.0, 0.0, 25.9, 81.7},
    {"1B", 110.0, 38.0, 26.3, 75.0},
    {"2B", 150.0, 14.0, 27.5, 78.2},
    {"SS", 150.0, -14.0, 27.9, 83.3},
    {"3B", 115.0, -38.0, 27.2, 83.5},
    {"LF", 295.0, -28.0, 27.9, 86.2},
    {"CF", 320.0, 0.0, 28.6, 87.8},
    {"RF", 294.0, 28.0, 27.7, 89.4},
}};
constexpr double kReaction = 0.3;     // s after contact before a fielder moves (ESTIMATE)
constexpr double kAccel = 4.0;        // m/s² to top speed: an outfielder covers ~34 ft in the
                                      // 2.55 s after contact of Statcast's 3 s "jump" (2024 mean 34.1 ft)
constexpr double kReach = 1.5;        // m: glove, arm and a dive
constexpr double kCatchable = 2.4;    // m: a ball above this is over the fielder's head
constexpr double kTransfer = 0.6;     // s to field cleanly and release a throw (ESTIMATE)
constexpr double kHomeToFirst = 4.47; // s, Statcast 2024 mean home-to-first
constexpr double kBaseToBase = 90.0 / 27.0 + 0.3;  // s: 90 ft at 27 ft/s (the mean sprint speed), + the turn

Vec3 at(double depth_ft, double angle_deg) {
  const double d = depth_ft * 0.3048, a = deg_to_rad(angle_deg);
  return Vec3(d * std::cos(a), 0.0, d * std::sin(a));
}
const Vec3 kFirst = at(90.0, 45.0), kSecond = at(90.0 * std::sqrt(2.0), 0.0), kThird = at(90.0, -45.0);

double run_time(double distance, double top_speed) {
  const double d = std::max(0.0, distance - kReach);
  const double d_acc = top_speed * top_speed / (2.0 * kAccel);
  if (d <= d_acc) return kReaction + std::sqrt(2.0 * d / kAccel);
  return kReaction + top_speed / kAccel + (d - d_acc) / top_speed;
}
double horizontal(const Vec3& a, const Vec3& b) { return std::hypot(a.x() - b.x(), a.z() - b.z()); }
double spray(const Vec3& p) { return std::atan2(p.z(), p.x()); }
bool fair_direction(const Vec3& p) { return p.x() > 0.0 && std::abs(spray(p)) <= kFoul; }

// Fair or foul (MLB Rule definitions): beyond the bases, where it first lands; before them,
// where it passes the bases' distance or comes to rest.
bool is_fair(const ShotTrajectory& t) {
  const Vec3& land = t.summary.landing_position;
  if (std::hypot(land.x(), land.z()) > kBaseLine) return fair_direction(land);
  for (const TrajectorySample& s : t.samples)
    if (std::hypot(s.position.x(), s.position.z()) > kBaseLine) return fair_direction(s.position);
  return fair_direction(t.summary.rest_position);
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
  }
  return "?";
}

const std::vector<BatterSkill>& batter_skills() {
  static const std::vector<BatterSkill> s = {
      {"pro", mph_to_mps(71.5), 8.0, 0.004, 0.04},
      {"amateur", mph_to_mps(60.0), 18.0, 0.009, 0.09},
  };
  return s;
}

const BatterSkill& batter_skill(std::string_view name) {
  std::string names;
  for (const BatterSkill& b : batter_skills()) {
    if (b.name == name) return b;
    names += (names.empty() ? "" : ", ") + b.name;
  }
  throw InputError("unknown batter skill '" + std::string(name) + "' (allowed: " + names + ")");
}

double fence_distance(const WorldAsset& world, double spray) {
  const auto& f = world.fence_line;
  for (std::size_t i = 1; i < f.size(); ++i) {
    const double a0 = std::atan2(f[i - 1].z(), f[i - 1].x()), a1 = std::atan2(f[i].z(), f[i].x());
    if ((spray - a0) * (spray - a1) <= 0.0) {
      const double u = a1 != a0 ? (spray - a0) / (a1 - a0) : 0.0;
      return (1.0 - u) * std::hypot(f[i - 1].x(), f[i - 1].z()) + u * std::hypot(f[i].x(), f[i].z());
    }
  }
  return std::numeric_limits<double>::infinity();
}

bool is_barrel(double ev, double la) { return la <= 50.0 && ev >= 98.0 && 1.5 * ev - la >= 117.0 && ev + la >= 124.0; }

BattedOutcome field_ball(const ShotResult& shot, const AeroModel& aero, const Environment& env, std::string* who) {
  if (who) who->clear();
  if (shot.end == ShotEnd::HomeRun) return BattedOutcome::HomeRun;
  const ShotTrajectory& t = shot.trajectory;
  if (shot.end == ShotEnd::OutOfBounds || !is_fair(t)) return BattedOutcome::Foul;
  const Vec3& land = t.summary.landing_position;
  const double hang = t.summary.hang_time_s;
  // In the air: caught if a fielder gets under it before it lands (not off the wall: a
  // first touch above the field is the fence).
  const bool off_wall = land.y() > 0.3;
  for (const Fielder& f : kFielders) {
    if (off_wall) break;
    if (run_time(horizontal(at(f.depth_ft, f.angle_deg), land), f.sprint_ftps * 0.3048) <= hang) {
      if (who) *who = f.name;
      return BattedOutcome::Out;
    }
  }
  // On the ground: the fielder who first reaches the ball low enough to field it.
  double best_t = std::numeric_limits<double>::infinity();
  Vec3 best_p = t.summary.rest_position;
  const Fielder* best_f = &kFielders[0];
  for (const Fielder& f : kFielders) {
    const Vec3 start = at(f.depth_ft, f.angle_deg);
    const double v = f.sprint_ftps * 0.3048;
    for (const TrajectorySample& s : t.samples) {
      if (s.t < hang || s.position.y() > kCatchable) continue;
      if (run_time(horizontal(start, s.position), v) <= s.t) {
        if (s.t < best_t) {
          best_t = s.t;
          best_p = s.position;
          best_f = &f;
        }
        break;
      }
    }
    // At rest, eventually.
    const double arrive = std::max(t.summary.total_time_s, run_time(horizontal(start, t.summary.rest_position), v));
    if (arrive < best_t) {
      best_t = arrive;
      best_p = t.summary.rest_position;
      best_f = &f;
    }
  }
  if (who) *who = best_f->name;
  // The throw at the fielder's arm strength, flown through the air to the bag (throwing.hpp).
  const Thrower thrower(aero, env, mph_to_mps(best_f->arm_mph), kTransfer);
  const auto defence = [&](const Vec3& base) { return best_t + kTransfer + thrower.to(horizontal(best_p, base)).time; };
  if (defence(kFirst) < kHomeToFirst) return BattedOutcome::Out;
  // Extra bases the batter can take with a half-second to spare.
  if (defence(kSecond) < kHomeToFirst + kBaseToBase + 0.5) return BattedOutcome::Single;
  if (defence(kThird) < kHomeToFirst + 2.0 * kBaseToBase + 0.5) return BattedOutcome::Double;
  return BattedOutcome::Triple;
}

SwingResult swing_at(const Assets& assets, const PitchFlight& pitch, const SwingInput& in, double bat_speed,
                     const std::string& bat_name) {
  check_range("swing.timing", in.timing_ms, SwingInput::kTiming, "ms");
  check_range("swing.undercut", in.undercut, SwingInput::kUndercut, "m");
  SwingResult out;
  if (std::abs(in.timing_ms) > kMissTimingMs) return out;  // through the zone before or after the ball
  const EquipmentCatalog& eq = assets.equipment();
  const BatSpec& bat = eq.bat(bat_name);
  const BallSpec& ball = eq.ball("mlb");
  BatSwing s;
  s.bat_speed = bat_speed * (in.power ? 1.0 : 0.92);
  s.attack_angle = deg_to_rad(10.0);  // Statcast's ideal attack angle is 5-20°; the league sits near 10°
  s.direction = std::clamp(kDirectionPerMs * in.timing_ms, BatSwing::kDirection.min, BatSwing::kDirection.max);
  s.impact_from_tip = std::clamp(bat.sweet_spot_from_tip + kBarrelPerMs * in.timing_ms, 0.01, 0.45);
  s.undercut = in.undercut;
  // A left-handed batter is the mirror image across the mound line: swing at the mirrored
  // pitch as a right-hander, then mirror the batted ball back.
  const double m = in.left_handed ? -1.0 : 1.0;
  const Vec3 v(pitch.plate_velocity.x(), pitch.plate_velocity.y(), m * pitch.plate_velocity.z());
  const Vec3 w(m * pitch.plate_spin.x(), m * pitch.plate_spin.y(), pitch.plate_spin.z());
  Delivery d;
  try {
    d = deliver_baseball(ball, bat, s, v, w, bat.material);
  } catch (const InputError&) {
    return out;  // the bat cannot close on the ball there: a swing and a miss
  }
  LaunchMetrics L = measure_launch(d.launch);
  if (in.left_handed) {
    L.horizontal_angle = -L.horizontal_angle;
    L.spin.axis_rad = -L.spin.axis_rad;
  }
  ShotSpec spec;
  spec.sport = "baseball";
  LaunchStrike ls;
  ls.numbers.ball_speed = std::min(L.ball_speed, LaunchNumbers::kBallSpeed.max);
  ls.numbers.vertical_angle = L.vertical_angle;
  ls.numbers.horizontal_angle = std::clamp(L.horizontal_angle, LaunchNumbers::kHorizontalAngle.min, LaunchNumbers::kHorizontalAngle.max);
  ls.numbers.spin = std::min(L.spin.total, LaunchNumbers::kSpin.max);
  ls.numbers.spin_axis = L.spin.axis_rad;
  spec.strike = ls;
  out.contact = true;
  const ResolvedShot resolved = resolve(spec, assets);
  out.shot = run_shot(resolved, "swing", {true, true});
  out.outcome = field_ball(out.shot, *resolved.aero, resolved.spec.environment, &out.fielder);
  const double ev = mps_to_mph(L.ball_speed), la = rad_to_deg(L.vertical_angle);
  out.hard_hit = ev >= 95.0;
  out.sweet_spot = la >= 8.0 && la <= 32.0;
  out.barrel = is_barrel(ev, la);
  return out;
}

}  // namespace sweetspot
