// Dynamic resolution (game/app/resolution_scaler.hpp): frames over budget lower the 3D view's
// share of the window's pixels, frames well under it raise it again, within 0.5..1.
#include <catch2/catch.hpp>

#include "game/app/resolution_scaler.hpp"

using namespace sweetspot;

TEST_CASE("frames over budget lower the resolution, fast ones bring it back", "[resolution]") {
  ResolutionScaler s(18.0);
  CHECK(s.scale() == 1.0);
  // A fill-bound frame: cost = 6 ms + 24 ms x share² (the batting cage on llvmpipe).
  const auto cost = [](double share) { return 6.0 + 24.0 * share * share; };
  for (int i = 0; i < 200; ++i) s.frame(cost(s.scale()));
  CHECK(cost(s.scale()) <= 18.0);
  CHECK(s.scale() >= 0.6);  // no lower than it needs: 0.71 meets the budget
  const double settled = s.scale();
  for (int i = 0; i < 200; ++i) s.frame(cost(s.scale()));
  CHECK(s.scale() == settled);  // it stays put rather than hunting
  for (int i = 0; i < 200; ++i) s.frame(5.0);
  CHECK(s.scale() == 1.0);
  // A frame it cannot help never drives it below half.
  for (int i = 0; i < 200; ++i) s.frame(100.0);
  CHECK(s.scale() == 0.5);
  // Steps of 5 %: few framebuffer resizes.
  CHECK(std::abs(s.scale() * 20.0 - std::round(s.scale() * 20.0)) < 1e-9);
}
