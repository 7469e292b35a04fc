// Quantity parsing: exact conversions and clear rejection of bad text.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "physics/units.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

TEST_CASE("quantities convert exactly to SI", "[units]") {
  CHECK(parse_quantity("113mph", Dimension::Speed) == 113 * 0.44704);
  CHECK(parse_quantity("50m/s", Dimension::Speed) == 50.0);
  CHECK(parse_quantity("36km/h", Dimension::Speed) == Approx(10.0).epsilon(1e-15));
  CHECK(parse_quantity("10.5deg", Dimension::Angle) == Approx(10.5 * 3.14159265358979323846 / 180).epsilon(1e-15));
  CHECK(parse_quantity("-1.3deg", Dimension::Angle) == Approx(-0.022689280275926284).epsilon(1e-15));
  CHECK(parse_quantity("2686rpm", Dimension::AngularVelocity) ==
        Approx(2686 * 2 * 3.14159265358979323846 / 60).epsilon(1e-15));
  CHECK(parse_quantity("21C", Dimension::Temperature) == Approx(294.15).epsilon(1e-15));
  CHECK(parse_quantity("70F", Dimension::Temperature) == Approx(294.26111111111111).epsilon(1e-14));
  CHECK(parse_quantity("32F", Dimension::Temperature) == Approx(273.15).epsilon(1e-15));
  CHECK(parse_quantity("200g", Dimension::Mass) == Approx(0.2).epsilon(1e-15));
  CHECK(parse_quantity("34in", Dimension::Length) == Approx(0.8636).epsilon(1e-15));
  CHECK(parse_quantity("5%", Dimension::Fraction) == Approx(0.05).epsilon(1e-15));
  CHECK(parse_quantity("1600m", Dimension::Length) == 1600.0);
  CHECK(parse_quantity("29.92inHg", Dimension::Pressure) == Approx(101320.76).epsilon(1e-6));
  CHECK(parse_quantity("5143gcm2", Dimension::Inertia) == Approx(5.143e-4).epsilon(1e-14));
}

TEST_CASE("bare numbers are SI and whitespace is tolerated", "[units]") {
  CHECK(parse_quantity("0.83", Dimension::Dimensionless) == 0.83);
  CHECK(parse_quantity("75.5", Dimension::Speed) == 75.5);
  CHECK(parse_quantity("0.2", Dimension::Angle) == 0.2);  // radians: degrees are never bare
  CHECK(parse_quantity(" 113 mph ", Dimension::Speed) == 113 * 0.44704);
  CHECK(parse_quantity("+4deg", Dimension::Angle) == Approx(4 * 3.14159265358979323846 / 180));
  CHECK(parse_quantity("1e3rpm", Dimension::AngularVelocity) == Approx(1000 * 2 * 3.14159265358979323846 / 60));
}

TEST_CASE("bad quantities are rejected with a message naming text and units", "[units]") {
  CHECK_THROWS_WITH(parse_quantity("113furlongs", Dimension::Speed),
                    Contains("unknown unit 'furlongs'") && Contains("mph") && Contains("113furlongs"));
  CHECK_THROWS_WITH(parse_quantity("mph", Dimension::Speed), Contains("missing or malformed number"));
  CHECK_THROWS_WITH(parse_quantity("", Dimension::Speed), Contains("empty"));
  CHECK_THROWS_WITH(parse_quantity("nan", Dimension::Speed), Contains("NaN"));
  CHECK_THROWS_WITH(parse_quantity("infmph", Dimension::Speed), Contains("NaN and infinity"));
  CHECK_THROWS_WITH(parse_quantity("-inf", Dimension::Angle), Contains("NaN and infinity"));
  CHECK_THROWS_WITH(parse_quantity("10degx", Dimension::Angle), Contains("unknown unit 'degx'"));
  CHECK_THROWS_WITH(parse_quantity("10 deg 5", Dimension::Angle), Contains("unknown unit"));
  CHECK_THROWS_WITH(parse_quantity("10mph", Dimension::Angle), Contains("angle") && Contains("deg, rad"));
  CHECK_THROWS_WITH(parse_quantity("1e999", Dimension::Speed), Contains("out of range"));
  CHECK_THROWS_WITH(parse_quantity("5mph", Dimension::Dimensionless), Contains("unknown unit"));
  CHECK_THROWS_AS(parse_quantity("1.2.3m", Dimension::Length), InputError);
}

TEST_CASE("quantity lists", "[units]") {
  const auto v = parse_quantity_list("[10mm, 0mm]", Dimension::Length);
  REQUIRE(v.size() == 2);
  CHECK(v[0] == Approx(0.010).epsilon(1e-15));
  CHECK(v[1] == 0.0);
  CHECK(parse_quantity_list("[]", Dimension::Length).empty());
  CHECK_THROWS_WITH(parse_quantity_list("[10mm, 0mm", Dimension::Length), Contains("not closed"));
  CHECK_THROWS_WITH(parse_quantity_list("[10mm,,0mm]", Dimension::Length), Contains("empty"));
}
