#include "game/modes/baseball/hitter.hpp"

#include <algorithm>
#include <cmath>

namespace sweetspot {
namespace {

// His aim: the ball's centre 15 mm above the bat's axis (launch ~29° on time at his 10°
// attack against the league's fastball); his misreads, and early contact rolled over, bring
// the balls he puts in play to ~11° on average, Statcast's league ~12°.
constexpr double kAimUndercut = 0.015;  // m
// With two strikes he protects the plate: he offers at what he sees within this of the zone
// (ESTIMATE).
constexpr double kProtect = 0.05;  // m

}  // namespace

const ScoutingReport::Type& ScoutingReport::of(const std::string& type) const {
  for (const Type& t : types)
    if (t.type == type) return t;
  return fastball;
}

ScoutingReport scout(const Assets& assets, const PitcherProfile& pitcher) {
  ScoutingReport r;
  double fastest = -1.0;
  for (const PitchType& t : pitcher.arsenal) {
    PitchCall c;
    c.type = t;
    c.left_handed = pitcher.left_handed;
    c.target_height = 0.5 * (StrikeZone::kLow + StrikeZone::kHigh);
    const PitchFlight f = throw_pitch(assets, c);
    r.types.push_back({t.type, f.flight_time, f.flight_break_vertical, f.flight_break_horizontal});
    if (t.speed > fastest) {
      fastest = t.speed;
      r.fastball = r.types.back();
    }
  }
  return r;
}

double zone_swing_share(const Count& c) {
  if (c.balls == 3 && c.strikes == 0) return 0.2;
  return c.strikes == 0 ? 0.6 : c.strikes == 1 ? 0.72 : 0.9;
}

Hitter::Hitter(const BatterSkill& skill, bool left_handed, std::uint64_t seed, double aim_inside)
    : skill_(skill), left_(left_handed), aim_inside_(aim_inside), rng_(seed) {}

PitchRead Hitter::read(const PitchFlight& pitch, const std::string& type, const ScoutingReport& report, const Count& c) {
  PitchRead r;
  const double spread = c.strikes == 2 ? kTwoStrikeSpread : 1.0;
  r.recognized = rng_.uniform() < skill_.recognition;
  // He expects the type he recognises, or the fastball he sits on.
  const ScoutingReport::Type& expect = r.recognized ? report.of(type) : report.fastball;
  // The break after the commit point: a constant push over the flight moves the ball by its
  // whole break × (t/T)² in the last t of it; he expects his type's, it does its own.
  const double T = pitch.flight_time;
  const double unseen = std::pow(std::min(kCommitTime, T) / T, 2.0);
  const double dy = (pitch.flight_break_vertical - expect.vertical_break) * unseen;
  const double dz = (pitch.flight_break_horizontal - expect.horizontal_break) * unseen;
  const double away = left_ ? -1.0 : 1.0;  // + z is away from a right-handed batter
  // Where his eye puts the ball is where he swings: a pitch he chased because he saw it over
  // the plate is one his bat is aimed away from.
  const double eye_y = rng_.normal(skill_.eye_sd), eye_z = rng_.normal(skill_.eye_sd);
  r.height_error = dy + rng_.normal(spread * skill_.read_height_sd) + eye_y;
  r.away_error = away * dz + rng_.normal(spread * skill_.read_reach_sd) + away * eye_z;
  // A slower pitch than he expects arrives late by the share of its flight he did not see.
  r.timing_error_ms = -1000.0 * (T - expect.flight_time) * std::min(kCommitTime, T) / T + rng_.normal(spread * skill_.read_timing_sd_ms);
  r.seen = pitch.plate - Vec3(0.0, r.height_error, away * r.away_error);
  return r;
}

bool Hitter::swings(const PitchRead& r, const Count& c) {
  // Out of the zone as he sees it, the farther out the less often he offers; with two
  // strikes he protects the plate as if the zone were wider.
  const double outside = std::max(0.0, StrikeZone::outside_by(r.seen, kBaseballRadius) - (c.strikes == 2 ? kProtect : 0.0));
  return rng_.uniform() < zone_swing_share(c) * std::exp(-outside / skill_.discipline);
}

SwingInput Hitter::swing(const PitchRead& r, const Count& c) {
  SwingInput s;
  const bool two = c.strikes == 2;
  s.effort = two ? kTwoStrikeEffort : 1.0;
  s.left_handed = left_;
  s.attack_angle = skill_.attack_angle;
  s.swing_tilt = skill_.swing_tilt;
  s.sweep = skill_.sweep * (two ? kTwoStrikeSweep : 1.0);
  s.timing_ms = std::clamp(r.timing_error_ms, SwingInput::kTiming.min, SwingInput::kTiming.max);
  s.undercut = std::clamp(kAimUndercut + r.height_error, SwingInput::kUndercut.min, SwingInput::kUndercut.max);
  s.aim_inside = aim_inside_;
  s.reach_error = std::clamp(r.away_error, SwingInput::kReach.min, SwingInput::kReach.max);
  // He meets it where he sees it: an inside pitch out front.
  s.contact_lead = contact_lead_for(inside_by(r.seen, left_));
  s.speed_error = std::clamp(rng_.normal(skill_.bat_speed_sd * skill_.bat_speed), SwingInput::kSpeedError.min,
                             SwingInput::kSpeedError.max);
  return s;
}

}  // namespace sweetspot
