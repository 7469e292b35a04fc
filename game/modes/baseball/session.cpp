#include "game/modes/baseball/session.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "game/modes/baseball/aim.hpp"
#include "game/modes/baseball/ball_game.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

constexpr double kDerbySpeed = 27.7;           // m/s, ~62 mph

}  // namespace

PitchCall derby_pitch(const std::vector<PitchType>& types, Rng& rng) {
  PitchCall c;
  c.type = pitch_type(types, "four-seam");
  c.type.speed = kDerbySpeed;
  c.type.spin = rpm_to_radps(1800.0);  // a lob spins less (ESTIMATE)
  c.target_height = 0.80 + rng.normal(0.05);
  c.target_side = rng.normal(0.05);
  return c;
}

BotBatter::BotBatter(const Assets& assets, const BatterSkill& skill, std::uint64_t seed)
    : assets_(assets), skill_(skill), rng_(seed) {}

SwingInput BotBatter::plan(const PitchFlight& pitch, bool derby, bool left_handed) {
  SwingInput s;
  s.left_handed = left_handed;
  s.attack_angle = skill_.attack_angle;
  s.swing_tilt = skill_.swing_tilt;
  s.sweep = skill_.sweep;
  s.contact_lead = contact_lead_for(inside_by(pitch.plate, left_handed));
  // A batting-practice lob comes where he expects it along the bat (no reach error here), so
  // he aims at the sweet spot itself (aim.hpp is for the live hitter's scatter).
  double timing = 0.0;
  if (derby) {
    // Where to meet the ball to clear the fence by the most: how early (pulling toward the
    // shorter fence down the line) and how far under it — found once by trying, as a hitter
    // learns it in batting practice.
    if (!derby_planned_) {
      derby_planned_ = true;
      const WorldAsset* park = assets_.world("ballpark");
      // The margin by which it clears (or falls short of) the fence, averaged over the
      // batter's usual timing spread (a few ms turn the swing's path up or down, and the ball
      // pull or oppo): a plan that a few ms turn foul is a bad plan.
      const auto margin = [&](double t, double u) {
        SwingInput trial = s;
        trial.timing_ms = t;
        trial.undercut = u;
        FieldingSetup flight_only;
        flight_only.field = false;
        const SwingResult r = swing_at(assets_, pitch, trial, skill_.bat_speed, kGameBat, flight_only);
        if (!r.contact || r.outcome == BattedOutcome::Foul) return -200.0;
        const Vec3& land = r.shot.trajectory.summary.landing_position;
        return (r.outcome == BattedOutcome::HomeRun ? 30.0 : 0.0) + std::hypot(land.x(), land.z()) -
               fence_distance(*park, std::atan2(land.z(), land.x()));
      };
      // Neighbouring plans share their trial swings (t ± sd lands on the grid): try each once.
      std::map<std::pair<long long, long long>, double> tried;
      const auto trial_margin = [&](double t, double u) {
        const auto key = std::make_pair(std::llround(t * 1e3), std::llround(u * 1e6));
        const auto it = tried.find(key);
        return it != tried.end() ? it->second : tried.emplace(key, margin(t, u)).first->second;
      };
      double best = -1e9;
      for (double t = -8.0; t <= 0.0; t += 1.0) {
        for (double u = -0.006; u <= 0.036; u += 0.003) {
          const double sd = skill_.timing_sd_ms;
          const double m = (trial_margin(t - sd, u) + trial_margin(t, u) + trial_margin(t + sd, u)) / 3.0;
          if (m > best) {
            best = m;
            derby_undercut_ = u;
            derby_timing_ = t;
          }
        }
      }
    }
    s.undercut = derby_undercut_;
    timing = derby_timing_;
  } else {
    s.undercut = 0.010;  // a line drive: launch ~15-20°
  }
  s.timing_ms = std::clamp(timing + rng_.normal(skill_.timing_sd_ms), SwingInput::kTiming.min, SwingInput::kTiming.max);
  s.undercut = std::clamp(s.undercut + rng_.normal(skill_.height_sd), SwingInput::kUndercut.min, SwingInput::kUndercut.max);
  // No two swings run at the same speed (BatterSkill::bat_speed_sd), in batting practice as
  // in a game.
  s.speed_error = std::clamp(rng_.normal(skill_.bat_speed_sd * skill_.bat_speed), SwingInput::kSpeedError.min,
                             SwingInput::kSpeedError.max);
  return s;
}

std::vector<SwingRecord> run_session(const Assets& assets, const SessionOptions& o, BotBatter& bot, std::uint64_t seed) {
  if (o.mode != "derby" && o.mode != "at-bat" && o.mode != "practice")
    throw InputError("mode '" + o.mode + "' (allowed: derby, at-bat, practice)");
  check_range("outs", o.outs, SessionOptions::kOuts, "");
  check_range("swings", o.swings, SessionOptions::kSwings, "");
  const std::vector<PitchType> types = load_pitch_types(assets);
  Rng pitcher(seed ^ 0x5EEDBA5EBA11ULL);
  std::vector<SwingRecord> out;
  if (o.mode == "derby" || o.mode == "practice") {
    int outs = 0;
    while (o.mode == "derby" ? outs < o.outs : static_cast<int>(out.size()) < o.swings) {
      SwingRecord rec;
      rec.call = derby_pitch(types, pitcher);
      rec.pitch = throw_pitch(assets, rec.call);
      const SwingInput s = bot.plan(rec.pitch, o.mode == "derby", o.left_handed);
      rec.timing_ms = s.timing_ms;
      rec.undercut = s.undercut;
      rec.result = swing_at(assets, rec.pitch, s, bot.skill().bat_speed);
      rec.call_text = to_string(rec.result.outcome);
      if (rec.result.outcome != BattedOutcome::HomeRun) ++outs;
      out.push_back(std::move(rec));
    }
    return out;
  }
  // An at-bat: the league's pitcher against the bot's skill, pitch by pitch (ball_game.hpp).
  Team pitching(assets, "pitching", bot.skill(), seed);
  Hitter hitter(bot.skill(), o.left_handed, seed ^ 0xB47B47B47ULL, aim_inside(assets, bot.skill(), kGameBat));
  const PlateAppearance pa = plate_appearance(assets, hitter, pitching);
  for (const PitchRecord& p : pa.pitches) {
    SwingRecord rec;
    rec.call = p.planned.call;
    rec.pitch = p.flight;
    rec.swung = p.swung;
    rec.timing_ms = p.swing.timing_ms;
    rec.undercut = p.swing.undercut;
    rec.result = p.result;
    rec.call_text = p.call == PitchResult::InPlay ? to_string(p.result.outcome) : to_string(p.call);
    out.push_back(std::move(rec));
  }
  return out;
}

}  // namespace sweetspot
