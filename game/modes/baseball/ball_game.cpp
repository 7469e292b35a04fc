#include "game/modes/baseball/ball_game.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "game/modes/baseball/aim.hpp"
#include "game/modes/baseball/base_running.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr int kMaxExtra = 40;          // extra innings before a game still tied is stopped (MLB's longest: 26 innings)

}  // namespace

bool bats_left(int order) { return order == 1 || order == 3 || order == 5 || order == 8; }

const char* lineup_position(int order) {
  static constexpr std::array<const char*, 9> kPositions{"CF", "SS", "RF", "1B", "DH", "3B", "LF", "C", "2B"};
  return kPositions[static_cast<std::size_t>(order) % kPositions.size()];
}

bool Team::to_the_bullpen(const MoundVisit& v, std::uint64_t seed) {
  if (pitchers_used >= kMaxPitchers) return false;
  const int thrown = pitcher.pitches_thrown();
  const bool starter = pitchers_used == 1;
  const bool long_man = !starter && (entered_inning <= kLongReliefBy || std::abs(entered_lead) >= kBlowoutRuns);
  const int outs_limit = long_man ? kLongReliefOuts : 3, pitch_limit = long_man ? kLongReliefPitches : kRelieverPitches;
  bool done = v.runs_this_inning >= kBlowUpRuns;
  if (v.inning_start)
    done = done || (starter ? thrown >= kStarterPitches || (v.inning > kStarterInnings && thrown >= kStarterCruising)
                            : thrown > 0 && (v.outs_recorded >= outs_limit || thrown >= pitch_limit));
  else if (starter)
    done = done || thrown >= kStarterLimit || (thrown >= kStarterPitches - 15 && v.runners >= 2);
  else
    done = done || (thrown >= pitch_limit && v.runners >= 1) || thrown >= pitch_limit + 10;
  if (!done) return false;
  const bool left = draws_left_handed(seed ^ 0x1EF7A4D5C0FFEE11ULL, kLeftRelieverShare);
  pitcher = Pitcher(league_average_pitcher(types_, left), seed);
  report = left ? left_report_ : right_report_;
  ++pitchers_used;
  entered_inning = v.inning;
  entered_lead = v.lead;
  return true;
}

namespace {
// The starter's hand, from the team's seed.
bool starter_left(std::uint64_t seed) { return draws_left_handed(seed ^ 0x57A27E5C0FFEE22ULL, kLeftStarterShare); }

// The same pitches thrown with the other hand: mirror images, their side-to-side break the
// other way (the flights are the same, so none is thrown again).
ScoutingReport mirrored(ScoutingReport r) {
  for (ScoutingReport::Type& t : r.types) t.horizontal_break = -t.horizontal_break;
  r.fastball.horizontal_break = -r.fastball.horizontal_break;
  return r;
}
}  // namespace

Team::Team(const Assets& assets, std::string team_name, const BatterSkill& skill, std::uint64_t seed)
    : name(std::move(team_name)),
      pitcher(league_average_pitcher(load_pitch_types(assets), starter_left(seed)), seed ^ 0x9E3779B97F4A7C15ULL),
      report(scout(assets, pitcher.profile())),
      fielding_rng(seed ^ 0xF1E1D1C1B1A19181ULL),
      types_(pitcher.profile().arsenal),
      right_report_(pitcher.profile().left_handed ? mirrored(report) : report),
      left_report_(pitcher.profile().left_handed ? report : mirrored(report)) {
  Rng r(seed);
  const double aim = aim_inside(assets, skill, kGameBat);
  for (int i = 0; i < 9; ++i) lineup.emplace_back(skill, bats_left(i), r.next(), aim);
  defense = draw_defense(r);
}

