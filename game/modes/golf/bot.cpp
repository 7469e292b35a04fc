#include "game/modes/golf/bot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
AlongAcross relative(const Vec3& from, double line, const Vec3& p) {
  const double dx = p.x() - from.x(), dz = p.z() - from.z();
  const double c = std::cos(line), s = std::sin(line);
  return {dx * c + dz * s, -dx * s + dz * c};
}

namespace {

/// How near the cup's centre (m across the line) a planned putt must cross: a quarter of
/// the cup's 54 mm radius, so the player's own start-line error, not the plan, decides it.
constexpr double kPuttCentred = 0.0135;

/// A putt's line runs through grass a putter cannot roll through (rough, sand, water): a
/// ball on the green's edge with the cup beyond a strip of rough is chipped, not putted.
/// A collar of fairway is putted through, up to kPuttableCollar of it.
bool putt_line_clear(const GolfRound& round) {
  constexpr double kStep = 0.25;          // m along the line
  constexpr double kPuttableCollar = 3.0; // m of fairway or tee grass a tour player still putts across
  const Terrain& world = *round.hole().world->world;
  double collar = 0.0;
  for (const GolfRound::LineStretch& s : round.ground_to_pin(kStep)) {
    if (!s.ground) return false;
    const SurfaceKind k = world.material(s.ground->material).kind;
    if (k == SurfaceKind::Green) continue;
    if (k != SurfaceKind::Fairway && k != SurfaceKind::Tee) return false;
    collar += s.length;
  }
  return collar <= kPuttableCollar;
}

/// What a lie costs the next stroke, in metres of fairway: from Broadie's PGA Tour baseline
/// (Every Shot Counts, 2014), 150 yd out a tour player needs ~2.98 strokes from the fairway,
/// ~3.23 from the rough and ~3.40 from sand, and ~0.0045 strokes per metre nearer or farther
/// there: the rough is worth ~55 m, sand ~90 m. The green and the tee cost nothing.
double lie_cost(const std::string& surface) {
  if (surface == "fairway" || surface == "green" || surface == "tee") return 0.0;
  return surface == "sand" ? 90.0 : 55.0;
}
/// The risk of a flight planned into a tree's branches, in metres of fairway: where it drops
/// is luck (the plan sees one bounce of many), and Broadie's recovery shots, from behind trees,
/// cost a tour player ~0.5 strokes more than the same distance from the rough: ~100 m.
constexpr double kTreeCost = 100.0;
/// A penalty stroke in metres of fairway at Broadie's ~0.0045 strokes per metre: ~220 m.
constexpr double kStrokeCost = 220.0;
/// Around the green a chip that stays off it is another chip, not a putt: from ~10 yd a tour
/// player needs ~2.4-2.5 strokes from the rough and ~2.0 from 30 ft on the green, where a
/// metre of putt is worth ~0.07 strokes (Broadie's baseline): the rough counts as ~5 m more.
constexpr double kChipLieCost = 5.0;
/// The ways out of trees a bot tries: lines this far apart (rad, ~11°) on each side of the
/// planned one, up to ~57° off it, with every other club from the planned one down.
constexpr double kWayOutStep = 0.2;
constexpr int kWayOutLines = 5;
constexpr std::size_t kWayOutClubStride = 2;

/// Whether a tree stands where a flight from the ball that lands at `land`, or a miss of it,
/// could first touch one: a crown nearer the ball than the landing (with its spread), not
/// behind it. Where none does, no miss is flown to look (the links, an open fairway).
bool trees_in_reach(const GolfRound& round, const Vec3& land) {
  const Vec3& b = round.ball();
  const double lx = land.x() - b.x(), lz = land.z() - b.z();
  const double reach = std::hypot(lx, lz);
  if (reach <= 0.0) return false;
  for (const TreeCrown& c : round.hole().world->trees) {
    const double cx = c.centre.x() - b.x(), cz = c.centre.z() - b.z();
    if (std::hypot(cx, cz) <= reach + c.radius && (cx * lx + cz * lz) / reach >= -c.radius) return true;
  }
  return false;
}

/// How a lie plays for the next stroke: the short grass, then the rough (and anything else
/// off the fairway), then sand.
int lie_rank(const std::string& surface) {
  if (surface == "fairway" || surface == "green" || surface == "tee") return 0;
  return surface == "sand" ? 2 : 1;
}

/// The point on the hole's line from `bend` on (its later bends, then `pin`) that lies
/// `reach` m from `ball` in a straight line, or the pin when all of it is nearer.
Vec3 past_bend(const Vec3& ball, const Vec3& bend, const std::vector<Vec3>& later, const Vec3& pin, double reach) {
  const auto flat = [](const Vec3& a, const Vec3& b) { return std::hypot(a.x() - b.x(), a.z() - b.z()); };
  Vec3 a = bend;
  std::vector<Vec3> rest = later;
  rest.push_back(pin);
  for (const Vec3& b : rest) {
    if (flat(ball, b) >= reach) {
      // Bisect the segment for the point at `reach` (the distance grows along it from a
      // point nearer than `reach` to one beyond).
      double lo = 0.0, hi = 1.0;
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (flat(ball, a + mid * (b - a)) < reach ? lo : hi) = mid;
      }
      return a + lo * (b - a);
    }
    a = b;
  }
  return pin;
}

}  // namespace

