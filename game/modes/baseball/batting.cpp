#include "game/modes/baseball/batting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "game/modes/baseball/throwing.hpp"
#include "physics/delivery.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
namespace {

// A ball flown as its mirror image across the plate's plane (x → −x) put back where it went.
void mirror_behind_plate(ShotResult& shot) {
  for (TrajectorySample& p : shot.trajectory.samples) {
    p.position.x() = -p.position.x();
    p.velocity.x() = -p.velocity.x();
    p.spin.z() = -p.spin.z();
    p.spin.y() = -p.spin.y();
  }
  shot.trajectory.summary.landing_position.x() = -shot.trajectory.summary.landing_position.x();
  shot.trajectory.summary.rest_position.x() = -shot.trajectory.summary.rest_position.x();
}

// A foul behind the plate is dead where it reaches the backstop, kFoulGround from home
// plate (Rule 2.01; the ballpark's wall arc and the stands behind it): into the wall below its
// top or over it into the stands, the ball drops there. Trims the flight at that point, whether
// it was flown mirrored over open field or drifted back over the ballpark.
void stop_at_backstop(ShotResult& shot, double ball_radius) {
  std::vector<TrajectorySample>& s = shot.trajectory.samples;
  const auto behind = [](const Vec3& p) { return p.x() < 0.0 && std::hypot(p.x(), p.z()) >= kFoulGround; };
  std::size_t i = 1;
  while (i < s.size() && !behind(s[i].position)) ++i;
  if (i >= s.size()) return;
  // Where the step from s[i-1] to s[i] reaches the backstop's circle (linear in the step).
  const auto r = [](const Vec3& p) { return std::hypot(p.x(), p.z()); };
  const double r0 = r(s[i - 1].position), r1 = r(s[i].position);
  const double u = r1 > r0 ? std::clamp((kFoulGround - r0) / (r1 - r0), 0.0, 1.0) : 1.0;
  TrajectorySample at = s[i - 1];
  at.t = s[i - 1].t + u * (s[i].t - s[i - 1].t);
  at.position = s[i - 1].position + u * (s[i].position - s[i - 1].position);
  at.velocity = s[i - 1].velocity + u * (s[i].velocity - s[i - 1].velocity);
  s.resize(i);
  s.push_back(at);
  TrajectorySample dropped = at;  // at the foot of the backstop, dead
  dropped.position.y() = std::min(at.position.y(), ball_radius);  // on the flat world's ground
  dropped.velocity.setZero();
  dropped.spin.setZero();
  dropped.phase = Phase::Rest;
  if (dropped.position.y() < at.position.y()) s.push_back(dropped);
  FlightSummary& f = shot.trajectory.summary;
  const Vec3 foot(at.position.x(), dropped.position.y(), at.position.z());
  if (f.hang_time_s > at.t) {  // over the backstop before it came down: its distance ends there
    f.hang_time_s = at.t;
    f.landing_position = foot;
    f.carry_m = std::hypot(foot.x(), foot.z());
    f.lateral_m = foot.z();
  }
  f.rest_position = foot;
  f.total_m = std::hypot(foot.x(), foot.z());
  f.total_time_s = at.t;
  shot.end = ShotEnd::OutOfBounds;
}

}  // namespace

