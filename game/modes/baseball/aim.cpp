#include "game/modes/baseball/aim.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

#include "game/content/assets.hpp"
#include "physics/delivery.hpp"

namespace sweetspot {
namespace {

// The exit speed along the bat, sampled every kProfileStep from the end cap's rim past the tip
// in to where the hands are hit; linear between.
constexpr double kProfileStep = 0.005;  // m
// The scatter is integrated on grids of ±kSpan standard deviations: the normal's weight beyond
// 4 sd (6e-5) cannot move the argmax by a step of the aim. The reach grid is fine enough
// (4.7 mm at the pro's 9.5 cm) that the mean moves smoothly with the aim's 2.5 mm steps.
constexpr double kSpan = 4.0;
constexpr int kTurnNodes = 41, kReachNodes = 161;
// The aims tried, from the sweet spot in toward the hands.
constexpr double kAimStep = 0.0025, kAimMax = 0.2;  // m

struct ExitSpeedProfile {
  double first_from_tip = 0.0;  // m from the tip of the first sample (past the tip: negative)
  double last_from_tip = 0.0;   // m from the tip of the last, nearest the hands
  std::vector<double> speed;    // m/s every kProfileStep from `first_from_tip`

  double at(double from_tip) const {
    assert(speed.size() >= 2);
    const double u = std::clamp((from_tip - first_from_tip) / kProfileStep, 0.0, static_cast<double>(speed.size() - 1));
    const std::size_t i = std::min(static_cast<std::size_t>(u), speed.size() - 2);
    const double f = u - static_cast<double>(i);
    return (1.0 - f) * speed[i] + f * speed[i + 1];
  }
};

ExitSpeedProfile exit_speed_profile(const BallSpec& ball, const BatSpec& bat, double bat_speed) {
  const Range on_bat = bat_contact_range(bat, ball);
  ExitSpeedProfile p;
  p.first_from_tip = on_bat.min;
  const int samples = std::max(2, static_cast<int>(std::floor((std::min(kHandsFromTip, on_bat.max) - on_bat.min) / kProfileStep)) + 1);
  BatSwing s;
  s.bat_speed = bat_speed;
  s.attack_angle = 0.0;
  s.undercut = 0.0;
  const Pitch pitch;  // 90 mph at the plate with ~2300 rpm of backspin: a fastball
  for (int k = 0; k < samples; ++k) {
    s.impact_from_tip = std::min(on_bat.min + k * kProfileStep, on_bat.max);
    p.speed.push_back(deliver_baseball(ball, bat, s, pitch, bat.material).launch.velocity.norm());
  }
  p.last_from_tip = s.impact_from_tip;
  return p;
}

// The grid's standard-normal values and their (unnormalised) weights.
struct NormalNodes {
  std::vector<double> z, w;
  explicit NormalNodes(int n) {
    for (int i = 0; i < n; ++i) {
      z.push_back(-kSpan + 2.0 * kSpan * i / (n - 1));
      w.push_back(std::exp(-0.5 * z.back() * z.back()));
    }
  }
};

double best_aim_inside(const BallSpec& ball, const BatSpec& bat, const BatterSkill& skill) {
  const ExitSpeedProfile profile = exit_speed_profile(ball, bat, skill.bat_speed);
  const double reach_sd = reach_scatter(skill);
  const double turn_sd = bat_turn(skill.bat_speed, bat, skill.read_timing_sd_ms);
  const NormalNodes turn(kTurnNodes), reach(kReachNodes);
  double weight = 0.0;  // the same for every aim: each node's, misses included
  for (const double a : turn.w)
    for (const double b : reach.w) weight += a * b;
  double chosen = 0.0, best = -1.0;
  const int aims = static_cast<int>(std::lround(kAimMax / kAimStep));
  for (int k = 0; k <= aims; ++k) {
    const double aim = k * kAimStep;
    double sum = 0.0;
    for (std::size_t i = 0; i < turn.z.size(); ++i) {
      const double turned = turn_sd * turn.z[i];
      // Turned past a right angle the bat is through the zone: no crossing, a miss.
      if (std::abs(turned) >= 0.5 * kPi) continue;
      const double cos_turned = std::cos(turned);
      for (std::size_t j = 0; j < reach.z.size(); ++j) {
        const double from_pivot = (bat.sweet_arm() - aim + reach_sd * reach.z[j]) / cos_turned;
        const double from_tip = bat.pivot_to_tip() - from_pivot;
        if (from_tip < profile.first_from_tip) continue;  // past the end of the bat: a miss
        sum += turn.w[i] * reach.w[j] * profile.at(std::min(from_tip, profile.last_from_tip));
      }
    }
    if (sum / weight > best) {
      best = sum / weight;
      chosen = aim;
    }
  }
  return chosen;
}

// What the aim depends on: the catalog and, in case another is later loaded at the same
// address, the ball's and bat's main values; the skill's speed and scatter.
using AimKey = std::tuple<const EquipmentCatalog*, std::string, double, double, double, double, double, double, double,
                          double, double, double, double>;

AimKey aim_key(const EquipmentCatalog& eq, const BallSpec& ball, const BatSpec& bat, const BatterSkill& skill) {
  return {&eq,           bat.name,            bat.length,           bat.mass,
          bat.cg_from_knob, bat.inertia_cg,   bat.pivot_from_knob,  bat.sweet_spot_from_tip,
          ball.mass,     ball.radius,         skill.bat_speed,      reach_scatter(skill),
          skill.read_timing_sd_ms};
}

}  // namespace

double aim_inside(const Assets& assets, const BatterSkill& skill, const std::string& bat_name) {
  const EquipmentCatalog& eq = assets.equipment();
  const BallSpec& ball = eq.ball("mlb");
  const BatSpec& bat = eq.bat(bat_name);
  // Every game makes its lineups afresh: the aim is found once per process for each key.
  static std::mutex mutex;
  static std::map<AimKey, double> found;
  const AimKey key = aim_key(eq, ball, bat, skill);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = found.find(key); it != found.end()) return it->second;
  }
  const double aim = best_aim_inside(ball, bat, skill);
  const std::lock_guard<std::mutex> lock(mutex);
  return found.emplace(key, aim).first->second;
}

}  // namespace sweetspot
