#include "game/modes/baseball/aim.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

#include "game/content/assets.hpp"
#include "physics/delivery.hpp"

namespace sweetspot {
namespace {

// The exit speed along the bat, sampled every kStep from the end cap's reach past the tip
// (kEndCapReach) in to where the hands are hit (kHandsFromTip); linear between.
constexpr double kStep = 0.005;  // m
// The scatter is integrated on a grid of ±kSpan standard deviations, kNodes to a side: the
// normal's weight beyond 4 sd (6e-5) cannot move the argmax by a step of the aim.
constexpr double kSpan = 4.0;
constexpr int kNodes = 41;
// The aims tried, from the sweet spot in toward the hands.
constexpr double kAimStep = 0.0025, kAimMax = 0.2;  // m

struct ExitSpeedProfile {
  double first = 0.0;          // m from the tip of the first sample (past the tip: negative)
  std::vector<double> speed;   // m/s every kStep from `first`

  double at(double from_tip) const {
    const double u = std::clamp((from_tip - first) / kStep, 0.0, static_cast<double>(speed.size() - 1));
    const std::size_t i = std::min(static_cast<std::size_t>(u), speed.size() - 2);
    const double f = u - static_cast<double>(i);
    return (1.0 - f) * speed[i] + f * speed[i + 1];
  }
};

ExitSpeedProfile exit_speed_profile(const BallSpec& ball, const BatSpec& bat, double bat_speed) {
  ExitSpeedProfile p;
  p.first = -kEndCapReach * ball.radius;
  BatSwing s;
  s.bat_speed = bat_speed;
  s.attack_angle = 0.0;
  s.undercut = 0.0;
  const Pitch pitch;  // 90 mph at the plate with ~2300 rpm of backspin: a fastball
  const int samples = static_cast<int>(std::floor((kHandsFromTip - p.first) / kStep + 1e-9)) + 1;
  for (int k = 0; k < samples; ++k) {
    s.impact_from_tip = p.first + k * kStep;
    p.speed.push_back(deliver_baseball(ball, bat, s, pitch, bat.material).launch.velocity.norm());
  }
  return p;
}

double best_aim(const BallSpec& ball, const BatSpec& bat, const BatterSkill& skill) {
  const ExitSpeedProfile profile = exit_speed_profile(ball, bat, skill.bat_speed);
  const double sweet_arm = bat.length - bat.sweet_spot_from_tip - bat.pivot_from_knob;
  const double reach_sd = std::hypot(skill.read_reach_sd, skill.eye_sd);
  // The bat turns at its sweet spot's speed over the arm (swing_at): his timing error as an
  // angle from square.
  const double turn_sd = skill.bat_speed / sweet_arm * 1e-3 * skill.read_timing_sd_ms;
  std::vector<double> z(kNodes), w(kNodes);
  for (int i = 0; i < kNodes; ++i) {
    z[static_cast<std::size_t>(i)] = -kSpan + 2.0 * kSpan * i / (kNodes - 1);
    w[static_cast<std::size_t>(i)] = std::exp(-0.5 * z[static_cast<std::size_t>(i)] * z[static_cast<std::size_t>(i)]);
  }
  double best_aim = 0.0, best = -1.0;
  const int aims = static_cast<int>(std::lround(kAimMax / kAimStep));
  for (int a = 0; a <= aims; ++a) {
    const double aim = a * kAimStep;
    double sum = 0.0, weight = 0.0;
    for (int i = 0; i < kNodes; ++i) {
      const double turned = turn_sd * z[static_cast<std::size_t>(i)];
      const double cos_turned = std::cos(turned);
      for (int j = 0; j < kNodes; ++j) {
        const double wij = w[static_cast<std::size_t>(i)] * w[static_cast<std::size_t>(j)];
        weight += wij;
        if (std::abs(turned) >= 0.5 * kPi) continue;  // through the zone: no crossing on the bat
        const double from_pivot = (sweet_arm - aim + reach_sd * z[static_cast<std::size_t>(j)]) / cos_turned;
        const double from_tip = bat.length - bat.pivot_from_knob - from_pivot;
        if (from_tip < profile.first) continue;  // past the end: a miss
        sum += wij * profile.at(std::min(from_tip, kHandsFromTip));
      }
    }
    if (sum / weight > best) {
      best = sum / weight;
      best_aim = aim;
    }
  }
  return best_aim;
}

}  // namespace

double aim_inside(const Assets& assets, const BatterSkill& skill, const std::string& bat_name) {
  const EquipmentCatalog& eq = assets.equipment();
  // Each game makes its lineups afresh; the aim is a pure function of the (immutable, loaded
  // once) equipment and these numbers of the skill: found once per process.
  using Key = std::tuple<const EquipmentCatalog*, std::string, double, double, double, double>;
  static std::mutex mutex;
  static std::map<Key, double> found;
  const Key key{&eq, bat_name, skill.bat_speed, skill.read_reach_sd, skill.eye_sd, skill.read_timing_sd_ms};
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = found.find(key); it != found.end()) return it->second;
  }
  const double aim = best_aim(eq.ball("mlb"), eq.bat(bat_name), skill);
  const std::lock_guard<std::mutex> lock(mutex);
  return found.emplace(key, aim).first->second;
}

}  // namespace sweetspot
