#include "physics/sand_splash.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sweetspot {

double club_speed_after_sand(double speed, double head_mass, double cut_width, double entry, double density,
                             double depth) {
  // The sand swept up: the channel's cross-section times its length; its momentum comes from
  // the head (perfectly plastic: the sand leaves at the head's speed, its energy spent).
  const double swept = density * std::max(cut_width, 0.0) * std::max(depth, 0.0) * std::max(entry, 0.0);
  return speed * head_mass / (head_mass + swept);
}

double sand_cushion(double entry, double ball_radius, double depth) {
  const double d = std::max(depth, 0.0);
  return d * std::max(entry, 0.0) / (d + std::max(ball_radius, 0.0));
}

double hertz_flattening(double mass, double stiffness, double normal_speed) {
  if (!(stiffness > 0.0) || !(mass > 0.0)) return 0.0;
  return std::pow(5.0 * mass * normal_speed * normal_speed / (4.0 * stiffness), 0.4);
}

double cushion_share(double cushion, double flattening) {
  if (!(cushion > 0.0)) return 0.0;
  if (!(flattening > 0.0)) return 1.0;
  return std::min(1.0, cushion / flattening);
}

CorCurve mix_restitution(const CorCurve& face, const CorCurve& sand, double share) {
  if (share <= 0.0) return face;
  if (share >= 1.0) return sand;
  // The speeds of both curves (a one-point curve is flat: its point counts at 0).
  std::vector<double> at;
  for (const CorCurve* c : {&face, &sand})
    for (int i = 0; i < c->count; ++i) at.push_back(c->count == 1 ? 0.0 : c->speed[static_cast<std::size_t>(i)]);
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  if (at.size() > static_cast<std::size_t>(CorCurve::kMaxPoints)) {
    at.clear();
    for (int i = 0; i < face.count; ++i) at.push_back(face.count == 1 ? 0.0 : face.speed[static_cast<std::size_t>(i)]);
  }
  CorCurve mixed;
  mixed.count = static_cast<int>(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) {
    mixed.speed[i] = at[i];
    mixed.cor[i] = (1.0 - share) * face.at(at[i]) + share * sand.at(at[i]);
  }
  return mixed;
}

}  // namespace sweetspot
