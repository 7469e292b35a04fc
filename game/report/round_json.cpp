#include "game/report/round_json.hpp"

#include <algorithm>
#include <cstdio>

#include "game/modes/golf/standings.hpp"
#include "game/rules/golf_scoring.hpp"

namespace sweetspot {

namespace {

// The holes a card has to show: every hole finished or begun (the next hole's card, opened
// when the last was finished but not yet played, is left out).
std::vector<const HoleCard*> listed_holes(const GolfRound& round) {
  std::vector<const HoleCard*> out;
  for (std::size_t k = 0; k < round.card().size(); ++k)
    if (k < round.hole_index() || !round.card()[k].shots.empty()) out.push_back(&round.card()[k]);
  return out;
}

nlohmann::json holes_json(const GolfRound& round) {
  using nlohmann::json;
  json holes = json::array();
  for (const HoleCard* hp : listed_holes(round)) {
    const HoleCard& h = *hp;
    json shots = json::array();
    for (const StrokeRecord& s : h.shots) {
      json shot = {{"club", s.club},
                   {"lie", s.lie},
                   {"start_m", {s.start.x(), s.start.y(), s.start.z()}},
                   {"rest_m", {s.rest.x(), s.rest.y(), s.rest.z()}},
                   {"end", to_string(s.end)},
                   {"to_pin_m", s.to_pin_m}};
      // Beyond DESIGN §9's keys: how the stroke was swung and how far it flew, for a player
      // (or a coach) reading a round back. A conceded stroke was not swung.
      if (!s.conceded) {
        shot["power"] = s.power;
        shot["carry_m"] = s.carry_m;
      }
      if (s.conceded) shot["conceded"] = true;
      if (s.relief) shot["relief"] = "cart_path";
      if (s.wrong_green) shot["relief"] = "wrong_green";
      if (s.unplayable) shot["unplayable"] = true;
      shots.push_back(shot);
    }
    json hole = {{"number", h.number}, {"par", h.par},       {"strokes", h.strokes},
                 {"putts", h.putts},   {"penalties", h.penalties}, {"holed", h.holed},
                 {"fairway", h.tee_shot == TeeShot::None ? json(nullptr) : json(to_string(h.tee_shot))},
                 {"green_in_regulation", h.green_in_regulation},
                 {"shots", shots}};
    if (h.picked_up) hole["picked_up"] = true;
    if (h.conceded) hole["conceded"] = true;
    holes.push_back(hole);
  }
  return holes;
}

// Fairways hit of the par 4s and 5s teed off, and greens in regulation, over the holes listed.
struct BallStriking {
  int fairways_hit = 0, fairways = 0, greens = 0;
};
void count_hole(BallStriking& b, const HoleCard& h) {
  b.fairways += h.tee_shot != TeeShot::None;
  b.fairways_hit += h.tee_shot == TeeShot::Fairway;
  b.greens += h.green_in_regulation;
}
BallStriking ball_striking(const GolfRound& round) {
  BallStriking b;
  for (const HoleCard* h : listed_holes(round)) count_hole(b, *h);
  return b;
}

}  // namespace

nlohmann::json round_json(const GolfRound& round, const std::string& player, std::uint64_t seed) {
  // The totals are those of the holes listed: a round stopped after two holes is par for two.
  int total = 0, par = 0;
  for (const HoleCard* h : listed_holes(round)) {
    total += h->strokes;
    par += h->par;
  }
  const BallStriking b = ball_striking(round);
  return {{"course", round.course().name}, {"player", player}, {"seed", seed}, {"holes", holes_json(round)},
          {"total_strokes", total}, {"total_par", par}, {"fairways_hit", b.fairways_hit},
          {"fairways", b.fairways}, {"greens_in_regulation", b.greens}};
}

std::string round_table(const GolfRound& round, const std::string& player) {
  std::string out = round.course().name + " — " + player + "\n";
  char line[200];
  std::snprintf(line, sizeof line, "%-6s %4s %8s %6s %8s %6s %10s %s\n", "hole", "par", "strokes", "putts", "fairway", "green",
                "penalties", "note");
  out += line;
  int par = 0, strokes = 0, putts = 0, penalties = 0;
  // A card of more than nine holes adds each nine, as a printed card does: "out" after the
  // 9th, "in" for the rest, then the total.
  const bool nines = round.card().size() > 9;
  struct Nine {
    int par = 0, strokes = 0, putts = 0, penalties = 0;
  } nine;
  const auto nine_line = [&](const char* name) {
    std::snprintf(line, sizeof line, "%-6s %4d %8d %6d %8s %6s %10d\n", name, nine.par, nine.strokes, nine.putts, "", "",
                  nine.penalties);
    out += line;
    nine = Nine{};
  };
  // The holes played (a round stopped after a hole has a card for the next, begun and empty).
  for (const HoleCard* hp : listed_holes(round)) {
    const HoleCard& h = *hp;
    par += h.par;
    strokes += h.strokes;
    putts += h.putts;
    penalties += h.penalties;
    nine.par += h.par;
    nine.strokes += h.strokes;
    nine.putts += h.putts;
    nine.penalties += h.penalties;
    // The fairway column: "hit", or the side the tee shot missed on; "-" on a par 3 (none).
    const char* fairway = h.tee_shot == TeeShot::None ? "-" : to_string(h.tee_shot);
    std::snprintf(line, sizeof line, "%-6d %4d %8d %6d %8s %6s %10d %s\n", h.number, h.par, h.strokes, h.putts, fairway,
                  h.green_in_regulation ? "hit" : "miss", h.penalties,
                  h.picked_up ? "picked up" : h.conceded ? "conceded" : score_name(h.strokes, h.par).c_str());
    out += line;
    if (nines && h.number == 9) nine_line("out");
  }
  if (nines) nine_line("in");
  const BallStriking b = ball_striking(round);
  const std::string fairways = std::to_string(b.fairways_hit) + "/" + std::to_string(b.fairways);
  const std::string greens = std::to_string(b.greens) + "/" + std::to_string(listed_holes(round).size());
  std::snprintf(line, sizeof line, "%-6s %4d %8d %6d %8s %6s %10d\n", "total", par, strokes, putts, fairways.c_str(), greens.c_str(),
                penalties);
  out += line;
  out += "to par: " + to_par_text(strokes - par) + "\n";
  return out;
}

std::string to_par_text(int diff) {
  if (diff == 0) return "E";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%+d", diff);
  return buf;
}

namespace {

nlohmann::json wind_json(const HoleWind& w) {
  return {{"wind_mps", w.speed}, {"wind_toward_deg", w.toward * 180.0 / 3.14159265358979323846}};
}

std::string leaders_text(const GolfGroup& g, const Standings& s) {
  std::string names;
  for (int p : s.leaders) names += (names.empty() ? "" : ", ") + g.players()[static_cast<std::size_t>(p)].name;
  if (s.leaders.empty()) return "no skins won";
  return (s.leaders.size() > 1 ? "tied: " : g.finished() ? "winner: " : "leader: ") + names;
}

nlohmann::json result_json(const GolfGroup& g, const Standings& s) {
  using nlohmann::json;
  const auto name = [&](int p) { return p < 0 ? json(nullptr) : json(g.players()[static_cast<std::size_t>(p)].name); };
  json r = json::object();
  switch (s.format) {
    case GolfFormat::Stroke: {
      json rank = json::array();
      for (int p : s.ranking) {
        const PlayerStanding& ps = s.players[static_cast<std::size_t>(p)];
        rank.push_back({{"player", name(p)}, {"total_strokes", ps.total_strokes}, {"total_net", ps.total_net},
                        {"to_par", ps.total_strokes - ps.total_par}});
      }
      r["ranking"] = rank;
      break;
    }
    case GolfFormat::Stableford: {
      json pts = json::array();
      for (int p : s.ranking) {
        const PlayerStanding& ps = s.players[static_cast<std::size_t>(p)];
        pts.push_back({{"player", name(p)}, {"points", ps.points}, {"total_points", ps.total_points}});
      }
      r["points"] = pts;
      break;
    }
    case GolfFormat::Skins: {
      json holes = json::array();
      for (std::size_t h = 0; h < s.skins->winner.size(); ++h)
        holes.push_back({{"number", g.course().holes[h].number}, {"winner", name(s.skins->winner[h])},
                         {"skins", s.skins->value[h]}, {"carried", s.skins->winner[h] < 0}});
      json won = json::array();
      for (std::size_t p = 0; p < s.skins->skins.size(); ++p)
        won.push_back({{"player", name(static_cast<int>(p))}, {"skins", s.skins->skins[p]}});
      r["holes"] = holes;
      r["skins"] = won;
      r["carried_unwon"] = s.skins->unwon;
      break;
    }
    case GolfFormat::Match: {
      json holes = json::array();
      for (std::size_t h = 0; h < s.match->holes.size(); ++h)
        holes.push_back({{"number", g.course().holes[h].number}, {"winner", name(s.match->holes[h].winner)},
                         {"holes_up", s.match->holes[h].lead}, {"status", s.match->holes[h].status}});
      r["holes"] = holes;
      r["holes_up"] = s.match->lead;  // + the first player up
      r["status"] = s.match->result;
      r["decided_after_hole"] = s.match->decided_after < 0 ? json(nullptr) : json(s.match->decided_after + 1);
      break;
    }
  }
  // The winner, or none on a tie (then `tied` names those level at the top).
  r["winner"] = s.leaders.size() == 1 ? name(s.leaders.front()) : json(nullptr);
  if (s.leaders.size() > 1) {
    json tied = json::array();
    for (int p : s.leaders) tied.push_back(name(p));
    r["tied"] = tied;
  }
  return r;
}

}  // namespace

nlohmann::json group_json(const GolfGroup& g) {
  using nlohmann::json;
  const Standings s = standings(g);
  json players = json::array();
  for (std::size_t p = 0; p < g.players().size(); ++p) {
    const GolfPlayer& pl = g.players()[p];
    const GolfRound& r = g.round(static_cast<int>(p));
    json holes = holes_json(r);
    const std::vector<int> given = g.strokes_received(static_cast<int>(p));
    for (std::size_t h = 0; h < holes.size(); ++h) {
      holes[h]["strokes_received"] = given[h];
      holes[h]["net"] = r.card()[h].strokes - given[h];
      if (s.format == GolfFormat::Stableford && h < s.holes) holes[h]["points"] = s.players[p].points[h];
      holes[h].update(wind_json(g.winds()[h]));
    }
    // The totals are the sums of the holes listed that count (a round stopped mid-hole
    // included); a match's hole conceded, or left once conceded, has no score and is in
    // none of them, its fairway and green as little as its strokes, as on the card.
    const PlayerStanding& ps = s.players[p];
    for (std::size_t h = 0; h < holes.size(); ++h)
      holes[h]["counted"] = s.format != GolfFormat::Match || h >= ps.scored.size() || ps.scored[h];
    int strokes = 0, putts = 0, net = 0, par = 0;
    BallStriking b;
    for (std::size_t h = 0; h < holes.size(); ++h) {
      if (!holes[h]["counted"].get<bool>()) continue;
      strokes += holes[h]["strokes"].get<int>();
      putts += holes[h]["putts"].get<int>();
      net += holes[h]["net"].get<int>();
      par += holes[h]["par"].get<int>();
      count_hole(b, r.card()[h]);
    }
    players.push_back({{"player", pl.name},
                       {"skill", pl.human ? std::string("human") : pl.skill},
                       {"handicap", pl.handicap},
                       {"holes", holes},
                       {"total_strokes", strokes},
                       {"total_putts", putts},
                       {"total_net", net},
                       {"to_par", strokes - par},
                       {"fairways_hit", b.fairways_hit},
                       {"fairways", b.fairways},
                       {"greens_in_regulation", b.greens}});
  }
  json winds = json::array();
  for (std::size_t h = 0; h < g.winds().size(); ++h) {
    json w = wind_json(g.winds()[h]);
    w["number"] = g.course().holes[h].number;
    w["stroke_index"] = g.course().holes[h].stroke_index;
    winds.push_back(w);
  }
  json j = {{"course", g.course().name},
            {"tees", g.course().setup.tees},
            {"pin_set", g.course().setup.pin_set},
            {"seed", g.options().seed},
            {"format", to_string(s.format)},
            {"gimme_m", g.options().gimme_m},
            {"auto_putt", g.options().auto_putt},
            {"holes_info", winds},
            {"players", players},
            // The par of the holes listed, as each player's to_par: a round stopped early is not
            // measured against the whole course.
            {"total_par", players.empty() ? g.course().par() : players[0]["total_strokes"].get<int>() - players[0]["to_par"].get<int>()},
            {"result", result_json(g, s)}};
  if (g.players().size() == 1) {
    j["player"] = g.players()[0].name;
    j["holes"] = players[0]["holes"];
    j["total_strokes"] = players[0]["total_strokes"];
    for (const char* k : {"fairways_hit", "fairways", "greens_in_regulation"}) j[k] = players[0][k];
  }
  return j;
}

std::string group_table(const GolfGroup& g, const std::vector<int>& restarts) {
  const Standings s = standings(g);
  const std::size_t n = g.players().size();
  std::string out = g.course().name + " — " + to_string(s.format) + " play\n";
  char cell[64];
  auto pad = [](std::string t, std::size_t w) {
    if (t.size() < w) t.insert(0, w - t.size(), ' ');
    return t;
  };
  // Each player's column: gross strokes, a '*' per stroke received, the putts in brackets, the
  // penalty strokes (out of bounds, water, unplayable) as "Np", so a 6 with one putt reads.
  // The first column is as wide as the totals' labels ("fairways"), so each total's par sits
  // under "par".
  // Past nine holes each nine is added up, as a printed card does: "out", then "in".
  const auto nine_row = [&](const char* label, std::size_t from, std::size_t to) {
    int nine_par = 0;
    for (std::size_t h = from; h < to; ++h) nine_par += g.course().holes[h].par;
    std::snprintf(cell, sizeof cell, "%-8s %3d    ", label, nine_par);
    std::string line = cell;
    for (std::size_t p = 0; p < n; ++p) {
      const PlayerStanding::Sum nine = s.players[p].sum(from, to);
      std::string v = std::to_string(nine.strokes) + " (" + std::to_string(nine.putts) + ")";
      if (s.format == GolfFormat::Stableford) v += " " + std::to_string(nine.points) + "pt";  // each nine's points, as its holes'
      line += "  " + pad(v, 14);
    }
    return line + "\n";
  };
  std::string head = "hole     par  SI";
  for (const GolfPlayer& p : g.players()) head += "  " + pad(p.name.substr(0, 14), 14);
  if (s.format == GolfFormat::Match) head += "  match";
  if (s.format == GolfFormat::Skins) head += "  skin";
  out += head + "\n";
  for (std::size_t h = 0; h < s.holes; ++h) {
    const CourseHole& ch = g.course().holes[h];
    const bool restarted = h < restarts.size() && restarts[h] > 0;
    std::snprintf(cell, sizeof cell, "%4d%-5s%3d %3d", ch.number, restarted ? " R" : "", ch.par, ch.stroke_index);
    std::string line = cell;
    for (std::size_t p = 0; p < n; ++p) {
      const PlayerStanding& ps = s.players[p];
      const HoleCard& c = g.round(static_cast<int>(p)).card()[h];
      char v[48];
      if (!ps.scored[h])  // a match's hole conceded (C) or left once conceded: no score
        std::snprintf(v, sizeof v, "%s", c.conceded ? "C" : "-");
      else
        std::snprintf(v, sizeof v, "%s%d%.*s (%d)", c.picked_up ? "PU " : "", ps.gross[h], std::min(ps.received[h], 6), "******",
                      ps.putts[h]);
      std::string cellv = v;
      if (c.penalties > 0) cellv.append(" ").append(std::to_string(c.penalties)).append("p");
      if (s.format == GolfFormat::Stableford) cellv.append(" ").append(std::to_string(ps.points[h])).append("pt");
      line += "  " + pad(cellv, 14);
    }
    if (s.format == GolfFormat::Match) line += "  " + s.match->holes[h].status;
    if (s.format == GolfFormat::Skins) {
      const int w = s.skins->winner[h];
      if (w < 0) line += "  carried";
      else line.append("  ").append(g.players()[static_cast<std::size_t>(w)].name).append(" x").append(std::to_string(s.skins->value[h]));
    }
    out += line + "\n";
    if (s.holes > 9 && h == 8) out += nine_row("out", 0, 9);
  }
  if (s.holes > 9) out += nine_row("in", 9, s.holes);
  auto sum_row = [&](const char* label, int par, auto value) {
    std::snprintf(cell, sizeof cell, "%-8s %3s    ", label, par >= 0 ? std::to_string(par).c_str() : "");
    std::string line = cell;
    // No hole scored yet (a match's first hole conceded): no sums, not zeros.
    for (std::size_t p = 0; p < n; ++p)
      line += "  " + pad(s.players[p].holes_scored == 0 && s.holes > 0 ? std::string("-") : value(s.players[p]), 14);
    out += line + "\n";
  };
  int par = 0;
  for (std::size_t h = 0; h < s.holes; ++h) par += g.course().holes[h].par;
  sum_row("total", par, [&](const PlayerStanding& ps) { return ps.total_text(s.holes); });
  sum_row("putts", -1, [](const PlayerStanding& ps) { return std::to_string(ps.total_putts); });
  sum_row("fairways", -1, [](const PlayerStanding& ps) { return std::to_string(ps.fairways_hit) + "/" + std::to_string(ps.fairways); });
  sum_row("greens", -1, [&](const PlayerStanding& ps) { return std::to_string(ps.greens_in_regulation) + "/" + std::to_string(ps.greens); });
  sum_row("to par", -1, [](const PlayerStanding& ps) { return to_par_text(ps.total_strokes - ps.total_par); });
  sum_row("net", -1, [](const PlayerStanding& ps) { return std::to_string(ps.total_net); });
  if (s.format == GolfFormat::Stableford)
    sum_row("points", -1, [](const PlayerStanding& ps) { return std::to_string(ps.total_points); });
  if (s.format == GolfFormat::Skins)
    for (std::size_t p = 0; p < n; ++p)
      out += g.players()[p].name + ": " + std::to_string(s.skins->skins[p]) + (s.skins->skins[p] == 1 ? " skin\n" : " skins\n");
  if (s.format == GolfFormat::Skins && s.skins->unwon > 0) out += std::to_string(s.skins->unwon) + (s.skins->unwon == 1 ? " skin" : " skins") + " carried, unwon\n";
  if (s.format == GolfFormat::Match) out += "result: " + s.match->result + "\n";
  else if (s.holes > 0) out += leaders_text(g, s) + "\n";
  out += std::string("(SI the stroke index, the hole's rank by difficulty; * a stroke received; putts in brackets; 1p a penalty stroke; PU picked up") +
         (s.format == GolfFormat::Match ? "; C a hole conceded, - one left unfinished: no score, in no total" : "") +
         (std::any_of(restarts.begin(), restarts.end(), [](int r) { return r > 0; }) ? "; R the hole was restarted (its first try not counted)" : "") +
         ")\n";
  return out;
}

}  // namespace sweetspot
