#include "game/modes/golf/standings.hpp"

#include <algorithm>

namespace sweetspot {

Standings standings(const GolfGroup& g) {
  Standings s;
  s.format = g.options().format;
  const int n = static_cast<int>(g.players().size());
  // The holes the whole group has finished: all of them, or a match's up to its decision.
  s.holes = g.hole_index();
  std::vector<std::vector<int>> nets;
  std::vector<int> conceded_by(s.holes, -1);
  for (int p = 0; p < n; ++p) {
    PlayerStanding ps;
    const GolfRound& r = g.round(p);
    const std::vector<int> given = g.strokes_received(p);
    for (std::size_t h = 0; h < s.holes; ++h) {
      const HoleCard& c = r.card()[h];
      ps.gross.push_back(c.strokes);
      ps.putts.push_back(c.putts);
      ps.received.push_back(given[h]);
      ps.net.push_back(c.strokes - given[h]);
      // A hole not holed (picked up) has no score: no points (Rule 21.1b(1)).
      ps.points.push_back(c.holed ? stableford_points(c.par, c.strokes - given[h]) : 0);
      const bool scored = c.holed || c.picked_up;
      ps.scored.push_back(scored);
      ps.tee_shot.push_back(c.tee_shot);
      ps.green_in_regulation.push_back(c.green_in_regulation);
      ps.total_points += ps.points.back();
      // A hole with no score (a match's, conceded or left unfinished) is in none of the
      // totals: its putts, fairway and green as little as its strokes, so that every row of
      // the card counts the same holes.
      if (scored) {
        ++ps.holes_scored;
        ps.total_strokes += c.strokes;
        ps.total_putts += c.putts;
        ps.total_net += c.strokes - given[h];
        ps.total_par += c.par;
        if (c.tee_shot != TeeShot::None) {
          ++ps.fairways;
          if (c.tee_shot == TeeShot::Fairway) ++ps.fairways_hit;
        }
        ++ps.greens;
        if (c.green_in_regulation) ++ps.greens_in_regulation;
      }
      if (c.conceded) conceded_by[h] = p;
    }
    nets.push_back(ps.net);
    s.players.push_back(std::move(ps));
  }
  for (int p = 0; p < n; ++p) s.ranking.push_back(p);
  auto rank_by = [&](auto better) { std::stable_sort(s.ranking.begin(), s.ranking.end(), better); };
  switch (s.format) {
    case GolfFormat::Stroke:
      rank_by([&](int a, int b) { return s.players[static_cast<std::size_t>(a)].total_net < s.players[static_cast<std::size_t>(b)].total_net; });
      break;
    case GolfFormat::Stableford:
      rank_by([&](int a, int b) {
        return s.players[static_cast<std::size_t>(a)].total_points > s.players[static_cast<std::size_t>(b)].total_points;
      });
      break;
    case GolfFormat::Skins:
      s.skins = score_skins(nets);
      rank_by([&](int a, int b) { return s.skins->skins[static_cast<std::size_t>(a)] > s.skins->skins[static_cast<std::size_t>(b)]; });
      break;
    case GolfFormat::Match:
      s.match = score_match(nets[0], nets[1], conceded_by, static_cast<int>(g.course().holes.size()), g.players()[0].name,
                            g.players()[1].name);
      if (s.match->lead < 0) s.ranking = {1, 0};
      break;
  }
  // The value each format ranks by, larger better.
  auto score = [&](int p) {
    const PlayerStanding& ps = s.players[static_cast<std::size_t>(p)];
    switch (s.format) {
      case GolfFormat::Stroke: return -ps.total_net;
      case GolfFormat::Stableford: return ps.total_points;
      case GolfFormat::Skins: return s.skins->skins[static_cast<std::size_t>(p)];
      case GolfFormat::Match: return p == 0 ? s.match->lead : -s.match->lead;
    }
    return 0;
  };
  // Skins where every hole carried has nobody at the top: no one leads with none won.
  const bool none_won = s.format == GolfFormat::Skins && !s.ranking.empty() && score(s.ranking.front()) == 0;
  for (int p : s.ranking)
    if (!none_won && score(p) == score(s.ranking.front())) s.leaders.push_back(p);
  return s;
}

RunningTotal running_total(const GolfGroup& group, const Standings& s, int player, std::size_t hole, bool stroke_untold) {
  const PlayerStanding& ps = s.players.at(static_cast<std::size_t>(player));
  RunningTotal t{ps.total_strokes, ps.total_par, ps.holes_scored};
  const GolfRound& r = group.round(player);
  if (r.card().size() <= hole) return t;
  const HoleCard& c = r.card()[hole];
  if (!(c.holed || c.picked_up) || !(r.finished() || r.hole_index() > hole)) return t;
  const bool counted = s.holes > hole;  // the whole group is past it: the standings hold it
  const int sign = !counted && !stroke_untold ? 1 : counted && stroke_untold ? -1 : 0;
  t.strokes += sign * c.strokes;
  t.par += sign * c.par;
  t.holes += sign;
  return t;
}

}  // namespace sweetspot
