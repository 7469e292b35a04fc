#include "game/report/box_score.hpp"

#include <cstdarg>
#include <cstdio>

#include "game/report/flight_json.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

nlohmann::json batting_json(const BattingLine& l) {
  return {{"pa", l.pa}, {"ab", l.ab}, {"r", l.r},     {"h", l.h},     {"2b", l.doubles}, {"3b", l.triples}, {"hr", l.hr},
          {"rbi", l.rbi}, {"bb", l.bb}, {"so", l.so}, {"hbp", l.hbp}, {"sf", l.sf}};
}

nlohmann::json team_json(const TeamBox& t) {
  nlohmann::json batting = nlohmann::json::array();
  for (std::size_t i = 0; i < t.batting.size(); ++i) {
    nlohmann::json b = batting_json(t.batting[i]);
    b["order"] = i + 1;
    b["bats"] = bats_left(static_cast<int>(i)) ? "L" : "R";
    b["position"] = lineup_position(static_cast<int>(i));
    batting.push_back(b);
  }
  const auto pitching = [](const PitchingLine& p) {
    return nlohmann::json{{"outs", p.outs},
                          {"innings_pitched", std::to_string(p.outs / 3) + "." + std::to_string(p.outs % 3)},
                          {"batters_faced", p.batters}, {"h", p.h}, {"r", p.r}, {"er", p.er}, {"bb", p.bb}, {"so", p.so},
                          {"hr", p.hr}, {"hbp", p.hbp}, {"pitches", p.pitches}, {"strikes", p.strikes}};
  };
  nlohmann::json pitchers = nlohmann::json::array();
  for (const PitchingLine& p : t.pitchers) {
    nlohmann::json one = pitching(p);
    one["decision"] = to_string(p.decision);  // "W", "L", "S" or ""
    one["throws"] = p.left_handed ? "L" : "R";
    one["inherited_runners"] = p.inherited;
    one["inherited_scored"] = p.inherited_scored;
    pitchers.push_back(one);
  }
  return {{"team", t.name},
          {"runs_by_inning", t.runs_by_inning},
          {"runs", t.runs},
          {"hits", t.hits},
          {"errors", t.errors},
          {"left_on_base", t.left_on_base},
          {"batting", batting},
          {"pitching", pitching(t.pitching)},
          {"pitchers", pitchers}};
}

nlohmann::json pitch_json(const PitchRecord& p) {
  using nlohmann::json;
  const Vec3& at = p.flight.plate;
  json j = {{"count", std::to_string(p.count.balls) + "-" + std::to_string(p.count.strikes)},
            {"type", p.planned.call.type.type},
            {"speed_mps", p.planned.call.type.speed},
            {"spin_rpm", radps_to_rpm(p.planned.call.type.spin)},
            {"plate_position_m", {at.x(), at.y(), at.z()}},
            {"call", to_string(p.call)},
            {"swung", p.swung}};
  if (!p.swung) return j;
  j["timing_ms"] = p.swing.timing_ms;
  j["contact"] = p.result.contact;
  j["bat_tracking"] = bat_tracking_json(p.result.tracking);
  if (p.result.contact) {
    j["launch"] = launch_json(p.result.shot.launch, -1.0);
    j["flight"] = flight_json(p.result.shot.trajectory.summary);
    j["flight"]["end"] = to_string(p.result.shot.end);
    j["outcome"] = to_string(p.result.outcome);
    j["batted_ball_type"] = to_string(p.result.play.type);
    j["barrel"] = p.result.barrel;
    j["hard_hit"] = p.result.hard_hit;
    if (!p.result.fielder.empty()) j["fielder"] = p.result.fielder;
    if (p.result.play.catch_probability > 0.0) j["catch_probability"] = p.result.play.catch_probability;
  }
  return j;
}

