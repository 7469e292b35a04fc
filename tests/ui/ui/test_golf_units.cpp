// The golf HUD's distances in player words.
#include <catch2/catch.hpp>

#include "game/ui/golf_draw.hpp"

using namespace sweetspot;

TEST_CASE("a ball a few inches from the cup reads in inches, never 0 ft", "[ui][golf]") {
  const GolfUnits feet{true}, metres{false};
  CHECK(feet.putt(0.10) == "4 in");
  CHECK(feet.putt(0.001) == "1 in");  // not holed: at least an inch
  CHECK(feet.putt(0.30) == "1 ft");
  CHECK(feet.putt(2.44) == "8 ft");
  CHECK(metres.putt(0.10) == "10 cm");
  CHECK(metres.putt(0.001) == "1 cm");
  CHECK(metres.putt(2.44) == "2.4 m");
}
