#include "game/render/spray_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "game/render/canvas.hpp"

namespace sweetspot {
namespace {

constexpr int kSize = 800;
constexpr double kMetresPerPixel = 150.0 / 700.0;  // 150 m (492 ft) of field over 700 px

// Field metres (x toward centre field, z toward first base) to pixels: home plate at the
// bottom centre, centre field up, first base to the right.
double px(const Vec3& p) { return kSize / 2.0 + p.z() / kMetresPerPixel; }
double py(const Vec3& p) { return kSize - 50.0 - p.x() / kMetresPerPixel; }

Rgb colour(BattedOutcome o) {
  switch (o) {
    case BattedOutcome::HomeRun: return 0xD62828;
    case BattedOutcome::Triple: return 0xF77F00;
    case BattedOutcome::Double: return 0xE9C46A;
    case BattedOutcome::Single: return 0x2A9D8F;
    case BattedOutcome::Out: return 0x6C757D;
    case BattedOutcome::Error: return 0x9B5DE5;
    case BattedOutcome::Foul: return 0x8ECAE6;
    case BattedOutcome::Strike: return 0x000000;
  }
  return 0x000000;
}

}  // namespace

void write_spray_chart(const Assets& assets, const std::vector<SwingRecord>& swings, const std::filesystem::path& png) {
  // Grass, the infield dirt, the foul lines and the fence of the ballpark.
  Canvas c(kSize, kSize, 0x4F8A3C);
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
    c.marker(px(p), py(p), 6.0, 4.5, colour(s.result.outcome));
  }
  // Legend: each outcome's colour and how many balls in play had it.
  int y = kSize - 20 * 6 - 8;
  c.rect(8, y - 8, 150, kSize - 8, 0x3E6E30);
  for (const BattedOutcome o : {BattedOutcome::HomeRun, BattedOutcome::Triple, BattedOutcome::Double,
                                BattedOutcome::Single, BattedOutcome::Out, BattedOutcome::Foul}) {
    const auto n = std::count_if(swings.begin(), swings.end(),
                                 [&](const SwingRecord& s) { return s.result.contact && s.result.outcome == o; });
    c.marker(24, y + 6, 6.0, 4.5, colour(o));
    c.text(38, y, std::string(to_string(o)) + " " + std::to_string(n), 0xFFFFFF);
    y += 20;
  }
  c.write_png(png);
}

}  // namespace sweetspot
