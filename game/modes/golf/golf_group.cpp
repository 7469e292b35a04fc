#include "game/modes/golf/golf_group.hpp"

#include <algorithm>
#include <cstdio>

#include "game/modes/golf/wind.hpp"
#include "game/util/rng.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

bool same(const StrokeInput& a, const StrokeInput& b) {
  return a.club == b.club && a.aim == b.aim && a.meter.power == b.meter.power && a.meter.accuracy_ms == b.meter.accuracy_ms;
}

}  // namespace

GolfGroup::GolfGroup(const Assets& assets, const Course& course, std::vector<GolfPlayer> players, GolfOptions options)
    : course_(course), players_(std::move(players)), options_(std::move(options)) {
  if (players_.empty() || players_.size() > 4)
    throw InputError("a round has 1 to 4 players, not " + std::to_string(players_.size()));
  if (options_.format == GolfFormat::Match && players_.size() != 2)
    throw InputError("match play is between two players, not " + std::to_string(players_.size()));
  // A skin is won by beating everyone else on a hole: alone, every hole is a skin.
  if (options_.format == GolfFormat::Skins && players_.size() < 2)
    throw InputError("skins is played by 2 to 4 players, not " + std::to_string(players_.size()));
  check_range("gimme", options_.gimme_m, GolfOptions::kGimme, "m");
  winds_ = round_winds(course_, options_.seed);
  // The first player's bot draws from the round's seed itself (a one-bot round as `round
  // --bot S --seed N` always played); the others from seeds drawn off it.
  Rng seeds(options_.seed);
  for (std::size_t p = 0; p < players_.size(); ++p) {
    const GolfPlayer& pl = players_[p];
    if (pl.handicap < 0 || pl.handicap > kMaxHandicap)
      throw InputError("player " + std::to_string(p + 1) + " (" + pl.name + "): handicap " + std::to_string(pl.handicap) +
                       " is out of range (allowed [0, 54])");
    const GolferSkill& skill = golfer_skill(pl.skill);
    rounds_.emplace_back(assets, course_, skill, winds_);
    bots_.emplace_back(assets, skill, p == 0 ? options_.seed : seeds.next(), pl.bag);
    order_.push_back(static_cast<int>(p));
  }
  choose_next();
}

bool GolfGroup::bot_turn() const {
  if (finished()) return false;
  const GolfPlayer& p = players_[static_cast<std::size_t>(next_)];
  return !p.human || (options_.auto_putt && round(next_).lie() == "green");
}

StrokeInput GolfGroup::bot_stroke() {
  if (finished()) throw InputError("the round is over");
  const std::size_t p = static_cast<std::size_t>(next_);
  return bots_[p].plan(rounds_[p]);
}

const StrokeRecord& GolfGroup::play_bot(ShotResult* shot) { return play_stroke(bot_stroke(), true, shot); }

const StrokeRecord& GolfGroup::play(const StrokeInput& in, ShotResult* shot) { return play_stroke(in, false, shot); }

const StrokeRecord& GolfGroup::play_stroke(const StrokeInput& in, bool drawn, ShotResult* shot) {
  if (finished()) throw InputError("the round is over");
  const int p = next_;
  GolfRound& r = rounds_[static_cast<std::size_t>(p)];
  const std::size_t hole = r.hole_index();
  r.play(in, shot);
  events_.push_back({p, GolfEvent::Kind::Stroke, in, drawn});
  const std::size_t shot_index = r.card()[hole].shots.size() - 1;
  after_turn(p, hole);
  return r.card()[hole].shots[shot_index];
}

void GolfGroup::concede_hole() {
  if (finished()) throw InputError("the round is over");
  if (options_.format != GolfFormat::Match) throw InputError("a hole can be conceded in match play only");
  const int p = next_;
  GolfRound& r = rounds_[static_cast<std::size_t>(p)];
  const std::size_t hole = r.hole_index();
  r.concede_hole();
  events_.push_back({p, GolfEvent::Kind::ConcedeHole, {}, false});
  after_turn(p, hole);
  const std::string& who = players_[static_cast<std::size_t>(p)].name;
  const std::string decided = note_;  // the hole's result, when the opponent had holed out
  note_ = who + (who == "You" ? " concede hole " : " concedes hole ") + std::to_string(course_.holes[hole].number) +
          (decided.empty() ? "" : ". " + decided);
  // The hole is decided: the opponent need not hole out (Rule 3.2b(1)).
  GolfRound& other = rounds_[static_cast<std::size_t>(1 - p)];
  if (other.hole_index() == hole) {
    other.leave_hole();
    choose_next();
  }
}

