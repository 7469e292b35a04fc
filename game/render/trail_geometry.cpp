#include "game/render/trail_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace sweetspot {

Eigen::Vector3f phase_color(Phase phase) {
  switch (phase) {
    case Phase::Flight: return {1.00f, 0.86f, 0.10f};
    case Phase::Bounce: return {1.00f, 0.42f, 0.05f};
    case Phase::Roll:
    case Phase::Rest: return {0.95f, 0.22f, 0.88f};
  }
  return {1.0f, 1.0f, 1.0f};
}

void append_trail(MeshData& out, const ShotTrajectory& trajectory, double t, const Camera& camera,
                  const TrailStyle& style) {
  const auto& s = trajectory.samples;
  if (s.size() < 2) return;
  std::size_t last = 0;
  const TrajectorySample end = sample_at(trajectory, t, &last);
  // Points up to t: samples 0..last, then the interpolated point at t.
  auto point = [&](std::size_t i) { return i <= last ? s[i].position : end.position; };
  const std::size_t n = last + 2 <= s.size() ? last + 2 : s.size();
  const Vec3 side_fallback = camera.right();
  auto offset = [&](std::size_t i, double width_px) {
    const Vec3 p = point(i);
    const Vec3 a = point(i > 0 ? i - 1 : 0);
    const Vec3 b = point(i + 1 < n ? i + 1 : n - 1);
    Vec3 side = (b - a).cross(p - camera.eye);
    side = side.norm() > 1e-12 ? side.normalized() : side_fallback;
    return Vec3(side * (0.5 * width_px * camera.metres_per_pixel(p, style.image_height)));
  };
  // Time along the drawn trail, for the halo's fade from the ball back to the launch.
  const double t0 = s.front().t, span = std::max(end.t - t0, 1e-9);
  auto ribbon = [&](double width_px, bool glow) {
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const Vec3 p0 = point(i), p1 = point(i + 1);
      if ((p1 - p0).squaredNorm() < 1e-14) continue;
      const Phase ph = s[std::min(i + 1, s.size() - 1)].phase;
      if (ph == Phase::Rest) continue;
      const Eigen::Vector3f c = phase_color(ph);
      const Vec3 o0 = offset(i, width_px), o1 = offset(i + 1, width_px);
      const double age0 = (std::min(s[i].t, end.t) - t0) / span;
      const double age1 = (i + 1 <= last ? s[i + 1].t - t0 : span) / span;
      // The halo keeps 40 % at the launch so the whole flight glows in a still image.
      auto fade = [&](double age) { return static_cast<float>(style.glow_opacity * (0.4 + 0.6 * std::min(age, 1.0))); };
      const float opacity[2] = {fade(age0), fade(age1)};
      const auto base = static_cast<std::uint32_t>(out.vertices.size());
      const Vec3 corners[4] = {p0 - o0, p0 + o0, p1 + o1, p1 - o1};
      const float across[4] = {-1.0f, 1.0f, 1.0f, -1.0f};
      for (int k = 0; k < 4; ++k) {
        Vertex v;
        v.position = corners[k].cast<float>();
        // Core: a feathered ribbon (normal.x = 1). Halo: normal.x = 2, opacity in normal.y.
        v.normal = glow ? Eigen::Vector3f(2.0f, opacity[k < 2 ? 0 : 1], 0.0f) : Eigen::Vector3f::UnitX();
        v.color = c;
        v.pattern = across[k];
        out.vertices.push_back(v);
      }
      for (std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) out.indices.push_back(base + k);
    }
  };
  if (style.glow_px > 0.0) ribbon(style.glow_px, true);
  ribbon(style.width_px + 1.0, false);
}

}  // namespace sweetspot
