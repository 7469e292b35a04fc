#include "game/render/spray_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "game/render/image.hpp"

namespace sweetspot {
namespace {

constexpr int kSize = 800;
constexpr double kMetresPerPixel = 150.0 / 700.0;  // 150 m (492 ft) of field over 700 px

struct Canvas {
  std::vector<std::uint8_t> rgba = std::vector<std::uint8_t>(static_cast<std::size_t>(kSize) * kSize * 4, 255);
  void put(int x, int y, std::uint32_t c) {
    if (x < 0 || y < 0 || x >= kSize || y >= kSize) return;
    std::uint8_t* p = rgba.data() + (static_cast<std::size_t>(y) * kSize + x) * 4;
    p[0] = static_cast<std::uint8_t>(c >> 16);
    p[1] = static_cast<std::uint8_t>(c >> 8);
    p[2] = static_cast<std::uint8_t>(c);
    p[3] = 255;
  }
  void disc(double cx, double cy, double r, std::uint32_t c) {
    for (int y = static_cast<int>(cy - r); y <= static_cast<int>(cy + r); ++y)
      for (int x = static_cast<int>(cx - r); x <= static_cast<int>(cx + r); ++x)
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) put(x, y, c);
  }
  void line(double x0, double y0, double x1, double y1, std::uint32_t c, double w = 1.5) {
    const int n = static_cast<int>(std::hypot(x1 - x0, y1 - y0)) + 1;
    for (int i = 0; i <= n; ++i) disc(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * i / n, w, c);
  }
};

// Field metres (x toward centre field, z toward first base) to pixels: home plate at the
// bottom centre, centre field up, first base to the right.
double px(const Vec3& p) { return kSize / 2.0 + p.z() / kMetresPerPixel; }
double py(const Vec3& p) { return kSize - 50.0 - p.x() / kMetresPerPixel; }

std::uint32_t colour(BattedOutcome o) {
  switch (o) {
    case BattedOutcome::HomeRun: return 0xD62828;
    case BattedOutcome::Triple: return 0xF77F00;
    case BattedOutcome::Double: return 0xE9C46A;
    case BattedOutcome::Single: return 0x2A9D8F;
    case BattedOutcome::Out: return 0x6C757D;
    case BattedOutcome::Foul: return 0x8ECAE6;
    case BattedOutcome::Strike: return 0x000000;
  }
  return 0x000000;
}

}  // namespace

void write_spray_chart(const Assets& assets, const std::vector<SwingRecord>& swings, const std::filesystem::path& png) {
  Canvas c;
  // Grass, the infield dirt, the foul lines and the fence of the ballpark.
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) c.put(x, y, 0x4F8A3C);
  const Vec3 home = Vec3::Zero();
  c.disc(px(Vec3(18.44, 0, 0)), py(Vec3(18.44, 0, 0)), 29.0 / kMetresPerPixel, 0x9C6B46);
  const double far = 140.0;
  c.line(px(home), py(home), px(Vec3(far, 0, far)), py(Vec3(far, 0, far)), 0xF5F5F5);
  c.line(px(home), py(home), px(Vec3(far, 0, -far)), py(Vec3(far, 0, -far)), 0xF5F5F5);
  if (const WorldAsset* w = assets.world("ballpark")) {
    const auto& f = w->fence_line;
    for (std::size_t i = 1; i < f.size(); ++i) c.line(px(f[i - 1]), py(f[i - 1]), px(f[i]), py(f[i]), 0x1D3557, 2.5);
  }
  for (const SwingRecord& s : swings) {
    if (!s.result.contact) continue;
    const FlightSummary& f = s.result.shot.trajectory.summary;
    const bool air = s.result.outcome == BattedOutcome::HomeRun || f.carry_m > 40.0;
    const Vec3 p = air ? f.landing_position : f.rest_position;
    c.disc(px(p), py(p), 6.0, 0x000000);
    c.disc(px(p), py(p), 4.5, colour(s.result.outcome));
  }
  write_png_atomic(png, kSize, kSize, c.rgba);
}

}  // namespace sweetspot