const std::vector<BatterSkill>& batter_skills() {
  static const std::vector<BatterSkill> s = [] {
    BatterSkill pro{"pro", mph_to_mps(71.5), 5.0, 0.004, 0.03};
    // His reads of live pitching (ESTIMATES, set together against MLB's 2024 league rates over
    // 200 seeded games: strikeouts, walks, BABIP, power, whiffs per swing, fouls per pitch,
    // with his aim inside the sweet spot that follows from them, aim.hpp): he reads the type of
    // 85 % of pitches before he must commit, his timing of a pitch he has read is off by 8.5 ms
    // (Brenner et al. measured ~7 ms hitting a falling ball, Front. Hum. Neurosci. 8 (2014)
    // 342; a pitch is faster and breaks), his reach along the barrel by 90 mm and his height by
    // 22 mm (at the contact's ~1.2° of launch per mm of undercut, the spread of the league's
    // launch angles), and where his eye puts the pitch by 30 mm.
    pro.recognition = 0.85;
    pro.read_timing_sd_ms = 8.5;
    pro.read_height_sd = 0.022;
    pro.read_reach_sd = 0.09;
    pro.discipline = 0.05;
    pro.attack_angle = deg_to_rad(10.0);
    pro.swing_tilt = kLeagueSwingTilt;
    pro.sweep = 2.65;
    pro.sprint_speed = 27.0 * 0.3048;
    // The high-school hitter reads pitching about half as well as the pro in every respect
    // (ESTIMATES): against the league's pitcher he strikes out in half his plate appearances.
    BatterSkill amateur{"amateur", mph_to_mps(60.0), 10.0, 0.009, 0.06};
    amateur.recognition = 0.5;
    amateur.read_timing_sd_ms = 13.0;
    amateur.read_height_sd = 0.035;
    amateur.read_reach_sd = 0.09;
    amateur.discipline = 0.11;
    amateur.attack_angle = deg_to_rad(6.0);
    amateur.swing_tilt = kLeagueSwingTilt;
    amateur.sweep = 2.9;
    amateur.sprint_speed = 25.0 * 0.3048;
    return std::vector<BatterSkill>{pro, amateur};
  }();
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

namespace {
// β, round the swing's circle from its low point, where a path climbing at `attack` is met in a
// plane whose slope is `sin_tilt`.
double arc_on_time(double attack, double sin_tilt) {
  return std::asin(std::clamp(std::sin(attack) / sin_tilt, -1.0, 1.0));
}
}  // namespace

double attack_angle_at(double attack, double tilt, double turned) {
  const double st = std::sin(tilt);
  if (st <= 0.0) return attack;
  return std::asin(std::clamp(st * std::sin(arc_on_time(attack, st) - turned), -1.0, 1.0));
}

double vertical_bat_angle_at(double attack, double tilt, double turned) {
  const double st = std::sin(tilt);
  if (st <= 0.0) return 0.0;
  // The axis runs from the circle's centre out to the sweet spot: at β it points down the
  // plane's slope by cos β of it.
  return -std::asin(std::clamp(st * std::cos(arc_on_time(attack, st) - turned), -1.0, 1.0));
}

BallCrossing meet_ball(const Vec3& ball_dir, double attack, double vertical_bat_angle, double reach, double undercut,
                       double early) {
  const Vec3 u0(std::cos(attack), std::sin(attack), 0.0);  // the on-time path
  // The bat's axis on time, toward the tip: across the path, head down by the bat angle.
  const Vec3 a0 = bat_axis_across(u0, Vec3::UnitZ(), vertical_bat_angle);
  const Vec3 n = a0.cross(u0);                             // the plane's normal, up for a level swing
  const Vec3 axis = std::cos(early) * a0 + std::sin(early) * u0;   // the bat turned toward the pitcher
  const Vec3 across = -std::sin(early) * a0 + std::cos(early) * u0;  // in the plane, across the bat
  const Vec3 d = ball_dir.normalized();
  BallCrossing c;
  const double closing = d.dot(across);
  if (std::abs(closing) < 1e-6) return c;
  // From the pivot the ball's centre is at reach·a0 + undercut·n on time, and at λ along its
  // flight from there it lies on the turned axis when it has no part across it. (The ball first
  // touches the bat's front a bat-and-ball radius before that, which moves the contact along
  // the bat by ~7 cm·tan φ: ~4 cm at 30°, early out toward the end, late in toward the hands.
  // Not modelled yet.)
  const Vec3 on_time = reach * a0 + undercut * n;
  const double lambda = -on_time.dot(across) / closing;
  const Vec3 met = on_time + lambda * d;
  c.crosses = true;
  c.from_pivot = met.dot(axis);
  c.undercut = met.dot(n);
  c.ahead = met.x() - on_time.x();
  return c;
}

const char* contact_spot(const BatSpec& bat, double from_tip) {
  if (bat.cor_factor_at(from_tip) >= kBarrelCorFactor) return "on the barrel";
  return from_tip < bat.sweet_spot_from_tip ? "off the end of the bat" : "in on the hands";
}

double contact_lead_for(double inside) {
  return std::clamp(kLeadPerInside * inside, SwingInput::kContactLead.min, SwingInput::kContactLead.max);
}

bool is_barrel(double ev, double la) { return la <= 50.0 && ev >= 98.0 && 1.5 * ev - la >= 117.0 && ev + la >= 124.0; }

SwingResult swing_at(const Assets& assets, const PitchFlight& pitch, const SwingInput& in, double bat_speed,
                     const std::string& bat_name, const FieldingSetup& fielding) {
  check_range("swing.timing", in.timing_ms, SwingInput::kTiming, "ms");
  check_range("swing.undercut", in.undercut, SwingInput::kUndercut, "m");
  check_range("swing.reach_error", in.reach_error, SwingInput::kReach, "m");
  check_range("swing.attack_angle", in.attack_angle, SwingInput::kAttackAngle, "rad");
  check_range("swing.swing_tilt", in.swing_tilt, SwingInput::kSwingTilt, "rad");
  if (std::abs(in.attack_angle) > in.swing_tilt) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "swing.attack_angle: %.1f deg is steeper than the swing's plane (swing.swing_tilt %.1f deg); allowed: |attack_angle| <= swing_tilt",
                  rad_to_deg(in.attack_angle), rad_to_deg(in.swing_tilt));
    throw InputError(msg);
  }
  SwingResult out;
  const EquipmentCatalog& eq = assets.equipment();
  const BatSpec& bat = eq.bat(bat_name);
  const BallSpec& ball = eq.ball("mlb");
  BatSwing s;
  check_range("swing.effort", in.effort, SwingInput::kEffort, "");
  check_range("swing.speed_error", in.speed_error, SwingInput::kSpeedError, "m/s");
  s.bat_speed = (bat_speed + in.speed_error) * (in.power ? 1.0 : 0.92) * in.effort;
  check_range("swing.contact_lead", in.contact_lead, SwingInput::kContactLead, "rad");
  check_range("swing.aim_inside", in.aim_inside, SwingInput::kAimInside, "m");
  // Turned past where he meant to meet it (+ late), from square: the bat met a pitch he meant
  // to meet out front that much sooner round its arc.
  const double turned = bat_turn(s.bat_speed, bat, in.timing_ms) - in.contact_lead;  // rad
  s.direction = std::clamp(turned, BatSwing::kDirection.min, BatSwing::kDirection.max);
  s.attack_angle = std::clamp(attack_angle_at(in.attack_angle, in.swing_tilt, turned), BatSwing::kAttackAngle.min,
                              BatSwing::kAttackAngle.max);
  // A left-handed batter is the mirror image across the mound line: swing at the mirrored
  // pitch as a right-hander, then mirror the batted ball back.
  const double m = in.left_handed ? -1.0 : 1.0;
  const Vec3 v(pitch.plate_velocity.x(), pitch.plate_velocity.y(), m * pitch.plate_velocity.z());
  const Vec3 w(m * pitch.plate_spin.x(), m * pitch.plate_spin.y(), pitch.plate_spin.z());
  // On time the bat is turned by his lead and meets the ball 1/cos(lead) out along its axis
  // from where the ball's line passes: he aims the pitch's line that much nearer.
  const BallCrossing met = meet_ball(v, in.attack_angle, vertical_bat_angle_at(in.attack_angle, in.swing_tilt, 0.0),
                                     (bat.sweet_arm() - in.aim_inside) * std::cos(in.contact_lead) + in.reach_error,
                                     in.undercut, -turned);
  s.impact_from_tip = bat.pivot_to_tip() - met.from_pivot;
  s.undercut = met.undercut;
  s.vertical_bat_angle = std::clamp(vertical_bat_angle_at(in.attack_angle, in.swing_tilt, turned),
                                    BatSwing::kVerticalBatAngle.min, BatSwing::kVerticalBatAngle.max);
  // Statcast tracks every swing, misses too: the sweet spot's path where it passes the ball.
  SwingPath path{s.bat_speed, s.attack_angle, s.direction, in.sweep, in.swing_tilt};
  const double pitch_speed = pitch.release_velocity.norm();  // Statcast's pitch speed is out of the hand
  out.tracking = track_swing(path, bat, pitch_speed, 0.0);
  out.crossing_undercut = met.undercut;
  // A bat along the ball's line, or turned past a right angle, is through the zone; past the
  // end of the bat the ball's edge still catches the end cap's rim up to kEndCapReach of its
  // radius.
  // The crossing's geometry repeats every turn of the bat: a swing 150 ms early (the bat ~6.8
  // rad round) would otherwise meet the ball as one ~20° early and pull it foul at 90°.
  const bool through = !met.crosses || met.from_pivot <= 0.0 || std::abs(turned) >= 0.5 * kPi;
  const Range on_bat = bat_contact_range(bat, ball);
  out.past_end = !through && s.impact_from_tip < on_bat.min;
  out.through = through;
  // Past the end the ball crosses the axis's extension, up to metres out along its flight
  // where it descends across the swing plane: its height there says nothing of the bat. The
  // height that mends the next swing is where he set the bat against the ball on time.
  if (out.past_end) out.crossing_undercut = in.undercut;
  if (through || out.past_end) return out;
  s.impact_from_tip = std::min({s.impact_from_tip, kHandsFromTip, on_bat.max});
  Delivery d;
  try {
    d = deliver_baseball(ball, bat, s, v, w, bat.material);
  } catch (const InputError&) {
    return out;  // the bat passes above or below the ball: a swing and a miss
  }
  LaunchMetrics L = measure_launch(d.launch);
  out.contact = true;
  out.impact_from_tip = s.impact_from_tip;
  out.contact_time = d.contact_time;
  out.normal_impulse = d.impact.normal_impulse;
  out.tracking = track_swing(path, bat, pitch_speed, L.ball_speed);
  // Back toward the catcher: a foul behind the plate, or a foul tip into the mitt.
  const Vec3 out_dir = d.launch.velocity.normalized();
  out.foul_tip = std::acos(std::clamp(out_dir.dot(v.normalized()), -1.0, 1.0)) < kFoulTipCone;
  const bool backward = std::abs(L.horizontal_angle) > 0.5 * kPi;
  if (backward) L.horizontal_angle = (L.horizontal_angle > 0.0 ? kPi : -kPi) - L.horizontal_angle;  // flown mirrored
  if (in.left_handed) {
    L.horizontal_angle = -L.horizontal_angle;
    L.spin.axis_rad = -L.spin.axis_rad;
  }
  ShotSpec spec;
  spec.sport = "baseball";
  LaunchStrike ls;
  ls.numbers.ball_speed = std::min(L.ball_speed, LaunchNumbers::kBallSpeed.max);
  ls.numbers.vertical_angle = std::clamp(L.vertical_angle, LaunchNumbers::kVerticalAngle.min, LaunchNumbers::kVerticalAngle.max);
  ls.numbers.horizontal_angle = std::clamp(L.horizontal_angle, LaunchNumbers::kHorizontalAngle.min, LaunchNumbers::kHorizontalAngle.max);
  ls.numbers.spin = std::min(L.spin.total, LaunchNumbers::kSpin.max);
  ls.numbers.spin_axis = L.spin.axis_rad;
  spec.strike = ls;
  const ResolvedShot resolved = resolve(spec, assets);
  if (backward) {
    // Behind the plate there is only the backstop: the ball flies as its mirror image over
    // open field and is mirrored back (x → −x) for its landing spot and for drawing.
    spec.world = kFlatWorld;
    const ResolvedShot open = resolve(spec, assets);
    out.shot = run_shot(open, "swing", {true, true});
    mirror_behind_plate(out.shot);
    stop_at_backstop(out.shot, ball.radius);
    out.outcome = BattedOutcome::Foul;
  } else {
    out.shot = run_shot(resolved, "swing", {true, true});
    stop_at_backstop(out.shot, ball.radius);  // a pop-up drifting back over the backstop
  }
  static const Defense kLeague = league_defense();
  if (!fielding.field) {
    out.outcome = backward ? BattedOutcome::Foul : out.shot.end == ShotEnd::HomeRun ? BattedOutcome::HomeRun
                                                                                   : BattedOutcome::Out;
    if (!backward && out.shot.end != ShotEnd::HomeRun && !is_fair_ball(out.shot)) out.outcome = BattedOutcome::Foul;
  } else {
  out.play = field_play(out.shot, *resolved.aero, resolved.spec.environment, fielding.defense ? *fielding.defense : kLeague,
                        in.left_handed, fielding.batter_sprint, fielding.rng);
  if (!backward) out.outcome = out.play.outcome;
  else if (out.play.caught && !out.foul_tip) out.outcome = BattedOutcome::Out;  // a caught tip is a strike
  if (out.play.fielder >= 0) out.fielder = kPositionNames[static_cast<std::size_t>(out.play.fielder)];
  }
  const double ev = mps_to_mph(L.ball_speed), la = rad_to_deg(L.vertical_angle);
  out.hard_hit = ev >= 95.0;
  out.sweet_spot = !backward && la >= 8.0 && la <= 32.0;
  out.barrel = !backward && is_barrel(ev, la);
  return out;
}

}  // namespace sweetspot