bool GolfGroup::hole_lost_for_next() const {
  if (finished() || options_.format != GolfFormat::Match) return false;
  const std::size_t p = static_cast<std::size_t>(next_), o = 1 - p;
  const GolfRound& mine = rounds_[p];
  const GolfRound& theirs = rounds_[o];
  const std::size_t h = mine.hole_index();
  // Not yet decided while the opponent is still playing the hole, or has conceded it.
  if (theirs.hole_index() == h || h >= theirs.card().size() || theirs.card()[h].conceded) return false;
  const int their_net = theirs.card()[h].strokes - strokes_received(static_cast<int>(o))[h];
  const int best_mine = mine.card()[h].strokes + 1 - strokes_received(static_cast<int>(p))[h];
  return best_mine > their_net;
}

void GolfGroup::after_turn(int player, std::size_t hole_before) {
  note_.clear();
  GolfRound& r = rounds_[static_cast<std::size_t>(player)];
  const std::string& name = players_[static_cast<std::size_t>(player)].name;
  char buf[160];
  if (r.hole_index() == hole_before && options_.gimme_m > 0.0 && r.lie() == "green" && r.to_pin() <= options_.gimme_m) {
    r.concede_stroke();
    // The distance is the HUD's to give, in the player's units ("At rest 4 in from the pin").
    if (name == "You") std::snprintf(buf, sizeof buf, "Your putt is conceded");
    else std::snprintf(buf, sizeof buf, "%s's putt is conceded", name.c_str());
    note_ = buf;
  }
  const HoleCard& c = r.card()[hole_before];
  if (c.picked_up) {
    std::snprintf(buf, sizeof buf, "%s %s up at %d strokes", name.c_str(), name == "You" ? "pick" : "picks", GolfRound::kPickUp);
    note_ = buf;
  }
  choose_next();
}

std::vector<int> GolfGroup::honour_order() const {
  // Rule 6.4a: on the next tee the lowest score on the hole just played has the honour: the
  // net score where handicaps count (gross when nobody receives strokes), in match play the
  // winner of the hole (a hole conceded is lost). Ties keep the order they teed off in.
  if (hole_ == 0) return order_;
  const std::size_t h = hole_ - 1;
  std::vector<int> order = order_;
  std::vector<int> score(players_.size());
  for (std::size_t p = 0; p < players_.size(); ++p) {
    const HoleCard& c = rounds_[p].card()[h];
    score[p] = c.conceded ? 1000 : c.strokes - strokes_received(static_cast<int>(p))[h];
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return score[static_cast<std::size_t>(a)] < score[static_cast<std::size_t>(b)];
  });
  return order;
}

MatchResult GolfGroup::match_so_far() const {
  // The holes the whole group has finished (a player may have holed out on the next).
  std::vector<int> nets[2] = {net(0), net(1)};
  std::vector<int> conceded_by(hole_, -1);
  for (int p = 0; p < 2; ++p) {
    nets[p].resize(hole_);
    for (std::size_t h = 0; h < hole_; ++h)
      if (round(p).card()[h].conceded) conceded_by[h] = p;
  }
  return score_match(nets[0], nets[1], conceded_by, static_cast<int>(course_.holes.size()), players_[0].name, players_[1].name);
}

bool GolfGroup::match_decided() const {
  if (options_.format != GolfFormat::Match || hole_ == 0) return false;
  return match_so_far().decided_after >= 0;
}

std::string GolfGroup::match_hole_words(std::size_t hole) const {
  const MatchResult m = match_so_far();
  if (hole >= m.holes.size()) return {};
  const MatchHole& mh = m.holes[hole];
  const std::string number = std::to_string(course_.holes[hole].number);
  std::string won;
  if (mh.winner < 0) won = "Hole " + number + " halved";
  else {
    const std::string& name = players_[static_cast<std::size_t>(mh.winner)].name;
    won = name + (name == "You" ? " win hole " : " wins hole ") + number;
  }
  return won + ": " + mh.status;
}

