#include "game/rules/baseball_game.hpp"

#include <algorithm>
#include <numeric>

namespace sweetspot {

const char* to_string(PitchResult r) {
  switch (r) {
    case PitchResult::Ball: return "ball";
    case PitchResult::CalledStrike: return "called_strike";
    case PitchResult::SwingingStrike: return "swinging_strike";
    case PitchResult::Foul: return "foul";
    case PitchResult::FoulTip: return "foul_tip";
    case PitchResult::InPlay: return "in_play";
    case PitchResult::HitByPitch: return "hit_by_pitch";
  }
  return "?";
}

PlateEnd apply_pitch(Count& c, PitchResult r) {
  switch (r) {
    case PitchResult::Ball:
      return ++c.balls >= 4 ? PlateEnd::Walk : PlateEnd::None;
    case PitchResult::CalledStrike:
    case PitchResult::SwingingStrike:
    case PitchResult::FoulTip:
      return ++c.strikes >= 3 ? PlateEnd::Strikeout : PlateEnd::None;
    case PitchResult::Foul:
      if (c.strikes < 2) ++c.strikes;
      return PlateEnd::None;
    case PitchResult::InPlay: return PlateEnd::InPlay;
    case PitchResult::HitByPitch: return PlateEnd::HitByPitch;
  }
  return PlateEnd::None;
}

int force_advance(Bases& b, int batter) {
  int runs = 0;
  if (b[0] >= 0) {
    if (b[1] >= 0) {
      if (b[2] >= 0) ++runs;
      b[2] = b[1];
    }
    b[1] = b[0];
  }
  b[0] = batter;
  return runs;
}

void RunnerCharges::reached(int runner, int pitcher) { pitcher_.at(static_cast<std::size_t>(runner)) = pitcher; }

void RunnerCharges::fielders_choice(int batter, int out_runner) {
  pitcher_.at(static_cast<std::size_t>(batter)) = pitcher_.at(static_cast<std::size_t>(out_runner));
}

int RunnerCharges::charged(int runner) const { return pitcher_.at(static_cast<std::size_t>(runner)); }

std::string ordinal(int n) {
  const int teen = n % 100, last = n % 10;
  const char* suffix = (teen >= 11 && teen <= 13) ? "th" : last == 1 ? "st" : last == 2 ? "nd" : last == 3 ? "rd" : "th";
  return std::to_string(n) + suffix;
}

bool game_over(const GameSituation& s) {
  const bool last_or_later = s.inning >= s.scheduled;
  if (!last_or_later) return false;
  // The home team ahead in the bottom half: over at once (a walk-off) or when the top ends.
  if (s.bottom) return s.home_runs > s.away_runs || (s.outs >= 3 && s.home_runs != s.away_runs);
  return s.outs >= 3 && s.home_runs > s.away_runs;
}

BattingLine& BattingLine::operator+=(const BattingLine& o) {
  pa += o.pa, ab += o.ab, r += o.r, h += o.h, doubles += o.doubles, triples += o.triples, hr += o.hr;
  rbi += o.rbi, bb += o.bb, so += o.so, hbp += o.hbp, sf += o.sf;
  return *this;
}

PitchingLine& PitchingLine::operator+=(const PitchingLine& o) {
  outs += o.outs, h += o.h, r += o.r, bb += o.bb, so += o.so, hr += o.hr, hbp += o.hbp;
  pitches += o.pitches, strikes += o.strikes, batters += o.batters, er += o.er;
  return *this;
}

const char* to_string(Decision d) {
  switch (d) {
    case Decision::Win: return "W";
    case Decision::Loss: return "L";
    case Decision::Save: return "S";
    case Decision::None: break;
  }
  return "";
}

void assign_decisions(const std::vector<ScoreAfter>& log, int scheduled, TeamBox& away, TeamBox& home) {
  TeamBox* const team[2] = {&away, &home};
  for (TeamBox* t : team)
    for (PitchingLine& p : t->pitchers) p.decision = Decision::None;
  if (log.empty() || log.back().away == log.back().home) return;
  const int w = log.back().home > log.back().away ? 1 : 0, l = 1 - w;
  const auto runs = [](const ScoreAfter& s, int t) { return t == 0 ? s.away : s.home; };
  // The plate appearance after which the winners went ahead for good.
  std::size_t go_ahead = 0;
  bool ahead = false;
  for (std::size_t i = 0; i < log.size(); ++i) {
    const bool now = runs(log[i], w) > runs(log[i], l);
    if (now && !ahead) go_ahead = i;
    ahead = now;
  }
  TeamBox& wt = *team[w];
  TeamBox& lt = *team[l];
  if (log[go_ahead].fielding != l || wt.pitchers.empty() || lt.pitchers.empty()) return;
  // The go-ahead run is charged to the pitcher who let that runner on (Rule 9.16(g)), who
  // may have left before it scored. Runs score lead runner first: it is the run after the
  // ones that drew the winners level.
  const ScoreAfter& at = log[go_ahead];
  const int before = go_ahead == 0 ? 0 : runs(log[go_ahead - 1], w);
  const std::size_t nth = static_cast<std::size_t>(std::max(0, runs(at, l) - before));
  const int loser = nth < at.charged.size() ? at.charged[nth] : at.pitcher;
  lt.pitchers[static_cast<std::size_t>(loser)].decision = Decision::Loss;
  std::size_t record = 0;  // the winners' pitcher of record: the last of theirs to pitch before it
  for (std::size_t i = 0; i < go_ahead; ++i)
    if (log[i].fielding == w) record = static_cast<std::size_t>(log[i].pitcher);
  const int starter_needs = scheduled >= 6 ? 15 : 12;  // outs: five innings, four in a short game
  if (record == 0 && wt.pitchers[0].outs < starter_needs && wt.pitchers.size() > 1) {
    record = 1;
    for (std::size_t i = 2; i < wt.pitchers.size(); ++i)
      if (wt.pitchers[i].outs > wt.pitchers[record].outs) record = i;
  }
  wt.pitchers[record].decision = Decision::Win;
  const std::size_t last = wt.pitchers.size() - 1;
  PitchingLine& f = wt.pitchers[last];
  const int lead = f.lead_at_entry;
  const bool tying_run_near = lead >= 1 && lead <= f.runners_at_entry + 2;  // on base, at bat or on deck
  const bool save_spot = (lead >= 1 && lead <= 3 && f.outs >= 3) || tying_run_near || f.outs >= 9;
  if (last != record && f.outs >= 1 && save_spot) f.decision = Decision::Save;
}

std::string decisions_mismatch(const TeamBox& away, const TeamBox& home) {
  int wins[2] = {0, 0}, losses[2] = {0, 0}, saves[2] = {0, 0};
  const TeamBox* const team[2] = {&away, &home};
  for (int t = 0; t < 2; ++t)
    for (const PitchingLine& p : team[t]->pitchers) {
      if (p.er < 0 || p.er > p.r) return team[t]->name + ": a pitcher's earned runs are not among his runs";
      wins[t] += p.decision == Decision::Win;
      losses[t] += p.decision == Decision::Loss;
      saves[t] += p.decision == Decision::Save;
      if (p.decision == Decision::Save && p.outs < 1) return team[t]->name + ": a save without an out";
    }
  if (away.runs == home.runs) {
    if (wins[0] + wins[1] + losses[0] + losses[1] + saves[0] + saves[1] != 0) return "a tied game with a decision";
    return "";
  }
  const int w = home.runs > away.runs ? 1 : 0, l = 1 - w;
  if (wins[w] != 1 || wins[l] != 0) return team[w]->name + ": the winners do not have the one winning pitcher";
  if (losses[l] != 1 || losses[w] != 0) return team[l]->name + ": the losers do not have the one losing pitcher";
  if (saves[w] > 1 || saves[l] != 0) return "a save that is not the winners' one";
  return "";
}

std::string box_score_mismatch(const TeamBox& bat, const TeamBox& field) {
  const std::string who = bat.name + ": ";
  if (std::accumulate(bat.runs_by_inning.begin(), bat.runs_by_inning.end(), 0) != bat.runs)
    return who + "runs by inning do not add up to the runs";
  BattingLine sum;
  for (const BattingLine& l : bat.batting) {
    sum += l;
    if (l.pa != l.ab + l.bb + l.hbp + l.sf) return who + "a batter's plate appearances are not AB + BB + HBP + SF";
    if (l.h < l.doubles + l.triples + l.hr) return who + "a batter has more extra-base hits than hits";
  }
  if (sum.r != bat.runs) return who + "the batters' runs do not add up to the team's";
  if (sum.h != bat.hits) return who + "the batters' hits do not add up to the team's";
  const PitchingLine& p = field.pitching;
  if (!field.pitchers.empty()) {
    PitchingLine staff;
    for (const PitchingLine& one : field.pitchers) {
      staff += one;
      if (one.inherited_scored < 0 || one.inherited_scored > one.inherited || one.inherited > one.runners_at_entry)
        return field.name + ": a pitcher's inherited runners who scored are not among those he inherited";
    }
    if (staff.outs != p.outs || staff.r != p.r || staff.er != p.er || staff.h != p.h || staff.bb != p.bb ||
        staff.so != p.so || staff.pitches != p.pitches || staff.batters != p.batters)
      return field.name + ": the pitchers' lines do not add up to the staff's";
  }
  if (p.r != bat.runs || p.h != bat.hits || p.bb != sum.bb || p.so != sum.so || p.hr != sum.hr || p.hbp != sum.hbp ||
      p.batters != sum.pa)
    return who + "the opposing pitcher's line does not match the batting";
  // The box score's proof (Rule 9.03(c)): every batter, and every runner placed on second in
  // extra innings, scored, was left on base or was put out.
  if (sum.pa + bat.placed_runners != bat.runs + bat.left_on_base + p.outs)
    return who + "plate appearances and placed runners are not runs + left on base + the opponents' putouts";
  return "";
}

}  // namespace sweetspot