GolfBot::GolfBot(const Assets& assets, const GolferSkill& skill, std::uint64_t seed, std::vector<Stock> bag)
    : assets_(&assets), skill_(skill), rng_(seed) {
  const EquipmentCatalog& eq = assets.equipment();
  for (const std::string& club : golf_bag()) {
    if (club == "putter") continue;
    ShotSpec s;
    s.sport = "golf";
    s.world = kFlatWorld;
    ClubStrike c;
    c.club = club;
    c.swing = golfer_swing(skill, MeterInput{}, eq, club);
    s.strike = c;
    const ShotResult r = run_shot(resolve(s, assets), club, {true, false});
    stock_.push_back({club, r.trajectory.summary.carry_m, r.trajectory.summary.total_m, 0.0, 0.0});
  }
  // The player's measured clubs replace the skill's; the rest keep it. Longest first, as a
  // bag is ordered: the shortest is the partial-swing wedge.
  for (const Stock& m : bag)
    for (Stock& s : stock_)
      if (s.club == m.club) s = m;
  std::stable_sort(stock_.begin(), stock_.end(), [](const Stock& a, const Stock& b) { return a.carry > b.carry; });
}

std::string GolfBot::suggest(double distance, bool teed) const {
  // The shortest club that carries the distance, else the longest allowed.
  const Stock* pick = nullptr;
  for (const Stock& s : stock_) {
    if (s.club == "driver" && !teed) continue;
    if (s.carry >= distance && (pick == nullptr || s.carry < pick->carry)) pick = &s;
  }
  if (pick == nullptr) {
    for (const Stock& s : stock_) {
      if (s.club == "driver" && !teed) continue;
      if (pick == nullptr || s.carry > pick->carry) pick = &s;
    }
  }
  return pick->club;
}

std::size_t GolfBot::stock_index(const std::string& club) const {
  return static_cast<std::size_t>(
      std::find_if(stock_.begin(), stock_.end(), [&](const Stock& s) { return s.club == club; }) - stock_.begin());
}