PlateAppearance plate_appearance(const Assets& assets, Hitter& batter, Team& field) {
  PlateAppearance pa;
  Count count;
  for (;;) {
    PitchRecord rec;
    rec.count = count;
    rec.planned = field.pitcher.next(count, batter.left_handed());
    rec.flight = throw_pitch(assets, rec.planned.call);
    rec.read = batter.read(rec.flight, rec.planned.call.type.type, field.report, count);
    rec.swung = batter.swings(rec.read, count);
    if (!rec.swung) {
      if (hits_batter(rec.flight.plate, batter.left_handed(), kBaseballRadius)) rec.call = PitchResult::HitByPitch;
      else rec.call = StrikeZone::contains(rec.flight.plate, kBaseballRadius) ? PitchResult::CalledStrike : PitchResult::Ball;
    } else {
      rec.swing = batter.swing(rec.read, count);
      FieldingSetup setup{&field.defense, batter.skill().sprint_speed, &field.fielding_rng};
      rec.result = swing_at(assets, rec.flight, rec.swing, batter.skill().bat_speed, kGameBat, setup);
      const BattedOutcome o = rec.result.outcome;
      if (!rec.result.contact) rec.call = PitchResult::SwingingStrike;
      else if (o == BattedOutcome::Foul) rec.call = rec.result.foul_tip ? PitchResult::FoulTip : PitchResult::Foul;
      else rec.call = PitchResult::InPlay;
    }
    const PlateEnd end = apply_pitch(count, rec.call);
    pa.pitches.push_back(std::move(rec));
    const PitchRecord& last = pa.pitches.back();
    switch (end) {
      case PlateEnd::None: continue;
      case PlateEnd::Strikeout:
        pa.result = "strikeout";
        pa.description = last.call == PitchResult::CalledStrike ? "Strikeout looking"
                         : last.call == PitchResult::FoulTip      ? "Strikeout on a foul tip"
                                                                  : "Strikeout swinging";
        return pa;
      case PlateEnd::Walk:
        pa.result = "walk";
        pa.description = "Walk";
        return pa;
      case PlateEnd::HitByPitch:
        pa.result = "hit_by_pitch";
        pa.description = "Hit by pitch";
        return pa;
      case PlateEnd::InPlay:
        pa.result = to_string(last.result.outcome);
        pa.description = last.result.play.description;
        return pa;
    }
  }
}

void walk_off_limit(PlateAppearance& pa, const GameSituation& s, std::vector<int>& scored) {
  const int needed = s.away_runs - s.home_runs + 1;
  if (needed <= 0 || static_cast<int>(scored.size()) < needed) return;
  scored.resize(static_cast<std::size_t>(needed));
  const int winner = scored.back();
  int from = 0;  // the base the winning runner started from (0: the batter)
  for (int b = 0; b < 3; ++b)
    if (pa.bases_before[static_cast<std::size_t>(b)] == winner) from = b + 1;
  static const char* kHits[] = {"single", "double", "triple"};
  const int took = 4 - from;
  for (int h = 0; h < 3; ++h)
    if (pa.result == kHits[h] && took < h + 1) {
      pa.result = kHits[took - 1];
      // The hit's name is all before " to " ("Ground-rule double to RF" is two words).
      const std::string words = pa.result == "single" ? "Single" : pa.result == "double" ? "Double" : "Triple";
      const std::size_t where = pa.description.find(" to ");
      pa.description = words + (where == std::string::npos ? std::string() : pa.description.substr(where));
    }
  pa.rbi = std::min(pa.rbi, needed);
}

namespace {

void credit_batter(BattingLine& l, const PlateAppearance& pa) {
  ++l.pa;
  const std::string& r = pa.result;
  if (r == "walk") ++l.bb;
  else if (r == "hit_by_pitch") ++l.hbp;
  else if (pa.sacrifice_fly) ++l.sf;
  else ++l.ab;
  if (r == "strikeout") ++l.so;
  if (r == "single" || r == "double" || r == "triple" || r == "home_run") ++l.h;
  if (r == "double") ++l.doubles;
  if (r == "triple") ++l.triples;
  if (r == "home_run") ++l.hr;
  l.rbi += pa.rbi;
}

void charge_pitcher(PitchingLine& p, const PlateAppearance& pa) {
  ++p.batters;
  for (const PitchRecord& x : pa.pitches) {
    ++p.pitches;
    if (x.call != PitchResult::Ball && x.call != PitchResult::HitByPitch) ++p.strikes;
  }
  const std::string& r = pa.result;
  if (r == "walk") ++p.bb;
  if (r == "hit_by_pitch") ++p.hbp;
  if (r == "strikeout") ++p.so;
  if (r == "single" || r == "double" || r == "triple" || r == "home_run") ++p.h;
  if (r == "home_run") ++p.hr;
  p.outs += pa.outs_made;
}

bool on(const Bases& b, int who) { return std::find(b.begin(), b.end(), who) != b.end(); }

}  // namespace

