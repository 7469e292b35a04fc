#include "game/modes/baseball/pitcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/units.hpp"

namespace sweetspot {
namespace {

bool is_fastball(const PitchType& t) { return t.type == "four-seam" || t.type == "sinker"; }
bool is_breaking(const PitchType& t) { return t.type == "slider" || t.type == "curveball"; }

constexpr double kBodyFromMiddle = 0.55;  // m, see hits_batter
constexpr double kBodyLow = 0.3, kBodyHigh = 1.8;

// His spots (Pitcher::next): in the zone, kEdgeInset inside the edges of a quarter, or its
// heart kHeartShare of the time; a chase pitch kChaseOff past the top (fastballs, side spread
// kHighSideSd) or the bottom (the rest, away by half the plate plus a half-normal kAwaySd).
constexpr double kEdgeInset = 0.1, kHeartShare = 0.2, kChaseOff = 0.08, kHighSideSd = 0.12, kAwaySd = 0.15;  // m

bool chased_high(const PitchType& t) { return is_fastball(t) || t.type == "cutter"; }

// Midpoint quantiles of |N(0, 1)|, x with erf(x / sqrt 2) = (i + 1/2) / n, by Newton's method.
constexpr int kQuantiles = 40;
const std::array<double, kQuantiles>& half_normal_quantiles() {
  static const std::array<double, kQuantiles> q = [] {
    std::array<double, kQuantiles> out{};
    for (int i = 0; i < kQuantiles; ++i) {
      const double p = (i + 0.5) / kQuantiles;
      double x = 1.0;
      for (int k = 0; k < 30; ++k) x -= (std::erf(x / std::sqrt(2.0)) - p) / (std::sqrt(2.0 / kPi) * std::exp(-0.5 * x * x));
      out[static_cast<std::size_t>(i)] = x;
    }
    return out;
  }();
  return q;
}

// The count's odds times the type's odds against his mix's (both as he means them).
double combine_odds(double intent, double type_share, double mix_share) {
  if (intent <= 0.0 || intent >= 1.0) return intent;
  const auto odds = [](double p) { return p / (1.0 - p); };
  const double o = odds(intent) * odds(type_share) / odds(mix_share);
  return o / (1.0 + o);
}

// The chance a ball aimed at `aim` (m) crosses within [lo, hi] when it misses by a normal `sd`.
double within(double aim, double lo, double hi, double sd) {
  if (sd <= 0.0) return aim >= lo && aim <= hi ? 1.0 : 0.0;
  const auto cdf = [&](double x) { return 0.5 * std::erfc(-(x - aim) / (sd * std::sqrt(2.0))); };
  return cdf(hi) - cdf(lo);
}

// How often a pitch of a type crosses the zone through his command (m per axis): meant for
// it (a corner or the heart, as Pitcher::next picks them) and meant to be chased (over the
// top, or under and away).
struct ZoneOdds {
  double meant_in = 1.0, chased_in = 0.0;
};

ZoneOdds zone_odds(const PitchType& type, double command_sd) {
  const double r = kBaseballRadius, hw = StrikeZone::kHalfWidth;
  const double lo = StrikeZone::kLow - r, hi = StrikeZone::kHigh + r;
  const auto across = [&](double aim, double sd) { return within(aim, -hw - r, hw + r, sd); };
  ZoneOdds z;
  // Meant for the zone: a corner (its four alike by symmetry) or the heart.
  const double corner = within(StrikeZone::kLow + kEdgeInset, lo, hi, command_sd) * across(hw - kEdgeInset, command_sd);
  const double heart = within(0.5 * (StrikeZone::kLow + StrikeZone::kHigh), lo, hi, command_sd) * across(0.0, command_sd);
  z.meant_in = kHeartShare * heart + (1.0 - kHeartShare) * corner;
  // Meant to be chased: over the zone with a spread of side, or under it and away.
  if (chased_high(type)) {
    z.chased_in = within(StrikeZone::kHigh + kChaseOff, lo, hi, command_sd) * across(0.0, std::hypot(kHighSideSd, command_sd));
  } else {
    // The half-normal of his "away" by a midpoint sum over its quantiles.
    double side = 0.0;
    for (const double x : half_normal_quantiles()) side += across(0.5 * hw + kAwaySd * x, command_sd) / kQuantiles;
    z.chased_in = within(StrikeZone::kLow - kChaseOff, lo, hi, command_sd) * side;
  }
  return z;
}

double meant_zone_share(const PitchType& t, double command_sd) {
  // The share he must mean for the zone so that `zone_share` of the type crosses it, his
  // command carrying some pitches meant for an edge out and some meant to be chased in.
  const ZoneOdds z = zone_odds(t, command_sd);
  if (z.meant_in - z.chased_in < 0.05) return t.zone_share;
  return std::clamp((t.zone_share - z.chased_in) / (z.meant_in - z.chased_in), 0.02, 0.98);
}

double mix_zone_share(const std::vector<PitchType>& arsenal, double command_sd) {
  double usage = 0.0, share = 0.0;
  for (const PitchType& t : arsenal) {
    usage += t.usage;
    share += t.usage * meant_zone_share(t, command_sd);
  }
  return usage > 0.0 ? share / usage : 0.5;
}

}  // namespace

bool StrikeZone::contains(const Vec3& p, double r) { return outside_by(p, r) <= 0.0; }

double StrikeZone::outside_by(const Vec3& p, double r) {
  const double side = std::abs(p.z()) - (kHalfWidth + r);
  const double height = std::max(kLow - r - p.y(), p.y() - (kHigh + r));
  return std::max({side, height, 0.0});
}

bool draws_left_handed(std::uint64_t seed, double share) { return Rng(seed).uniform() < share; }

PitcherProfile league_average_pitcher(const std::vector<PitchType>& types, bool left_handed) {
  PitcherProfile p;
  p.arsenal = types;
  p.left_handed = left_handed;
  if (left_handed) p.name = "league average, left-handed";
  return p;
}

double zone_intent(const Count& c) {
  // Behind in the count he must throw strikes; ahead he can expand the zone.
  if (c.balls == 3) return c.strikes == 0 ? 0.95 : 0.9;
  if (c.strikes == 2 && c.balls <= 1) return 0.30;
  const int lead = c.balls - c.strikes;  // > 0: the batter is ahead
  return std::clamp(0.58 + 0.08 * lead, 0.35, 0.85);
}

double type_zone_intent(double intent, const PitchType& type, const std::vector<PitchType>& arsenal, double command_sd) {
  // The fastball he throws for the zone, the changeup he throws to be chased; at 3-0 every
  // type still mostly for the zone.
  return combine_odds(intent, meant_zone_share(type, command_sd), mix_zone_share(arsenal, command_sd));
}

bool hits_batter(const Vec3& p, bool left, double r) {
  const double inside = left ? p.z() : -p.z();  // toward the batter
  const bool body = inside + r >= kBodyFromMiddle && p.y() + r >= kBodyLow && p.y() - r <= kBodyHigh;
  const bool hands = std::hypot(inside - kStanceHandsFromMiddle, p.y() - kStanceHandsHigh) <= kStanceHandsReach + r;
  return body || hands;
}

Pitcher::Pitcher(PitcherProfile profile, std::uint64_t seed) : profile_(std::move(profile)), rng_(seed) {
  for (const PitchType& t : profile_.arsenal) meant_.push_back(meant_zone_share(t, profile_.command_sd));
  meant_mix_ = mix_zone_share(profile_.arsenal, profile_.command_sd);
}

std::size_t Pitcher::choose_type(const Count& c) {
  // His mix, with more fastballs when he needs a strike and more breaking balls with two
  // strikes (ESTIMATE of the pattern in Statcast's pitch mix by count).
  const bool behind = c.balls >= 2 && c.balls > c.strikes;
  const bool putaway = c.strikes == 2;
  std::vector<double> w;
  double total = 0.0;
  for (const PitchType& t : profile_.arsenal) {
    double u = t.usage;
    if (behind && is_fastball(t)) u *= 1.8;
    if (putaway && is_breaking(t)) u *= 1.5;
    w.push_back(u);
    total += u;
  }
  double x = rng_.uniform() * total;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (x < w[i]) return i;
    x -= w[i];
  }
  return profile_.arsenal.size() - 1;
}