StrokeInput GolfBot::putt(const GolfRound& round) const {
  StrokeInput in;
  in.club = "putter";
  const double d = round.to_pin();
  const double line = round.line_to_pin();
  const Vec3 start = round.ball();
  // Roll deceleration for first guesses: a 10 ft Stimpmeter green, ~0.55 m/s².
  constexpr double kDecel = 0.55;
  const double v_target = std::sqrt(2.0 * kDecel * GolfBot::kPuttPast);  // at the cup, to finish 0.43 m past
  const double full = full_swing_speed(skill_, assets_->equipment().club_info_of("putter"));
  double power = std::clamp(std::sqrt(2.0 * kDecel * (d + GolfBot::kPuttPast)) / 1.6 / full, 0.02, 1.1);
  double aim = 0.0;
  // The tried plan that holed nearest the centre: what the bot plays when the tries run out
  // before one is centred (the last correction is untried and may miss).
  std::optional<std::pair<double, StrokeInput>> best_holed;
  const auto remember = [&](double off_centre) {
    if (!best_holed || std::abs(off_centre) < best_holed->first) best_holed = {std::abs(off_centre), in};
  };
  for (int i = 0; i < 6; ++i) {
    in.aim = aim;
    in.meter.power = power;
    const ShotResult r = round.simulate(in, true);
    // Where the ball crosses the cup's distance, and how fast (between two samples): the
    // line and the speed to fix. A ball that drops is read from the sample before it fell.
    const auto& sm = r.trajectory.samples;
    const std::size_t usable = r.end == ShotEnd::Holed && sm.size() > 1 ? sm.size() - 1 : sm.size();
    bool crossed = false;
    double across = 0.0, v = 0.0, reach = 0.0;
    for (std::size_t k = 1; k < usable; ++k) {
      const AlongAcross a = relative(start, line, sm[k - 1].position), b = relative(start, line, sm[k].position);
      reach = std::max(reach, b.along);
      if (b.along >= d && a.along < d) {
        const double f = (d - a.along) / std::max(b.along - a.along, 1e-9);
        across = a.across + f * (b.across - a.across);
        v = sm[k - 1].velocity.norm() + f * (sm[k].velocity.norm() - sm[k - 1].velocity.norm());
        crossed = true;
        break;
      }
    }
    // Holed is not enough: a putt that dies into the front lip, or a line that only catches
    // the side of the cup, drops for the plan and misses with the smallest error. Done when
    // it reaches the cup at about the aimed speed and crosses within kPuttCentred of the
    // centre; a ball that drops before the centre line is judged by its speed as it fell.
    if (r.end == ShotEnd::Holed && !crossed && usable > 0) {
      const AlongAcross fell = relative(start, line, sm[usable - 1].position);
      if (sm[usable - 1].velocity.norm() < 0.5 * v_target) {  // died into the lip: firmer
        power = std::clamp(power * std::sqrt((d + GolfBot::kPuttPast) / std::max(fell.along, 0.05)), 0.02, 1.1);
        continue;
      }
      if (std::abs(fell.across) < kPuttCentred) return in;
      remember(fell.across);
      aim = std::clamp(aim - std::atan2(fell.across, d), -0.5, 0.5);  // in off the side: to the centre
      continue;
    }
    if (r.end == ShotEnd::Holed) {
      if (std::abs(across) < kPuttCentred && v > 0.5 * v_target && v < 1.5 * v_target) return in;
      remember(across);
    }
    if (!crossed) {  // short: more speed, the line from where it stopped
      const AlongAcross at = relative(start, line, r.trajectory.summary.rest_position);
      power = std::clamp(power * std::sqrt((d + GolfBot::kPuttPast) / std::max(std::max(reach, at.along), 0.05)), 0.02, 1.1);
      if (at.along > 0.3 * d) aim = std::clamp(aim - std::atan2(at.across, at.along), -0.5, 0.5);
      continue;
    }
    power = std::clamp(power * std::sqrt((2.0 * kDecel * d + v_target * v_target) / (2.0 * kDecel * d + v * v)), 0.02, 1.1);
    aim = std::clamp(aim - std::atan2(across, d), -0.5, 0.5);
  }
  if (best_holed) return best_holed->second;
  in.aim = aim;
  in.meter.power = power;
  return in;
}