GameRecord play_game(const Assets& assets, const GameOptions& o) {
  check_range("--innings", o.innings, GameOptions::kInnings, "");
  GameRecord g;
  g.options = o;
  Team teams[2] = {Team(assets, "away", batter_skill(o.away), o.seed * 2 + 1),
                   Team(assets, "home", batter_skill(o.home), o.seed * 2 + 2)};
  TeamBox box[2];
  for (int t = 0; t < 2; ++t) {
    box[t].name = teams[t].name;
    box[t].batting.assign(9, BattingLine{});
    box[t].pitchers.assign(1, PitchingLine{});
    box[t].pitchers.front().left_handed = teams[t].pitcher.profile().left_handed;
  }
  int next_up[2] = {0, 0};
  std::vector<ScoreAfter> score_log;  // for the decisions
  GameSituation s;
  s.scheduled = o.innings;
  const HalfInning half_start = empty_half_inning(assets);
  Rng throws(o.seed * 0x9E3779B97F4A7C15ULL + 0x7468726F77ULL);  // the throws as they come (base_running.hpp)
  for (s.inning = 1; s.inning <= o.innings + kMaxExtra; ++s.inning) {
    for (int half = 0; half < 2; ++half) {
      s.bottom = half == 1;
      s.outs = 0;
      if (s.bottom && s.inning >= s.scheduled && s.home_runs > s.away_runs) break;  // the home team need not bat
      Team& bat = teams[half];
      Team& field = teams[1 - half];
      TeamBox& fbox = box[1 - half];
      HalfInning h = half_start;
      // Runners whose runs are unearned (Rule 9.16): a batter who reached on an error, and
      // extra innings' placed runner.
      std::array<bool, 9> unearned{};
      RunnerCharges charges;
      // Extra innings start with a runner on second: the batter before this half's leadoff
      // man (MLB Rule 7.01(b), since 2023).
      if (s.inning > s.scheduled) {
        h.bases[1] = (next_up[half] + 8) % 9;
        unearned[static_cast<std::size_t>(h.bases[1])] = true;
        ++box[half].placed_runners;
      }
      int runs = 0;
      int runs_on_watch = 0;  // scored this half while the pitcher now on the mound pitched
      // Errors that put a batter aboard this half: each would have been an out (Rule 9.16(a)),
      // and runs that score once those and the real outs make three are unearned.
      int errors_as_outs = 0;
      bool inning_start = true;
      while (h.outs < 3) {
        // The fielding team's bullpen: the manager's look before each batter.
        const Team::MoundVisit visit{s.inning, inning_start, runners_on(h.bases), runs_on_watch, fbox.pitchers.back().outs,
                                     s.bottom ? s.away_runs - s.home_runs : s.home_runs - s.away_runs};
        const std::uint64_t mound_seed = o.seed * 1000003ULL + static_cast<std::uint64_t>(2 * s.inning + half) +
                                         (inning_start ? 0ULL : 7919ULL * static_cast<std::uint64_t>(field.pitchers_used));
        const bool change = field.to_the_bullpen(visit, mound_seed);
        if (change) {
          PitchingLine fresh;
          fresh.lead_at_entry = visit.lead;
          fresh.runners_at_entry = visit.runners;
          fresh.inherited = inning_start ? 0 : visit.runners;  // extra innings' runner is his own
          fresh.left_handed = field.pitcher.profile().left_handed;
          fbox.pitchers.push_back(fresh);
          runs_on_watch = 0;
        }
        const int mound = static_cast<int>(fbox.pitchers.size()) - 1;
        if (inning_start && h.bases[1] >= 0) charges.reached(h.bases[1], mound);
        inning_start = false;
        const int batter = next_up[half];
        next_up[half] = (batter + 1) % 9;
        PlateAppearance pa = plate_appearance(assets, bat.lineup[static_cast<std::size_t>(batter)], field);
        pa.inning = s.inning;
        pa.bottom = s.bottom;
        pa.batter = batter;
        pa.outs_before = h.outs;
        pa.bases_before = h.bases;
        pa.pitcher = mound;
        pa.pitching_change = change;
        std::vector<int> scored;
        if (pa.result == "walk" || pa.result == "hit_by_pitch") {
          if (force_advance(h.bases, batter) > 0) scored.push_back(pa.bases_before[2]);
          pa.rbi = static_cast<int>(scored.size());
        } else if (pa.result == "strikeout") {
          ++h.outs;
          pa.outs_made = 1;
        } else {
          int outs_made = 0;
          h.runs_to_win = s.bottom && s.inning >= s.scheduled ? std::max(0, s.away_runs - s.home_runs + 1) : 0;
          h.advance(pa, bat, field, throws, scored, outs_made, pa.description);
          pa.outs_made = outs_made;
          const bool error = pa.result == "error";
          // No run batted in on a ground ball into a double play (Rule 9.04(b)(1)).
          const bool double_play = pa.description.rfind("Grounded into a double play", 0) == 0;
          pa.sacrifice_fly = pa.result == "out" && pa.pitches.back().result.play.caught && !scored.empty();
          // The scorer's words for it: a run scored on the catch is a sacrifice fly.
          if (pa.sacrifice_fly)
            for (const char* caught : {"Fly out to ", "Line out to ", "Pop out to "})
              if (pa.description.rfind(caught, 0) == 0) {
                pa.description = "Sacrifice fly to " + pa.description.substr(std::string(caught).size());
                break;
              }
          pa.rbi = error || double_play ? 0 : static_cast<int>(scored.size());
          if (error) ++fbox.errors;
        }
        if (s.bottom && s.inning >= s.scheduled && pa.result != "home_run") {
          // Runners whose runs no longer count are left on base.
          const std::size_t crossed = scored.size();
          walk_off_limit(pa, s, scored);
          box[half].left_on_base += static_cast<int>(crossed - scored.size());
        }
        pa.runs = static_cast<int>(scored.size());
        unearned[static_cast<std::size_t>(batter)] = pa.result == "error";
        // Who answers for each runner (Rule 9.16(g)): the batter aboard is this pitcher's,
        // unless he reached on a fielder's choice that put out a runner another let on.
        const bool batter_aboard = on(h.bases, batter) || (!scored.empty() && scored.back() == batter);
        if (batter_aboard) charges.reached(batter, mound);
        if (pa.result == "out" && on(h.bases, batter))
          for (int was : pa.bases_before)
            if (was >= 0 && !on(h.bases, was) && std::find(scored.begin(), scored.end(), was) == scored.end())
              charges.fielders_choice(batter, was);
        ScoreAfter after{1 - half, mound, 0, 0, {}};
        int earned = 0;
        // The inning as it would have gone without the errors: over before this play, or
        // ended by this play's out (a sacrifice fly or a force for the third out: the pitcher
        // has the benefit of the doubt, Rule 9.16), or by this play itself when it is the
        // error (with two out, the batter put out as he should have been ends the inning, and
        // no run scores on it: Rule 5.08(a)). With no error in the half the inning is as it
        // went: a run that beat the third out on its play (a time play) counted, and is earned.
        const bool this_error = pa.result == "error";
        const bool past_the_third_out = pa.outs_before + errors_as_outs + this_error >= 3 ||
                                        (pa.outs_made > 0 && errors_as_outs > 0 && h.outs + errors_as_outs >= 3);
        for (int who : scored) {
          ++box[half].batting[static_cast<std::size_t>(who)].r;
          const bool is_earned = !unearned[static_cast<std::size_t>(who)] && !past_the_third_out;
          earned += is_earned;
          const int charged = charges.charged(who);
          PitchingLine& answers = fbox.pitchers[static_cast<std::size_t>(charged)];
          ++answers.r;
          answers.er += is_earned;
          if (charged != mound) ++fbox.pitchers[static_cast<std::size_t>(mound)].inherited_scored;
          after.charged.push_back(charged);
        }
        pa.earned_runs = earned;
        if (pa.result == "error") ++errors_as_outs;
        runs += pa.runs;
        runs_on_watch += pa.runs;
        (s.bottom ? s.home_runs : s.away_runs) += pa.runs;
        credit_batter(box[half].batting[static_cast<std::size_t>(batter)], pa);
        charge_pitcher(fbox.pitching, pa);
        charge_pitcher(fbox.pitchers.back(), pa);
        fbox.pitching.r += pa.runs;
        fbox.pitching.er += earned;
        after.away = s.away_runs;
        after.home = s.home_runs;
        score_log.push_back(std::move(after));
        g.plate_appearances.push_back(std::move(pa));
        s.outs = h.outs;
        if (s.bottom && game_over(s) && h.outs < 3) {
          g.walk_off = true;
          break;
        }
      }
      for (int b : h.bases)
        if (b >= 0) ++box[half].left_on_base;
      box[half].runs_by_inning.push_back(runs);
      g.innings_played = s.inning;
      s.outs = h.outs;
      if (game_over(s)) break;
    }
    s.outs = 3;
    if (game_over(s)) break;
  }
  g.stopped_tied = s.away_runs == s.home_runs;
  for (int t = 0; t < 2; ++t) {
    box[t].runs = t == 0 ? s.away_runs : s.home_runs;
    for (const BattingLine& l : box[t].batting) box[t].hits += l.h;
  }
  assign_decisions(score_log, o.innings, box[0], box[1]);
  g.away = box[0];
  g.home = box[1];
  return g;
}