void line(std::string& out, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void line(std::string& out, const char* fmt, ...) {
  char buf[256];
  va_list a;
  va_start(a, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, a);
  va_end(a);
  out += buf;
}

// A pitcher by his place in the staff's order: the starter "SP", the relievers "RP1", "RP2"...
std::string pitcher_name(std::size_t i) { return i == 0 ? std::string("SP") : "RP" + std::to_string(i); }

}  // namespace

nlohmann::json bat_tracking_json(const BatTracking& t) {
  return {{"bat_speed_mps", t.bat_speed_mps},       {"squared_up", t.squared_up},
          {"is_squared_up", t.is_squared_up},       {"blast", t.blast},
          {"swing_length_m", t.swing_length_m},     {"attack_angle_deg", t.attack_angle_deg},
          {"attack_direction_deg", t.attack_direction_deg}, {"swing_path_tilt_deg", t.swing_path_tilt_deg}};
}

nlohmann::json game_json(const GameRecord& g) {
  using nlohmann::json;
  json pas = json::array();
  for (const PlateAppearance& pa : g.plate_appearances) {
    json pitches = json::array();
    for (const PitchRecord& p : pa.pitches) pitches.push_back(pitch_json(p));
    json bases = json::array();
    for (int b : pa.bases_before) bases.push_back(b >= 0 ? json(b + 1) : json(nullptr));
    pas.push_back({{"inning", pa.inning},
                   {"half", pa.bottom ? "bottom" : "top"},
                   {"batter", pa.batter + 1},
                   {"outs_before", pa.outs_before},
                   {"runners_before", bases},
                   {"pitches", pitches},
                   {"result", pa.result},
                   {"description", pa.description},
                   {"runs", pa.runs},
                   {"earned_runs", pa.earned_runs},
                   {"rbi", pa.rbi},
                   {"outs_made", pa.outs_made},
                   {"pitcher", pa.pitcher},
                   {"pitching_change", pa.pitching_change}});
  }
  return {{"mode", "game"},
          {"seed", g.options.seed},
          {"innings", g.options.innings},
          {"innings_played", g.innings_played},
          {"walk_off", g.walk_off},
          {"stopped_tied", g.stopped_tied},
          {"plate_appearances", pas},
          {"box_score", {{"away", team_json(g.away)}, {"home", team_json(g.home)}}}};
}

std::string pitching_change_text(const PlateAppearance& pa) {
  const auto in_order = static_cast<std::size_t>(pa.pitcher);
  std::string out = std::string(pa.bottom ? "away" : "home") + " pitching change: " + pitcher_name(in_order) + " replaces " +
                    pitcher_name(in_order - 1);
  static const char* kBase[] = {"1st", "2nd", "3rd"};
  std::vector<std::string> on;
  for (int b = 0; b < 3; ++b)
    if (pa.bases_before[static_cast<std::size_t>(b)] >= 0) on.emplace_back(kBase[b]);
  if (on.size() == 3) return out + ", bases loaded";
  if (on.size() == 2) return out + ", runners on " + on[0] + " and " + on[1];
  if (on.size() == 1) return out + ", a runner on " + on[0];
  return out;
}