StrokeInput GolfBot::intend(const GolfRound& round, std::string* passed_over) const {
  if (passed_over != nullptr) passed_over->clear();
  if (round.lie() == "green" && putt_line_clear(round)) return putt(round);
  double d = round.to_pin();
  const bool teed = round.teed();
  auto allowed = [&](const Stock& s) { return !(s.club == "driver" && !teed); };
  // The partial-swing club: the shortest-carrying club allowed from here.
  const Stock* shortest_allowed = &stock_.back();
  for (const Stock& s : stock_)
    if (allowed(s)) shortest_allowed = &s;
  const Stock& shortest = *shortest_allowed;
  double reach = 0.0;
  for (const Stock& s : stock_)
    if (allowed(s)) reach = std::max(reach, s.total);
  bool going_for_pin = d <= reach;
  double line = round.line_to_pin();
  // Out of reach on a bending hole: play to the next bend of its line (a dogleg's corner), as
  // far as the shortest club that gets there carries it. A corner well inside the longest
  // club's carry may also be played past, along the next leg (below).
  std::optional<Vec3> beyond;
  const Stock* longest = nullptr;
  for (const Stock& s : stock_)
    if (!longest && allowed(s)) longest = &s;
  if (const std::optional<Vec3> bend = round.next_bend(); bend && !going_for_pin) {
    const Vec3& b = round.ball();
    const double to_bend = std::hypot(bend->x() - b.x(), bend->z() - b.z());
    if (to_bend >= shortest.carry) {  // a corner nearer than a full wedge is played past, toward the cup
      d = to_bend;
      line = std::atan2(bend->z() - b.z(), bend->x() - b.x());
    }
    // A player with 300 m to go and the corner 100 m away takes a long club past the corner,
    // not a 9-iron to it: the target on the next leg as far away as his longest club carries.
    constexpr double kPastBend = 30.0;  // m: the corner at least this far inside that carry
    if (longest && longest->carry - to_bend > kPastBend) {
      std::vector<Vec3> later;
      bool after = false;
      for (const Vec3& x : round.hole().bends) {
        if (after) later.push_back(x);
        after = after || x == *bend;
      }
      beyond = past_bend(b, *bend, later, round.hole().pin, longest->carry);
    }
  }
  // Aims are taken from the line to the cup: the bend's line starts this far off it.
  double toward = std::remainder(line - round.line_to_pin(), 2.0 * kPi);
  // Tries a club on the course and corrects the aim (wind, slopes, curve) and a partial
  // swing's power; returns the stroke, how far along the line to the cup it stops in these
  // conditions, and whether it ends in a penalty.
  struct Tried {
    StrokeInput in;
    double reach = 0.0;  ///< m along the line where it stops (or is lost)
    bool lost = false;
    bool in_tree = false;      ///< its flight ends in a tree's branches or trunk
    Vec3 land = Vec3::Zero();  ///< where it first lands
    Vec3 rest = Vec3::Zero();  ///< where it stops (or is lost)
  };
  // One correction from where `t` stopped: the aim turned onto the line (within 0.4 rad of the
  // line played: a dogleg's corner may lie further off the line to the cup than that), and a
  // partial swing's power scaled to the distance.
  const auto correct = [&](const Tried& t, double* aim, double* power) {
    const AlongAcross at = relative(round.ball(), line, t.rest);
    if (at.along <= 1.0) return;
    *aim = std::clamp(std::clamp(*aim - std::atan2(at.across, at.along), toward - 0.4, toward + 0.4), StrokeInput::kAim.min,
                      StrokeInput::kAim.max);
    if (*power < 1.0 && going_for_pin) *power = std::clamp(*power * std::pow(d / at.along, 0.8), 0.05, 1.0);
  };
  // `aim` starts the correction (a neighbour's); `iterations` simulations, the last one told.
  auto tune = [&](const std::string& club, double power, double aim, int iterations, double accuracy_ms = 0.0) {
    Tried t;
    t.in.club = club;
    t.in.meter.accuracy_ms = accuracy_ms;
    for (int i = 0;; ++i) {
      t.in.aim = aim;
      t.in.meter.power = power;
      const ShotResult r = round.simulate(t.in);
      t.lost = r.end == ShotEnd::Water || r.end == ShotEnd::OutOfBounds || r.end == ShotEnd::StepLimit;
      t.in_tree = round.first_touch_in_a_tree(r.trajectory.summary);
      t.land = r.trajectory.summary.landing_position;
      t.rest = t.lost ? t.land : r.trajectory.summary.rest_position;
      t.reach = relative(round.ball(), line, t.rest).along;
      if (i + 1 >= iterations) return t;
      correct(t, &aim, &power);
    }
  };
  // `more` simulations on from `t`: the same as having tuned it that many iterations longer.
  const auto refine = [&](const Tried& t, int more) {
    double aim = t.in.aim, power = t.in.meter.power;
    correct(t, &aim, &power);
    return tune(t.in.club, power, aim, more, t.in.meter.accuracy_ms);
  };
  // Going for the cup with a full swing that stops short of it by more than this, the next
  // club up is tried (below), and the partial wedge gives way to the clubs above it: a full
  // swing a metre short is the one the meter's pin mark puts past 100 % ("an overswing: more
  // club?"), and the caddie who handed it over would contradict his own meter.
  constexpr double kShortForMore = 1.0;  // m
  // A partial wedge, unless the wedge's full swing stops short from here (into a wind, off a
  // heavy lie: a 78 yd lob wedge that carries 66 yd today is no club for 77 yd).
  std::optional<Tried> first_chip;
  if (d < shortest.carry) {
    first_chip = tune(shortest.club, std::clamp(std::pow(d / shortest.carry, 0.8), 0.05, 1.0), toward, 3);
    // (Or ends in the water short of the green: the longer clubs are tried as for any shot.)
    if (first_chip->in.meter.power >= 1.0 && (first_chip->lost || d - first_chip->reach > kShortForMore)) first_chip.reset();
  }
  if (first_chip) {
    // A partial wedge: carry grows a little faster than swing speed; start at that guess and
    // correct the aim. Where rough or a bank lies short of the cup a ball landing there stops
    // dead and one a little firmer runs past, so the correction's steps (d / reach)^0.8 can
    // swing about the cup without settling: unsettled, the power is chosen among its
    // neighbours, the one whose ball stops nearest the cup counted with its lie (a chip left
    // in the rough is another chip).
    const Tried& first = *first_chip;
    const Vec3& pin = round.hole().pin;
    const auto left = [&](const Tried& t) {
      if (t.lost) return std::numeric_limits<double>::infinity();
      return std::hypot(pin.x() - t.rest.x(), pin.z() - t.rest.z()) + kChipLieCost * (lie_rank(round.surface_at(t.rest)) > 0);
    };
    Tried best_chip = first;
    double best_left = left(first);
    // Settled on the green within a putt a tour player holes nine times in ten (~1 m): done.
    constexpr double kSettled = 1.0;  // m
    if (best_left <= kSettled) return first.in;
    // Every 10 % of the power from 0.6 to 1.4 times it, then 5 % either side of the best.
    const double p0 = first.in.meter.power;
    double best_f = 1.0;
    const auto try_power = [&](double f) {
      const Tried t = tune(shortest.club, std::clamp(p0 * f, 0.05, 1.0), first.in.aim, 1);
      if (const double l = left(t); l < best_left) best_chip = t, best_left = l, best_f = f;
    };
    for (int i = 0; i <= 8; ++i) try_power(0.6 + 0.1 * i);
    const double around = best_f;
    for (const double df : {-0.05, 0.05}) try_power(around + df);
    return best_chip.in;
  }
  // The club that plays like the distance today: the still-air club, tried on the course
  // (the wind, the lie, the ground); a shorter one when it runs past the cup by more than the
  // gap to the next club, a longer one when it stops short, down the bag when it ends in a
  // penalty. Never a club that ends in a penalty when one stays in play.
  const std::string base = suggest(d, teed);
  std::size_t at = 0;
  while (stock_[at].club != base) ++at;
  Tried best = tune(base, 1.0, toward, 3);
  const double aim = best.in.aim;
  auto good = [&](const Tried& t) { return !t.lost && t.reach >= d; };
  if (good(best)) {
    // Shorter while it still gets there (each tried with this club's aim, then tuned).
    for (std::size_t k = at + 1; k < stock_.size(); ++k) {
      if (!allowed(stock_[k]) || best.reach - d <= stock_[k - 1].carry - stock_[k].carry) break;
      const Tried t = tune(stock_[k].club, 1.0, aim, 1);
      if (!good(t)) break;
      best = refine(t, 1);
    }
  } else if (!best.lost) {
    // Short: one club longer, if it stays in play. Going for the cup, swung to its distance
    // (a soft pitching wedge where the full sand wedge stops a yard short), not full: a
    // full swing with it flies a whole club's gap (~20 m) past. The one that stops nearer
    // the cup is played.
    if (at > 0 && allowed(stock_[at - 1])) {
      const Stock& longer = stock_[at - 1];
      const double power = going_for_pin ? std::clamp(std::pow(d / longer.carry, 0.8), 0.05, 1.0) : 1.0;
      const Tried t = tune(longer.club, power, aim, power < 1.0 ? 3 : 2);
      if (!t.lost && (!going_for_pin || std::abs(t.reach - d) < std::abs(best.reach - d))) best = t;
    }
  } else {
    // In a penalty. A strong wind can blow the first tries' aim off the map before the
    // correction settles, so the club is tuned on; then longer clubs (into that wind one of
    // them may be the one that gets there), and down the bag to the first club in play. Of those
    // in play the one that stops nearest the distance is played: laying up 80 yd short of a
    // par 3 with a wedge is no player's answer to a wind the 6-iron holds.
    std::vector<Tried> options{refine(best, 3)};
    // Up the bag while the longer clubs still end in the penalty (a headwind that drops the
    // stock club into the water in front of a green), to the first that carries it.
    for (std::size_t k = at; options.front().lost && k-- > 0;) {
      if (!allowed(stock_[k])) continue;
      const Tried t = tune(stock_[k].club, 1.0, options.front().in.aim, 2);
      options.push_back(t);
      if (!t.lost) break;
    }
    for (std::size_t k = at + 1; k < stock_.size(); ++k) {
      if (!allowed(stock_[k])) continue;
      const Tried t = tune(stock_[k].club, 1.0, aim, 2);
      if (!t.lost) {
        options.push_back(t);
        break;
      }
    }
    bool found = false;
    for (const Tried& t : options)
      if (!t.lost && (!found || std::abs(t.reach - d) < std::abs(best.reach - d))) best = t, found = true;
  }
  // Past the corner: the longest club aimed along the next leg, played when it stops
  // clearly nearer the cup than the layup and lies no worse.
  if (beyond && longest) {
    const Vec3& b = round.ball();
    line = std::atan2(beyond->z() - b.z(), beyond->x() - b.x());
    toward = std::remainder(line - round.line_to_pin(), 2.0 * kPi);
    const Tried t = tune(longest->club, 1.0, toward, 3);
    const auto to_cup = [&](const Vec3& p) { return std::hypot(round.hole().pin.x() - p.x(), round.hole().pin.z() - p.z()); };
    constexpr double kClearlyNearer = 15.0;  // m, about half a club
    if (!t.lost && to_cup(t.rest) < to_cup(best.rest) - kClearlyNearer &&
        lie_rank(round.surface_at(t.rest)) <= lie_rank(round.surface_at(best.rest)))
      best = t;
  }
  // Going for the cup with a full swing that flies well past it (the next club down stops
  // short, a whole gap away): the same club swung to the distance, as a player takes a
  // three-quarter wedge, when it stops nearer.
  constexpr double kPastForPartial = 6.0;  // m: about a third of the wedges' ~20 m gaps
  if (going_for_pin && !best.lost && best.in.meter.power >= 1.0 && best.reach - d > kPastForPartial) {
    const Stock& s = stock_[stock_index(best.in.club)];
    const Tried t = tune(s.club, std::clamp(std::pow(d / s.carry, 0.8), 0.05, 1.0), best.in.aim, 3);
    if (!t.lost && std::abs(t.reach - d) < std::abs(best.reach - d)) best = t;
  }
  // Going for the cup with a full swing that stops short of it (kShortForMore): the next club
  // up swung smooth to the distance, when it stops nearer ("take one more club": a full swing
  // is never forced past 100 %, where its error grows, swing_meter.hpp).
  if (going_for_pin && !best.lost && best.in.meter.power >= 1.0 && d - best.reach > kShortForMore) {
    const std::size_t k = stock_index(best.in.club);
    if (k > 0 && allowed(stock_[k - 1])) {
      const Stock& s = stock_[k - 1];
      const Tried t = tune(s.club, std::clamp(std::pow(d / s.carry, 0.8), 0.05, 1.0), best.in.aim, 3);
      if (!t.lost && std::abs(t.reach - d) < std::abs(best.reach - d)) best = t;
    }
  }
  // A plan that runs through the green into the rough behind it (a cup cut near the back, a
  // ball that releases): a player takes the club down, or this one a little softer, so that
  // it lands short and stops on the green; whichever of the three stops nearest the cup,
  // counted with its lie (kChipLieCost off the green).
  if (going_for_pin && !best.lost && round.surface_at(best.rest) != "green") {
    const Vec3& pin = round.hole().pin;
    const auto left = [&](const Tried& t) {
      if (t.lost) return std::numeric_limits<double>::infinity();
      return std::hypot(pin.x() - t.rest.x(), pin.z() - t.rest.z()) + kChipLieCost * (round.surface_at(t.rest) != "green");
    };
    const std::size_t k = stock_index(best.in.club);
    std::vector<Tried> options;
    if (best.reach > d && k + 1 < stock_.size() && allowed(stock_[k + 1])) options.push_back(tune(stock_[k + 1].club, 1.0, best.in.aim, 2));
    if (best.reach > d) options.push_back(tune(best.in.club, std::clamp(best.in.meter.power * std::pow(d / best.reach, 1.25), 0.05, 1.0), best.in.aim, 2));
    for (const Tried& t : options)
      if (left(t) < left(best)) best = t;
  }
  // A part swing going for the cup, tuned in a few steps from a guess, can stop well short
  // of where a power between two tries would (a scratch player's 3-wood at 84 % stopping
  // 14 m short in the rough where 88 % stops at the pin on the green): the power is found
  // as the HUD's pin mark is, by halving the bracket round the cup, and taken when it stops
  // nearer the cup on a lie no worse.
  constexpr double kNearEnough = 2.0;  // m: inside it a part swing is not tuned further
  if (going_for_pin && !best.lost && best.in.meter.power < 1.0 && std::abs(best.reach - d) > kNearEnough) {
    constexpr double kWiden = 0.05, kLeast = 0.05;  // power: the bracket's first step, the lowest swing
    const std::string club = best.in.club;
    const double a = best.in.aim;
    Tried lo = best, hi = best;
    for (int i = 0; i < 4 && hi.reach < d && !hi.lost && hi.in.meter.power < 1.0; ++i)
      hi = tune(club, std::min(1.0, hi.in.meter.power + kWiden), a, 1);
    for (int i = 0; i < 4 && lo.reach > d && !lo.lost && lo.in.meter.power > kLeast; ++i)
      lo = tune(club, std::max(kLeast, lo.in.meter.power - kWiden), a, 1);
    if (!lo.lost && !hi.lost && lo.reach <= d && hi.reach >= d) {
      for (int i = 0; i < 5; ++i) {
        const Tried mid = tune(club, 0.5 * (lo.in.meter.power + hi.in.meter.power), a, 1);
        if (mid.lost) break;
        (mid.reach < d ? lo : hi) = mid;
      }
      const Tried& near = std::abs(lo.reach - d) < std::abs(hi.reach - d) ? lo : hi;
      if (std::abs(near.reach - d) < std::abs(best.reach - d) &&
          lie_rank(round.surface_at(near.rest)) <= lie_rank(round.surface_at(best.rest)))
        best = near;
    }
  }
  // A plan that gets there only when struck perfectly: a player who carries trouble in front
  // of the green takes enough club that his usual short one still clears it. Struck a power
  // standard deviation short (his full swing's spread, more for a part swing, as plan()
  // draws it), where does it stop? In a worse lie than the plan's (the rough or a bunker
  // short of the green, water), he swings a standard deviation harder, or takes the next club
  // up when he is already swinging full, if that plan stays in play on as good a lie and its
  // own short one clears.
  if (going_for_pin && !best.lost) {
    const auto rank = [&](const Tried& t) { return t.lost ? 3 : lie_rank(round.surface_at(t.rest)); };
    const auto spread = [&](double power) { return skill_.power_sd + skill_.partial_feel_sd * (1.0 - std::min(power, 1.0)); };
    const auto short_of = [&](const Tried& t) {
      return tune(t.in.club, t.in.meter.power * (1.0 - spread(t.in.meter.power)), t.in.aim, 1);
    };
    // Only where worse ground lies in a short miss's way is it simulated: along the line
    // from where it would land (carry grows as power^1.25, less a margin for its bounce and
    // the wind) through the plan's landing to its rest. On open fairway or green no short
    // miss can finish worse.
    const auto worse_ground_short = [&](const Tried& t) {
      constexpr double kStep = 2.0;    // m between the ground's samples: a bunker's lip is wider
      constexpr double kMargin = 5.0;  // m short of the estimate
      const Vec3& b = round.ball();
      const double carry = std::hypot(t.land.x() - b.x(), t.land.z() - b.z());
      if (carry < kStep) return true;
      const double lands = carry * std::pow(1.0 - spread(t.in.meter.power), 1.25) - kMargin;
      const int plan = rank(t);
      const auto worse = [&](const Vec3& p) {
        const std::string s = round.surface_at(p);
        return (s == "water" || s == "out_of_bounds" ? 3 : lie_rank(s)) > plan;
      };
      for (double x = std::max(0.0, lands); x < carry; x += kStep)
        if (worse(b + (t.land - b) * (x / carry))) return true;
      const double roll = std::hypot(t.rest.x() - t.land.x(), t.rest.z() - t.land.z());
      for (double x = 0.0; x <= roll; x += kStep)
        if (worse(roll > 0.0 ? Vec3(t.land + (t.rest - t.land) * (x / roll)) : t.land)) return true;
      // A wedge that spins back stops short of where it landed: its short miss stops as much
      // nearer the ball again as it lands short.
      const Vec3 back = (b - t.land) / carry;
      for (double x = kStep; x <= carry - lands; x += kStep)
        if (worse(t.rest + back * x)) return true;
      return false;
    };
    if (worse_ground_short(best) && rank(short_of(best)) > rank(best)) {
      const std::size_t k = stock_index(best.in.club);
      std::optional<Tried> firmer;
      if (best.in.meter.power < 1.0)
        firmer = tune(best.in.club, std::min(1.0, best.in.meter.power * (1.0 + spread(best.in.meter.power))), best.in.aim, 1);
      else if (k > 0 && allowed(stock_[k - 1]))
        firmer = tune(stock_[k - 1].club, 1.0, best.in.aim, 2);
      if (firmer && rank(*firmer) <= rank(best) && (!worse_ground_short(*firmer) || rank(short_of(*firmer)) <= rank(best))) best = *firmer;
    }
  }
  // Near trees: the plan, or the plan as this golfer may strike it, flies into one. A player
  // takes the way out that leaves the best next shot: a line off to the side of it, or a club
  // that flies under or over it, judged by how far from the cup it stops and on what, struck
  // as this golfer strikes it: the mean over the plan and its misses either way of half and
  // one standard deviation of the meter's timing, at the plan's own power, so neither a gap
  // the ball only threads when struck perfectly nor a line held off a row of trees for the
  // wind to bring back is taken. The misses are flown only where a tree stands in their way.
  const double miss = skill_.accuracy_sd_ms;
  const auto missed = [&](const Tried& planned, double f) {
    return tune(planned.in.club, planned.in.meter.power, planned.in.aim, 1, f * miss);
  };
  // The plan's misses of one standard deviation either way, flown once: whether they find a
  // tree, and then in the plan's own cost.
  std::optional<std::pair<Tried, Tried>> wide;
  if (!best.in_tree && trees_in_reach(round, best.land)) wide.emplace(missed(best, -1.0), missed(best, 1.0));
  if (best.in_tree || (wide && (wide->first.in_tree || wide->second.in_tree))) {
    const Vec3& pin = round.hole().pin;
    const auto cost = [&](const Tried& t) {
      if (t.lost) return round.to_pin() + kStrokeCost;  // stroke and distance, or a drop back
      const double to_cup = std::hypot(pin.x() - t.rest.x(), pin.z() - t.rest.z());
      return to_cup + lie_cost(round.surface_at(t.rest)) + (t.in_tree ? kTreeCost : 0.0);
    };
    // `at_one_sd`: those misses when already flown.
    const auto as_struck = [&](const Tried& planned, const std::pair<Tried, Tried>* at_one_sd = nullptr) {
      double sum = cost(planned);
      sum += cost(at_one_sd ? at_one_sd->first : missed(planned, -1.0));
      sum += cost(missed(planned, -0.5));
      sum += cost(missed(planned, 0.5));
      sum += cost(at_one_sd ? at_one_sd->second : missed(planned, 1.0));
      return sum / 5.0;
    };
    double best_cost = as_struck(best, wide ? &*wide : nullptr);
    const std::string before_trees = best.in.club;
    // The plan's club at its power on lines about its own (at half the steps: a wind's line
    // held a few degrees nearer the trees' side may be all that changes), then every other
    // club down the bag swung full on lines about the hole's.
    const std::size_t planned = stock_index(best.in.club);
    const double planned_power = best.in.meter.power, planned_aim = best.in.aim;
    for (std::size_t k = planned; k < stock_.size(); k += kWayOutClubStride) {
      if (!allowed(stock_[k])) continue;
      const bool own = k == planned;
      for (int i = -kWayOutLines * (own ? 2 : 1); i <= kWayOutLines * (own ? 2 : 1); ++i) {
        const double a = std::clamp(own ? planned_aim + 0.5 * kWayOutStep * i : toward + kWayOutStep * i, StrokeInput::kAim.min,
                                    StrokeInput::kAim.max);
        // Struck perfectly it must already beat the best: only then are its misses tried.
        const Tried t = tune(stock_[k].club, own ? planned_power : 1.0, a, 1);
        if (cost(t) >= best_cost) continue;
        if (const double c = as_struck(t); c < best_cost) best = t, best_cost = c;
      }
    }
    if (passed_over != nullptr && best.in.club != before_trees) *passed_over = before_trees;
  }
  return best.in;
}