BattingRates batting_rates(const std::vector<PlateAppearance>& pas, int which) {
  BattingRates r;
  int k = 0, bb = 0, hbp = 0, hr = 0, h = 0, ab = 0, tb = 0, sf = 0, zone = 0, chase_swings = 0, outside = 0;
  int squared = 0, blasts = 0;
  double bat_speed = 0.0, length = 0.0;
  for (const PlateAppearance& pa : pas) {
    if (which != 2 && pa.bottom != (which == 1)) continue;
    ++r.pa;
    const std::string& x = pa.result;
    if (x == "strikeout") ++k;
    if (x == "walk") ++bb;
    if (x == "hit_by_pitch") ++hbp;
    if (x == "home_run") ++hr;
    const bool hit = x == "single" || x == "double" || x == "triple" || x == "home_run";
    h += hit;
    tb += x == "single" ? 1 : x == "double" ? 2 : x == "triple" ? 3 : x == "home_run" ? 4 : 0;
    if (pa.sacrifice_fly) ++sf;
    else if (x != "walk" && x != "hit_by_pitch") ++ab;
    for (const PitchRecord& p : pa.pitches) {
      ++r.pitches;
      const bool in = StrikeZone::contains(p.flight.plate, kBaseballRadius);
      zone += in;
      outside += !in;
      if (!p.swung) continue;
      ++r.swings;
      chase_swings += !in;
      r.whiffs += p.call == PitchResult::SwingingStrike;
      r.fouls += p.call == PitchResult::Foul || p.call == PitchResult::FoulTip;
      r.balls_in_play += p.call == PitchResult::InPlay;
      squared += p.result.tracking.is_squared_up;
      blasts += p.result.tracking.blast;
      bat_speed += mps_to_mph(p.result.tracking.bat_speed_mps);
      length += m_to_ft(p.result.tracking.swing_length_m);
    }
  }
  const auto ratio = [](double a, double b) { return b > 0.0 ? a / b : 0.0; };
  r.k_rate = ratio(k, r.pa);
  r.bb_rate = ratio(bb, r.pa);
  r.hbp_rate = ratio(hbp, r.pa);
  r.hr_rate = ratio(hr, r.pa);
  r.avg = ratio(h, ab);
  r.obp = ratio(h + bb + hbp, ab + bb + hbp + sf);
  r.slg = ratio(tb, ab);
  r.babip = ratio(h - hr, ab - k - hr + sf);
  r.whiff_per_swing = ratio(r.whiffs, r.swings);
  r.foul_per_pitch = ratio(r.fouls, r.pitches);
  r.swing_rate = ratio(r.swings, r.pitches);
  r.zone_rate = ratio(zone, r.pitches);
  r.chase_rate = ratio(chase_swings, outside);
  r.squared_up_per_swing = ratio(squared, r.swings);
  r.blast_per_swing = ratio(blasts, r.swings);
  r.mean_bat_speed_mph = ratio(bat_speed, r.swings);
  r.mean_swing_length_ft = ratio(length, r.swings);
  return r;
}

}  // namespace sweetspot
