// CPU charts: text lands where it is asked and nowhere else; the sweep plot draws the grid,
// and the grip boundary exactly when µ_grip lies inside the µ range.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>

#include <unistd.h>

#include "game/content/scenario.hpp"
#include "game/render/canvas.hpp"
#include "game/render/image.hpp"
#include "game/render/sweep_plot.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

TEST_CASE("canvas text draws ink inside its box only", "[charts]") {
  Canvas c(200, 40, 0xFFFFFF);
  const int w = c.text(10, 10, "mu_grip 0.21", 0x000000);
  CHECK(w == Canvas::text_width("mu_grip 0.21"));
  CHECK(w > 50);
  const auto path = std::filesystem::temp_directory_path() / ("sweetspot_text_" + std::to_string(::getpid()) + ".png");
  c.write_png(path);
  int width = 0, height = 0;
  const auto px = read_png_rgba(path, &width, &height);
  std::filesystem::remove(path);
  int ink = 0, outside = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool dark = px[static_cast<std::size_t>((y * width + x) * 4)] < 128;
      const bool in_box = x >= 10 && x < 10 + w && y >= 10 && y < 10 + Canvas::text_height();
      ink += dark && in_box;
      outside += dark && !in_box;
    }
  CHECK(ink > 40);
  CHECK(outside == 0);
}

namespace {
/// Pure white pixels inside the first heatmap's plot area (the grip line is the only white there).
int white_in_first_heatmap(const std::vector<SweepPoint>& pts, const SweepOptions& o) {
  const auto path = std::filesystem::temp_directory_path() / ("sweetspot_sweep_" + std::to_string(::getpid()) + ".png");
  DisplayUnits u;
  write_sweep_plot(pts, o, u, "test", path);
  int w = 0, h = 0;
  const auto px = read_png_rgba(path, &w, &h);
  std::filesystem::remove(path);
  REQUIRE(w == 1200);
  REQUIRE(h == 940);
  int white = 0;
  for (int y = 82; y < 438; ++y)
    for (int x = 82; x < 498; ++x) {
      const auto* p = &px[static_cast<std::size_t>((y * w + x) * 4)];
      white += p[0] == 255 && p[1] == 255 && p[2] == 255;
    }
  return white;
}
}  // namespace

TEST_CASE("the sweep plot draws the grip boundary where mu_grip is inside the mu range", "[charts][grip]") {
  const Scenario s = load_scenario(test::assets(), "golf/7-iron", {"world.name=none", "impact.model=rigid"});
  SweepOptions o;
  o.e = GridAxis{0.7, 0.85, 4};
  o.mu = GridAxis{0.0, 0.3, 7};
  o.threads = 1;
  CHECK(white_in_first_heatmap(run_sweep(s, o), o) > 50);
  o.mu = GridAxis{0.5, 1.0, 3};  // all above the rigid 7-iron's threshold (~0.1): no line
  CHECK(white_in_first_heatmap(run_sweep(s, o), o) == 0);
}