MeterInput GolfBot::full_swing() {
  MeterInput m;
  m.power = std::clamp(1.0 + rng_.normal(skill_.power_sd), 0.02, 1.1);
  m.accuracy_ms = std::clamp(rng_.normal(skill_.accuracy_sd_ms), MeterInput::kAccuracy.min, MeterInput::kAccuracy.max);
  return m;
}

StrokeInput GolfBot::plan(const GolfRound& round) {
  StrokeInput in = intend(round);
  if (in.club == "putter") {
    in.meter.power = std::clamp(in.meter.power * (1.0 + rng_.normal(skill_.putt_speed_sd)), 0.01, 1.1);
    in.aim = std::clamp(in.aim + rng_.normal(skill_.putt_aim_sd), -1.5, 1.5);
    return in;
  }
  // A partial swing is judged by feel: its power strays more the shorter it is.
  const bool partial = in.meter.power < 1.0;
  const double power_sd = skill_.power_sd + skill_.partial_feel_sd * (1.0 - std::min(in.meter.power, 1.0));
  in.meter.power = std::clamp(in.meter.power * (1.0 + rng_.normal(power_sd)), 0.02, 1.1);
  in.meter.accuracy_ms = std::clamp(rng_.normal(skill_.accuracy_sd_ms), MeterInput::kAccuracy.min, MeterInput::kAccuracy.max);
  // And aimed by eye along a read of the green, as a putt is: the same start-line spread
  // (the bot's plan reads the green perfectly; the spread stands for its misreads).
  if (partial) in.aim = std::clamp(in.aim + rng_.normal(skill_.putt_aim_sd), -1.5, 1.5);
  return in;
}

}  // namespace sweetspot