PlannedPitch Pitcher::next(const Count& count, bool batter_left) {
  ++thrown_;
  PlannedPitch out;
  const std::size_t k = choose_type(count);
  const PitchType& type = profile_.arsenal[k];
  out.call.type = type;
  out.call.left_handed = profile_.left_handed;
  out.call.type.speed = std::clamp(type.speed + rng_.normal(profile_.speed_sd), PitchType::kSpeed.min, PitchType::kSpeed.max);
  out.call.type.spin = std::clamp(type.spin + rpm_to_radps(rng_.normal(profile_.spin_rpm_sd)), PitchType::kSpin.min, PitchType::kSpin.max);
  // Sides seen from the catcher, + toward first base; "away" from a right-handed batter is +.
  const double away = batter_left ? -1.0 : 1.0;
  const double mid = 0.5 * (StrikeZone::kLow + StrikeZone::kHigh);
  out.in_zone_intent = rng_.uniform() < combine_odds(zone_intent(count), meant_[k], meant_mix_);
  if (out.in_zone_intent) {
    // A spot in the zone, nearer its edges than its middle: 0.1 m inside an edge of a
    // quarter he picks, or the heart of the zone one time in five (one in two with three
    // balls, when a walk costs more than a hit might).
    const bool heart = rng_.uniform() < (count.balls == 3 ? 0.5 : kHeartShare);
    const double s = heart ? 0.0 : (rng_.uniform() < 0.5 ? -1.0 : 1.0) * (StrikeZone::kHalfWidth - kEdgeInset);
    const double h = heart ? mid : (rng_.uniform() < 0.5 ? StrikeZone::kLow + kEdgeInset : StrikeZone::kHigh - kEdgeInset);
    out.aim_side = s;
    out.aim_height = h;
  } else {
    // A chase: breaking balls and changeups down (and away), fastballs up, just off the edge.
    if (chased_high(type)) {
      out.aim_height = StrikeZone::kHigh + kChaseOff;
      out.aim_side = rng_.normal(kHighSideSd);
    } else {
      out.aim_height = StrikeZone::kLow - kChaseOff;
      out.aim_side = away * (StrikeZone::kHalfWidth * 0.5 + std::abs(rng_.normal(kAwaySd)));
    }
  }
  out.call.target_height = out.aim_height + rng_.normal(profile_.command_sd);
  out.call.target_side = out.aim_side + rng_.normal(profile_.command_sd);
  // The ball cannot be aimed into the ground before the plate or over the backstop.
  out.call.target_height = std::clamp(out.call.target_height, 0.05, 2.4);
  return out;
}

}  // namespace sweetspot
