// Ranges: inclusion at both ends, open ends, NaN, the unit round-off slack, the message.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "physics/error.hpp"
#include "physics/range.hpp"
#include "physics/units.hpp"

using namespace sweetspot;

TEST_CASE("a range holds its closed ends, not its open ones, never NaN", "[range]") {
  constexpr Range closed{0.0, 1.0};
  constexpr Range open_low{0.0, 90.0, true};
  CHECK(closed.contains(0.0));
  CHECK(closed.contains(1.0));
  CHECK_FALSE(closed.contains(1.0 + 1e-9));
  CHECK_FALSE(closed.contains(-1e-9));
  CHECK_FALSE(open_low.contains(0.0));
  CHECK(open_low.contains(1e-300));
  CHECK(open_low.contains(90.0));
  CHECK_FALSE(closed.contains(std::numeric_limits<double>::quiet_NaN()));
  CHECK(Range{}.contains(-1e300));
  static_assert(Range{0.0, 1.0}.contains(0.5), "usable at compile time");
}

TEST_CASE("a bound written in another unit counts as the bound", "[range]") {
  // -50 °C and -58 °F land a few ulps from 223.15 K.
  constexpr Range t{celsius_to_kelvin(-50.0), celsius_to_kelvin(60.0)};
  CHECK(t.contains(parse_quantity("-50C", Dimension::Temperature)));
  CHECK(t.contains(parse_quantity("-58F", Dimension::Temperature)));
  CHECK(t.contains(parse_quantity("140F", Dimension::Temperature)));
  CHECK_FALSE(t.contains(parse_quantity("-50.01C", Dimension::Temperature)));
}

TEST_CASE("refusals name the field, the value and the range in SI", "[range]") {
  CHECK(range_refusal("swing.speed", 120.0, Range{0.0, 90.0, true}, "m/s") ==
        "swing.speed = 120 m/s is out of range (allowed (0, 90] m/s)");
  CHECK(range_refusal("impact.e", 0.5, Range{0.0, 1.0}, "").empty());
  // One-sided ranges read as bounds, not intervals to infinity (never "[0, inf]").
  CHECK(range_text(Range{}, "") == "any finite number");
  CHECK(range_text(Range{0.0, std::numeric_limits<double>::infinity(), true}, "m/s") == "> 0 m/s");
  CHECK(range_text(Range{-std::numeric_limits<double>::infinity(), 5.0}, "m") == "<= 5 m");
  CHECK_THROWS_WITH(check_range("impact.mu", -1.0, Range{0.0, 2.0}, ""), Catch::Contains("impact.mu = -1"));
}
