// Spin decomposition and launch numbers in the conventions of DESIGN §2.
#include <catch2/catch.hpp>

#include <cmath>

#include "physics/launch.hpp"

using namespace sweetspot;

TEST_CASE("pure backspin on a ball moving downrange", "[spin]") {
  const auto s = decompose_spin(Vec3(70, 0, 0), Vec3(0, 0, 300));
  CHECK(s.backspin == 300.0);
  CHECK(s.sidespin_right == 0.0);
  CHECK(s.rifle == 0.0);
  CHECK(s.axis_rad == 0.0);
  CHECK(s.total == 300.0);
}

TEST_CASE("hook spin tilts the axis negative", "[spin]") {
  // ω along +y on a ball moving +x: Magnus ω×v = y×x = −z, a curve to the left.
  const auto s = decompose_spin(Vec3(70, 0, 0), Vec3(0, 100, 0));
  CHECK(s.backspin == Approx(0.0).margin(1e-12));
  CHECK(s.sidespin_right == Approx(-100.0));
  CHECK(s.axis_rad == Approx(-kPi / 2));
  const Vec3 magnus = Vec3(0, 100, 0).cross(Vec3(70, 0, 0));
  CHECK(magnus.z() < 0.0);
}

TEST_CASE("rifle spin is separate and gives no backspin or sidespin", "[spin]") {
  const auto s = decompose_spin(Vec3(30, 0, 0), Vec3(50, 0, 0));
  CHECK(s.rifle == 50.0);
  CHECK(s.backspin == 0.0);
  CHECK(s.sidespin_right == Approx(0.0).margin(1e-12));
}

TEST_CASE("a ball launched 20 degrees right with pure backspin about its own axis", "[spin]") {
  const double a = deg_to_rad(20.0);
  const Vec3 v = 60.0 * Vec3(std::cos(a), 0.0, std::sin(a));
  const Vec3 h = v.normalized().cross(Vec3::UnitY()).normalized();
  const auto s = decompose_spin(v, 250.0 * h);
  CHECK(s.backspin == Approx(250.0));
  CHECK(s.sidespin_right == Approx(0.0).margin(1e-12));
  CHECK(s.axis_rad == Approx(0.0).margin(1e-14));
  // Spin about world z on that ball is NOT pure backspin: part of it is rifle spin.
  const auto s2 = decompose_spin(v, Vec3(0, 0, 250.0));
  CHECK(s2.backspin == Approx(250.0 * std::cos(a)));
  CHECK(s2.rifle == Approx(250.0 * std::sin(a)));
  const auto m = measure_launch({Vec3::Zero(), v, Vec3::Zero()});
  CHECK(m.horizontal_angle == Approx(a));
  CHECK(m.vertical_angle == 0.0);
}

TEST_CASE("launch_from_metrics inverts measure_launch", "[spin]") {
  const auto l = launch_from_metrics(74.66, deg_to_rad(10.9), deg_to_rad(-2.0), 281.3, deg_to_rad(7.5), Vec3::Zero());
  const auto m = measure_launch(l);
  CHECK(m.ball_speed == Approx(74.66));
  CHECK(m.vertical_angle == Approx(deg_to_rad(10.9)));
  CHECK(m.horizontal_angle == Approx(deg_to_rad(-2.0)));
  CHECK(m.spin.total == Approx(281.3));
  CHECK(m.spin.axis_rad == Approx(deg_to_rad(7.5)));
  CHECK(m.spin.rifle == Approx(0.0).margin(1e-9));
}

TEST_CASE("a ball moving straight up has finite spin numbers", "[spin]") {
  const auto s = decompose_spin(Vec3(0, 10, 0), Vec3(1, 2, 3));
  CHECK(std::isfinite(s.backspin));
  CHECK(std::isfinite(s.axis_rad));
  CHECK(s.rifle == 2.0);
}
