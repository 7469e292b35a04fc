#include "game/modes/golf/range_session.hpp"

#include <algorithm>
#include <cmath>

#include "game/core/shot_result.hpp"
#include "game/modes/golf/swing_meter.hpp"
#include "game/rules/run_shot.hpp"
#include "physics/error.hpp"

namespace sweetspot {

RangeSession::RangeSession(const Assets& assets, const GolferSkill& skill, const Environment& air)
    : assets_(&assets), skill_(skill), air_(air) {}

const RangeShot& RangeSession::hit(const std::string& club, const MeterInput& meter, ShotResult* shot_out) {
  const auto& bag = golf_bag();
  if (club == "putter" || std::find(bag.begin(), bag.end(), club) == bag.end())
    throw InputError("club '" + club + "': the range takes the clubs of the bag but the putter");
  const EquipmentCatalog& eq = assets_->equipment();
  ShotSpec s;
  s.sport = "golf";
  s.world = kFlatWorld;
  s.environment = air_;
  ClubStrike c;
  c.club = club;
  c.swing = golfer_swing(skill_, meter, eq, club);
  s.strike = c;
  ShotResult r = run_shot(resolve(s, *assets_), "range " + club, {true, shot_out != nullptr});
  RangeShot shot;
  shot.club = club;
  shot.carry = r.trajectory.summary.carry_m;
  shot.total = r.trajectory.summary.total_m;
  shot.side = side_of_aim(r, r.trajectory.summary.landing_position);
  shots_.push_back(shot);
  if (shot_out != nullptr) *shot_out = std::move(r);
  return shots_.back();
}

Bag RangeSession::bag(const std::string& player, std::size_t first) const {
  Bag b;
  b.player = player;
  b.skill = skill_.name;
  const std::size_t n_shots = std::min(first, shots_.size());
  for (const std::string& club : golf_bag()) {
    std::vector<const RangeShot*> mine;
    for (std::size_t i = 0; i < n_shots; ++i)
      if (shots_[i].club == club) mine.push_back(&shots_[i]);
    if (mine.empty()) continue;
    const double n = static_cast<double>(mine.size());
    BagClub c;
    c.club = club;
    c.shots = static_cast<int>(mine.size());
    double side2 = 0.0;
    for (const RangeShot* s : mine) {
      c.carry += s->carry / n;
      c.total += s->total / n;
      side2 += s->side * s->side;
    }
    double var = 0.0;
    for (const RangeShot* s : mine) var += (s->carry - c.carry) * (s->carry - c.carry);
    c.carry_sd = mine.size() > 1 ? std::sqrt(var / (n - 1.0)) : 0.0;
    // About the target line (not the mean): a player's miss to one side is part of the spread.
    c.side_sd = std::sqrt(side2 / n);
    b.clubs.push_back(c);
  }
  std::stable_sort(b.clubs.begin(), b.clubs.end(), [](const BagClub& x, const BagClub& y) { return x.carry > y.carry; });
  return b;
}

RangeSession::SideMiss RangeSession::side_miss(const std::string& club, std::size_t first) const {
  SideMiss m;
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < std::min(first, shots_.size()); ++i)
    if (shots_[i].club == club) {
      sum += shots_[i].side;
      sum2 += shots_[i].side * shots_[i].side;
      ++m.shots;
    }
  if (m.shots == 0) return m;
  m.mean = sum / m.shots;
  if (m.shots > 1) m.sd = std::sqrt(std::max(0.0, (sum2 - m.shots * m.mean * m.mean) / (m.shots - 1)));
  return m;
}

Bag gap_bag(const Assets& assets, const GolferSkill& skill, int shots, std::uint64_t seed) {
  if (shots < 1 || shots > 100) throw InputError("--shots " + std::to_string(shots) + " is out of range (allowed [1, 100])");
  RangeSession range(assets, skill);
  GolfBot bot(assets, skill, seed);
  for (const std::string& club : golf_bag()) {
    if (club == "putter") continue;
    for (int k = 0; k < shots; ++k) range.hit(club, bot.full_swing());
  }
  return range.bag(skill.name + " bot");
}

std::vector<GolfBot::Stock> bag_stock(const Bag& bag) {
  std::vector<GolfBot::Stock> out;
  for (const BagClub& c : bag.clubs) out.push_back({c.club, c.carry, c.total, c.carry_sd, c.side_sd});
  return out;
}

}  // namespace sweetspot
