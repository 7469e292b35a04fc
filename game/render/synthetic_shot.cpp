#include "game/render/synthetic_shot.hpp"

#include <cmath>

namespace sweetspot {

ShotTrajectory synthetic_shot(const SyntheticShotSpec& spec) {
  ShotTrajectory out;
  const double y0 = spec.ground_y + spec.ball_radius;
  // Flight: x linear in time, y a parabola through (0, y0) -> apex -> (carry, y0) with the
  // apex at 55 % of the carry (a driver's arc peaks past half way), z quadratic.
  const double flight_time = 6.5;
  const int n = 260;
  auto arc = [&](double u) {
    const double peak = 0.55;
    const double h = u <= peak ? 1.0 - std::pow((peak - u) / peak, 2) : 1.0 - std::pow((u - peak) / (1 - peak), 2);
    return Vec3(spec.carry * u, y0 + spec.apex * h, spec.lateral * u * u);
  };
  for (int i = 0; i <= n; ++i) {
    const double u = double(i) / n;
    TrajectorySample s;
    s.t = flight_time * u;
    s.position = arc(u);
    s.phase = Phase::Flight;
    out.samples.push_back(s);
  }
  // Two bounces (each a small parabola, 3/8 then 1/4 of the previous length), then a roll.
  double x = spec.carry, t = flight_time;
  const Vec3 land = arc(1.0);
  const double dir_z = 2 * spec.lateral / spec.carry;  // dz/dx at landing
  const double lengths[2] = {12.0, 4.5}, heights[2] = {1.6, 0.4}, times[2] = {1.1, 0.55};
  for (int b = 0; b < 2; ++b) {
    for (int i = 1; i <= 30; ++i) {
      const double u = i / 30.0;
      TrajectorySample s;
      s.t = t + times[b] * u;
      const double xx = x + lengths[b] * u;
      s.position = Vec3(xx, y0 + heights[b] * 4 * u * (1 - u), land.z() + dir_z * (xx - spec.carry));
      s.phase = Phase::Bounce;
      out.samples.push_back(s);
    }
    x += lengths[b];
    t += times[b];
  }
  const double roll = 14.0, roll_time = 3.0;
  for (int i = 1; i <= 30; ++i) {
    const double u = i / 30.0;
    const double xx = x + roll * (1 - (1 - u) * (1 - u));
    TrajectorySample s;
    s.t = t + roll_time * u;
    s.position = Vec3(xx, y0, land.z() + dir_z * (xx - spec.carry));
    s.phase = i == 30 ? Phase::Rest : Phase::Roll;
    out.samples.push_back(s);
  }
  // Velocities by finite differences (the follow camera looks along them).
  auto& v = out.samples;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 < v.size() ? i + 1 : i;
    const double dt = v[b].t - v[a].t;
    v[i].velocity = dt > 0 ? Vec3((v[b].position - v[a].position) / dt) : Vec3::Zero();
  }
  v.back().velocity = Vec3::Zero();
  auto& s = out.summary;
  s.landing_position = land;
  s.rest_position = v.back().position;
  s.carry_m = std::hypot(land.x(), land.z());
  s.total_m = std::hypot(s.rest_position.x(), s.rest_position.z());
  s.apex_m = spec.apex;
  s.hang_time_s = flight_time;
  s.lateral_m = land.z();
  s.total_time_s = v.back().t;
  s.bounces = 2;
  s.landing_angle_deg = rad_to_deg(std::atan2(2 * spec.apex / (1 - 0.55), spec.carry));
  s.end = EndReason::Rest;
  return out;
}

}  // namespace sweetspot