void GolfGroup::choose_next() {
  const std::size_t n = course_.holes.size();
  auto on_hole = [&](int p) { return rounds_[static_cast<std::size_t>(p)].hole_index() == hole_; };
  const std::size_t hole_before = hole_;
  while (hole_ < n && std::none_of(order_.begin(), order_.end(), on_hole)) {
    ++hole_;
    hole_first_events_.push_back(events_.size());
    if (hole_ < n) order_ = honour_order();
  }
  // A match's hole just finished: who won it, and where the match stands ("Hole 2 halved:
  // scratch bot 1 up"), or the strokes alone would leave the player to work it out.
  if (options_.format == GolfFormat::Match && hole_ != hole_before && hole_before < n) {
    const std::string words = match_hole_words(hole_before);
    if (!words.empty()) note_ += (note_.empty() ? "" : ". ") + words;
  }
  // A match can only be decided as a hole ends.
  if (hole_ >= n || (hole_ != hole_before && match_decided())) {
    next_ = -1;
    return;
  }
  // Everyone tees off first, in the order of the honour (Rule 6.4a) ...
  for (int p : order_)
    if (on_hole(p) && rounds_[static_cast<std::size_t>(p)].card().back().shots.empty()) {
      next_ = p;
      return;
    }
  // ... then the ball farthest from the hole (Rule 6.4b).
  next_ = -1;
  double farthest = -1.0;
  for (int p : order_) {
    if (!on_hole(p)) continue;
    const double d = rounds_[static_cast<std::size_t>(p)].to_pin();
    if (d > farthest) {
      farthest = d;
      next_ = p;
    }
  }
}

void GolfGroup::replay(const std::vector<GolfEvent>& events) {
  for (std::size_t i = 0; i < events.size(); ++i) {
    const GolfEvent& e = events[i];
    const std::string where = "event " + std::to_string(i + 1);
    // A match saved by a build that played on past its decision: the holes after it were
    // never part of the match.
    if (finished() && match_decided()) break;
    if (finished()) throw InputError(where + ": the round was already over");
    if (e.player != next_)
      throw InputError(where + ": player " + std::to_string(e.player + 1) + " played, but it was player " +
                       std::to_string(next_ + 1) + "'s turn");
    if (e.kind == GolfEvent::Kind::ConcedeHole) {
      concede_hole();
      continue;
    }
    if (e.drawn) {
      const StrokeInput drawn = bot_stroke();
      if (!same(drawn, e.stroke))
        throw InputError(where + ": the bot's stroke differs from the record (a save from another build or seed)");
    } else if (bot_turn()) {
      throw InputError(where + ": a stroke given for a bot's turn (bots draw their own)");
    }
    play_stroke(e.stroke, e.drawn, nullptr);
  }
}

std::vector<int> GolfGroup::strokes_received(int player) const {
  // The holes' order of difficulty: their stroke indexes ranked 1..n (a course cut short,
  // `play --holes 2`, keeps the order of the indexes it has).
  std::vector<int> index;
  for (const CourseHole& h : course_.holes) {
    int rank = 1;
    for (const CourseHole& o : course_.holes) rank += o.stroke_index < h.stroke_index;
    index.push_back(rank);
  }
  int handicap = players_.at(static_cast<std::size_t>(player)).handicap;
  if (options_.format == GolfFormat::Match) {
    int lowest = handicap;
    for (const GolfPlayer& p : players_) lowest = std::min(lowest, p.handicap);
    handicap -= lowest;
  }
  return sweetspot::strokes_received(handicap, index);
}

std::vector<int> GolfGroup::net(int player) const {
  const GolfRound& r = round(player);
  const std::vector<int> given = strokes_received(player);
  std::vector<int> out;
  for (std::size_t h = 0; h < r.card().size(); ++h) {
    if (h >= r.hole_index()) break;  // the hole in play has no score yet
    out.push_back(r.card()[h].strokes - given[h]);
  }
  return out;
}

}  // namespace sweetspot