std::string box_score_text(const GameRecord& g) {
  std::string out;
  const std::size_t n = std::max(g.away.runs_by_inning.size(), g.home.runs_by_inning.size());
  line(out, "%-6s", "");
  for (std::size_t i = 0; i < n; ++i) line(out, "%3zu", i + 1);
  line(out, "    R  H  E\n");
  for (const TeamBox* t : {&g.away, &g.home}) {
    line(out, "%-6s", t->name.c_str());
    for (std::size_t i = 0; i < n; ++i) {
      if (i < t->runs_by_inning.size()) line(out, "%3d", t->runs_by_inning[i]);
      else line(out, "%3s", t == &g.home && g.home.runs > g.away.runs ? "x" : "-");
    }
    line(out, "   %2d %2d %2d\n", t->runs, t->hits, t->errors);
  }
  for (const TeamBox* t : {&g.away, &g.home}) {
    // B: the side he bats from; "(L)" is kept for the losing pitcher.
    line(out, "\n%-8s B  AB  R  H 2B 3B HR RBI BB SO HBP SF\n", t->name.c_str());
    BattingLine sum;
    for (std::size_t i = 0; i < t->batting.size(); ++i) {
      const BattingLine& l = t->batting[i];
      sum += l;
      line(out, "%zu. %-5s %c %3d %2d %2d %2d %2d %2d %3d %2d %2d %3d %2d\n", i + 1, lineup_position(static_cast<int>(i)),
           bats_left(static_cast<int>(i)) ? 'L' : 'R',
           l.ab, l.r, l.h, l.doubles, l.triples, l.hr, l.rbi, l.bb, l.so, l.hbp, l.sf);
    }
    line(out, "%-10s %3d %2d %2d %2d %2d %2d %3d %2d %2d %3d %2d   LOB %d\n", "Totals", sum.ab, sum.r, sum.h, sum.doubles,
         sum.triples, sum.hr, sum.rbi, sum.bb, sum.so, sum.hbp, sum.sf, t->left_on_base);
  }
  // A left-hander is named so ("LHP"); "(L)" is the losing pitcher's decision.
  line(out, "\nPitching             IP   H  R ER BB SO HR HBP  Pitches-strikes\n");
  for (const TeamBox* t : {&g.away, &g.home}) {
    for (std::size_t i = 0; i < t->pitchers.size(); ++i) {
      const PitchingLine& p = t->pitchers[i];
      std::string who = t->name + " " + pitcher_name(i) + (p.left_handed ? " LHP" : "");
      if (p.decision != Decision::None) who += std::string(" (") + to_string(p.decision) + ")";
      line(out, "%-18s %2d.%d %3d %2d %2d %2d %2d %2d %3d  %d-%d\n", who.c_str(), p.outs / 3, p.outs % 3, p.h, p.r, p.er, p.bb,
           p.so, p.hr, p.hbp, p.pitches, p.strikes);
    }
  }
  // Inherited runners-scored, as a newspaper's box prints it under the pitching lines.
  std::string inherited;
  for (const TeamBox* t : {&g.away, &g.home})
    for (std::size_t i = 1; i < t->pitchers.size(); ++i)
      if (t->pitchers[i].inherited > 0)
        inherited += (inherited.empty() ? "" : ", ") + t->name + " " + pitcher_name(i) + " " +
                     std::to_string(t->pitchers[i].inherited) + "-" + std::to_string(t->pitchers[i].inherited_scored);
  if (!inherited.empty()) line(out, "Inherited runners-scored: %s.\n", inherited.c_str());
  if (g.walk_off) line(out, "\nWalk-off in the %s.\n", ordinal(g.innings_played).c_str());
  if (g.stopped_tied) line(out, "\nStopped tied after %d innings.\n", g.innings_played);
  return out;
}

std::string rates_text(const BattingRates& r, const std::string& title) {
  std::string out;
  line(out, "%s: %d PA, %d pitches\n", title.c_str(), r.pa, r.pitches);
  line(out, "  K%% %.1f  BB%% %.1f  HBP%% %.1f  HR/PA %.1f%%  AVG %.3f  OBP %.3f  SLG %.3f  BABIP %.3f\n", 100 * r.k_rate,
       100 * r.bb_rate, 100 * r.hbp_rate, 100 * r.hr_rate, r.avg, r.obp, r.slg, r.babip);
  line(out, "  swing%% %.1f  zone%% %.1f  chase%% %.1f  whiff/swing %.1f%%  foul/pitch %.1f%%\n", 100 * r.swing_rate,
       100 * r.zone_rate, 100 * r.chase_rate, 100 * r.whiff_per_swing, 100 * r.foul_per_pitch);
  line(out, "  bat speed %.1f mph  swing length %.1f ft  squared-up/swing %.1f%%  blast/swing %.1f%%\n", r.mean_bat_speed_mph,
       r.mean_swing_length_ft, 100 * r.squared_up_per_swing, 100 * r.blast_per_swing);
  return out;
}

}  // namespace sweetspot
