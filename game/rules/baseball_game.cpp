#include "game/rules/baseball_game.hpp"

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
  pitches += o.pitches, strikes += o.strikes, batters += o.batters;
  return *this;
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
    for (const PitchingLine& one : field.pitchers) staff += one;
    if (staff.outs != p.outs || staff.r != p.r || staff.h != p.h || staff.bb != p.bb || staff.so != p.so ||
        staff.pitches != p.pitches || staff.batters != p.batters)
      return field.name + ": the pitchers' lines do not add up to the staff's";
  }
  if (p.r != bat.runs || p.h != bat.hits || p.bb != sum.bb || p.so != sum.so || p.hr != sum.hr || p.hbp != sum.hbp ||
      p.batters != sum.pa)
    return who + "the opposing pitcher's line does not match the batting";
  return "";
}

}  // namespace sweetspot
