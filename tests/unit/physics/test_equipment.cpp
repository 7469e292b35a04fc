// Equipment validation: each field against the range beside it in physics/equipment.hpp.
#include <catch2/catch.hpp>

#include <string>

#include "physics/equipment.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

TEST_CASE("physics-side validation names the field and range", "[equipment][validation]") {
  ClubSpec c;
  c.name = "test";
  CHECK_NOTHROW(validate_club(c));
  c.loft = deg_to_rad(95);
  CHECK_THROWS_WITH(validate_club(c), Contains("club 'test': loft = 95 deg is out of range (allowed [0, 70] deg)"));
  c = ClubSpec{};
  c.cg = Vec3(0.01, 0, 0);
  CHECK_THROWS_WITH(validate_club(c), Contains("behind the face"));
  c = ClubSpec{};
  c.inertia(0, 1) = 1e-4;  // asymmetric
  CHECK_THROWS_WITH(validate_club(c), Contains("symmetric"));
  BallSpec b;
  b.inertia = 1.0;
  CHECK_THROWS_WITH(validate_ball(b), Contains("inertia must be in"));
  // A compliant ball softer than 1e5 N/m^1.5 never leaves the face (a hostile balls.toml
  // launches at 0 mph); 0 means rigid and is allowed.
  b = BallSpec{};
  b.compliance.stiffness = 1e-3;
  CHECK_THROWS_WITH(validate_ball(b), Contains("compliance.stiffness") && Contains("too soft"));
  b.compliance.stiffness = 0.0;
  CHECK_NOTHROW(validate_ball(b));
  b.compliance.stiffness = 2.36e7;  // the tour ball
  CHECK_NOTHROW(validate_ball(b));
  BatSpec bat;
  bat.barrel_profile = {{0.0, 0.02}, {0.84, 0.033}};
  CHECK_NOTHROW(validate_bat(bat));
  bat.pivot_from_knob = 0.6;
  CHECK_THROWS_WITH(validate_bat(bat), Contains("pivot_from_knob"));
}
