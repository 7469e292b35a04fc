#include "game/rules/golf_scoring.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "physics/error.hpp"

namespace sweetspot {

std::string score_name(int strokes, int par) {
  if (strokes == 1) return "hole in one";
  switch (strokes - par) {
    case -3: return "albatross";
    case -2: return "eagle";
    case -1: return "birdie";
    case 0: return "";
    case 1: return "bogey";
    case 2: return "double bogey";
    case 3: return "triple bogey";
    default: {
      char text[16];
      std::snprintf(text, sizeof text, "%+d", strokes - par);
      return text;
    }
  }
}

const char* to_string(GolfFormat f) {
  switch (f) {
    case GolfFormat::Stroke: return "stroke";
    case GolfFormat::Match: return "match";
    case GolfFormat::Stableford: return "stableford";
    case GolfFormat::Skins: return "skins";
  }
  return "?";
}

GolfFormat golf_format(std::string_view name) {
  for (GolfFormat f : {GolfFormat::Stroke, GolfFormat::Match, GolfFormat::Stableford, GolfFormat::Skins})
    if (name == to_string(f)) return f;
  throw InputError("format '" + std::string(name) + "' is not a golf format (allowed: stroke, match, stableford, skins)");
}

int strokes_for_round(int handicap, int holes) {
  if (handicap < 0 || handicap > kMaxHandicap)
    throw InputError("handicap " + std::to_string(handicap) + " is out of range (allowed [0, 54])");
  // handicap·holes/18 rounded half up, in integers.
  return (2 * handicap * holes + 18) / 36;
}

std::vector<int> strokes_received(int handicap, const std::vector<int>& stroke_index) {
  const int n = static_cast<int>(stroke_index.size());
  std::vector<int> out(stroke_index.size(), 0);
  if (n == 0) return out;
  const int total = strokes_for_round(handicap, n);
  for (std::size_t h = 0; h < stroke_index.size(); ++h) {
    const int si = stroke_index[h];
    if (si < 1 || si > n)
      throw InputError("stroke index " + std::to_string(si) + " of hole " + std::to_string(h + 1) +
                       " is out of range (allowed [1, " + std::to_string(n) + "])");
    // Every hole gets total / n; the remainder goes to the holes of index 1..total % n.
    out[h] = total / n + (si <= total % n ? 1 : 0);
  }
  return out;
}

int stableford_points(int par, int net_strokes) { return std::max(0, 2 + par - net_strokes); }

namespace {

std::string up_text(const std::string& leader, int up) { return leader + " " + std::to_string(up) + " up"; }
// The human player's card name is "You": "You win 3&2", not "You wins".
std::string wins_text(const std::string& leader) { return leader + (leader == "You" ? " win " : " wins "); }

}  // namespace

MatchResult score_match(const std::vector<int>& net0, const std::vector<int>& net1, const std::vector<int>& conceded_by,
                        int round_holes, const std::string& name0, const std::string& name1) {
  MatchResult m;
  const int n = static_cast<int>(std::min(net0.size(), net1.size()));
  int lead = 0;
  for (int h = 0; h < n; ++h) {
    MatchHole hole;
    const int c = h < static_cast<int>(conceded_by.size()) ? conceded_by[static_cast<std::size_t>(h)] : -1;
    if (c == 0 || c == 1) hole.winner = 1 - c;
    else if (net0[static_cast<std::size_t>(h)] < net1[static_cast<std::size_t>(h)]) hole.winner = 0;
    else if (net1[static_cast<std::size_t>(h)] < net0[static_cast<std::size_t>(h)]) hole.winner = 1;
    if (m.decided_after < 0) lead += hole.winner == 0 ? 1 : hole.winner == 1 ? -1 : 0;
    hole.lead = lead;
    const int remaining = std::max(round_holes, n) - h - 1;
    const std::string& leader = lead > 0 ? name0 : name1;
    const int up = std::abs(lead);
    if (m.decided_after >= 0) {
      hole.status = m.holes.back().status;
    } else if (up > remaining) {
      m.decided_after = h;
      hole.status = remaining == 0 ? wins_text(leader) + std::to_string(up) + " up"
                                   : wins_text(leader) + std::to_string(up) + "&" + std::to_string(remaining);
    } else if (up == 0) {
      hole.status = "all square";
    } else if (up == remaining) {
      hole.status = up_text(leader, up) + " (dormie)";
    } else {
      hole.status = up_text(leader, up);
    }
    m.holes.push_back(hole);
  }
  m.lead = lead;
  if (m.decided_after >= 0) m.result = m.holes[static_cast<std::size_t>(m.decided_after)].status;
  else if (n >= round_holes && lead == 0) m.result = "halved";
  else m.result = (lead == 0 ? std::string("all square") : up_text(lead > 0 ? name0 : name1, std::abs(lead))) + " after " +
                  std::to_string(n);
  return m;
}

SkinsResult score_skins(const std::vector<std::vector<int>>& net) {
  SkinsResult s;
  s.skins.assign(net.size(), 0);
  const std::size_t holes = net.empty() ? 0 : net[0].size();
  int carried = 0;
  for (std::size_t h = 0; h < holes; ++h) {
    int best = 0, winner = -1;
    bool tie = false;
    for (std::size_t p = 0; p < net.size(); ++p) {
      const int v = net[p][h];
      if (winner < 0 || v < best) {
        best = v;
        winner = static_cast<int>(p);
        tie = false;
      } else if (v == best) {
        tie = true;
      }
    }
    ++carried;
    if (tie || winner < 0) {
      s.winner.push_back(-1);
      s.value.push_back(0);
    } else {
      s.winner.push_back(winner);
      s.value.push_back(carried);
      s.skins[static_cast<std::size_t>(winner)] += carried;
      carried = 0;
    }
  }
  s.unwon = carried;
  return s;
}

}  // namespace sweetspot
