#include "game/modes/baseball/pitcher.hpp"

#include <algorithm>
#include <cmath>

#include "physics/units.hpp"

namespace sweetspot {
namespace {

bool is_fastball(const PitchType& t) { return t.type == "four-seam" || t.type == "sinker"; }
bool is_breaking(const PitchType& t) { return t.type == "slider" || t.type == "curveball"; }

constexpr double kBodyFromMiddle = 0.55;  // m, see hits_batter
constexpr double kBodyLow = 0.3, kBodyHigh = 1.8;

}  // namespace

bool StrikeZone::contains(const Vec3& p, double r) { return outside_by(p, r) <= 0.0; }

double StrikeZone::outside_by(const Vec3& p, double r) {
  const double side = std::abs(p.z()) - (kHalfWidth + r);
  const double height = std::max(kLow - r - p.y(), p.y() - (kHigh + r));
  return std::max({side, height, 0.0});
}

PitcherProfile league_average_pitcher(const std::vector<PitchType>& types) {
  PitcherProfile p;
  p.arsenal = types;
  return p;
}

double zone_intent(const Count& c) {
  // Behind in the count he must throw strikes; ahead he can expand the zone.
  if (c.balls == 3) return c.strikes == 0 ? 0.95 : 0.9;
  if (c.strikes == 2 && c.balls <= 1) return 0.30;
  const int lead = c.balls - c.strikes;  // > 0: the batter is ahead
  return std::clamp(0.58 + 0.08 * lead, 0.35, 0.85);
}

double type_zone_intent(double intent, const PitchType& type, const std::vector<PitchType>& arsenal) {
  double usage = 0.0, share = 0.0;
  for (const PitchType& t : arsenal) {
    usage += t.usage;
    share += t.usage * t.zone_share;
  }
  if (usage <= 0.0 || intent <= 0.0 || intent >= 1.0) return intent;
  share /= usage;
  // The count's odds times the type's odds against his mix's: the fastball he throws for the
  // zone, the changeup he throws to be chased; at 3-0 every type still mostly for the zone.
  const auto odds = [](double p) { return p / (1.0 - p); };
  const double o = odds(intent) * odds(type.zone_share) / odds(share);
  return o / (1.0 + o);
}

bool hits_batter(const Vec3& p, bool left, double r) {
  const double inside = left ? p.z() : -p.z();  // toward the batter
  const bool body = inside + r >= kBodyFromMiddle && p.y() + r >= kBodyLow && p.y() - r <= kBodyHigh;
  const bool hands = std::hypot(inside - kStanceHandsFromMiddle, p.y() - kStanceHandsHigh) <= kStanceHandsReach + r;
  return body || hands;
}

Pitcher::Pitcher(PitcherProfile profile, std::uint64_t seed) : profile_(std::move(profile)), rng_(seed) {}

const PitchType& Pitcher::choose_type(const Count& c) {
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
    if (x < w[i]) return profile_.arsenal[i];
    x -= w[i];
  }
  return profile_.arsenal.back();
}

PlannedPitch Pitcher::next(const Count& count, bool batter_left) {
  ++thrown_;
  PlannedPitch out;
  const PitchType& type = choose_type(count);
  out.call.type = type;
  out.call.left_handed = profile_.left_handed;
  out.call.type.speed = std::clamp(type.speed + rng_.normal(profile_.speed_sd), PitchType::kSpeed.min, PitchType::kSpeed.max);
  out.call.type.spin = std::clamp(type.spin + rpm_to_radps(rng_.normal(profile_.spin_rpm_sd)), PitchType::kSpin.min, PitchType::kSpin.max);
  // Sides seen from the catcher, + toward first base; "away" from a right-handed batter is +.
  const double away = batter_left ? -1.0 : 1.0;
  const double mid = 0.5 * (StrikeZone::kLow + StrikeZone::kHigh);
  out.in_zone_intent = rng_.uniform() < type_zone_intent(zone_intent(count), type, profile_.arsenal);
  if (out.in_zone_intent) {
    // A spot in the zone, nearer its edges than its middle: 0.1 m inside an edge of a
    // quarter he picks, or the heart of the zone one time in five (one in two with three
    // balls, when a walk costs more than a hit might).
    const bool heart = rng_.uniform() < (count.balls == 3 ? 0.5 : 0.2);
    const double s = heart ? 0.0 : (rng_.uniform() < 0.5 ? -1.0 : 1.0) * (StrikeZone::kHalfWidth - 0.1);
    const double h = heart ? mid : (rng_.uniform() < 0.5 ? StrikeZone::kLow + 0.1 : StrikeZone::kHigh - 0.1);
    out.aim_side = s;
    out.aim_height = h;
  } else {
    // A chase: breaking balls and changeups down (and away), fastballs up, just off the edge.
    const double off = 0.08;
    if (is_fastball(type) || type.type == "cutter") {
      out.aim_height = StrikeZone::kHigh + off;
      out.aim_side = rng_.normal(0.12);
    } else {
      out.aim_height = StrikeZone::kLow - off;
      out.aim_side = away * (StrikeZone::kHalfWidth * 0.5 + std::abs(rng_.normal(0.15)));
    }
  }
  out.call.target_height = out.aim_height + rng_.normal(profile_.command_sd);
  out.call.target_side = out.aim_side + rng_.normal(profile_.command_sd);
  // The ball cannot be aimed into the ground before the plate or over the backstop.
  out.call.target_height = std::clamp(out.call.target_height, 0.05, 2.4);
  return out;
}

}  // namespace sweetspot
