#include "game/report/round_json.hpp"

#include <cstdio>

namespace sweetspot {

nlohmann::json round_json(const GolfRound& round, const std::string& player, std::uint64_t seed) {
  using nlohmann::json;
  json holes = json::array();
  for (const HoleCard& h : round.card()) {
    json shots = json::array();
    for (const StrokeRecord& s : h.shots) {
      shots.push_back({{"club", s.club},
                       {"lie", s.lie},
                       {"start_m", {s.start.x(), s.start.y(), s.start.z()}},
                       {"rest_m", {s.rest.x(), s.rest.y(), s.rest.z()}},
                       {"end", to_string(s.end)},
                       {"to_pin_m", s.to_pin_m}});
    }
    holes.push_back({{"number", h.number},
                     {"par", h.par},
                     {"strokes", h.strokes},
                     {"putts", h.putts},
                     {"penalties", h.penalties},
                     {"holed", h.holed},
                     {"shots", shots}});
  }
  return {{"course", round.course().name},   {"player", player}, {"seed", seed}, {"holes", holes},
          {"total_strokes", round.total_strokes()}, {"total_par", round.total_par()}};
}

std::string round_table(const GolfRound& round, const std::string& player) {
  std::string out = round.course().name + " — " + player + "\n";
  char line[160];
  std::snprintf(line, sizeof line, "%-6s %4s %8s %6s %10s %s\n", "hole", "par", "strokes", "putts", "penalties", "");
  out += line;
  int par = 0;
  for (const HoleCard& h : round.card()) {
    par += h.par;
    std::snprintf(line, sizeof line, "%-6d %4d %8d %6d %10d %s\n", h.number, h.par, h.strokes, h.putts, h.penalties,
                  h.holed ? "" : "(picked up)");
    out += line;
  }
  const int diff = round.total_strokes() - par;
  std::snprintf(line, sizeof line, "%-6s %4d %8d   %s%d\n", "total", par, round.total_strokes(), diff > 0 ? "+" : "",
                diff);
  out += line;
  return out;
}

}  // namespace sweetspot
