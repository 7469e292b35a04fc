// Roll-out after the carry: how far a landing ball runs on the shipped turf, by
// landing angle, speed, spin and firmness, against what tour shots and greens do.
#include <catch2/catch.hpp>

#include <cmath>

#include "physics/flight.hpp"
#include "physics/ground.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

const SurfaceMaterial& material(const char* name) {
  for (const SurfaceMaterial& m : test::assets().materials())
    if (m.name == name) return m;
  FAIL("no material " << name);
  return test::assets().materials().front();
}

// A ball arriving at flat ground of `surface` at `speed` (m/s), `angle_deg` below the
// horizontal, with `rpm` of backspin: how far it runs past where it landed (m).
double run_after_landing(const char* surface, double speed, double angle_deg, double rpm, double firmness = 1.0) {
  const FlatGround ground(material(surface));
  test::FlightCase c;
  c.aero = &test::assets().aero("tour_fit");
  c.settings.ground_firmness = firmness;
  const double a = deg_to_rad(angle_deg);
  c.launch.position = Vec3(0, c.ball.radius + 1e-4, 0);
  c.launch.velocity = speed * Vec3(std::cos(a), -std::sin(a), 0);
  c.launch.spin = Vec3(0, 0, rpm_to_radps(rpm));  // +z: backspin for a ball moving +x
  c.record_samples = false;
  const ShotTrajectory t = test::fly(c, &ground);
  REQUIRE(t.summary.end == EndReason::Rest);
  return t.summary.rest_position.x() - t.summary.landing_position.x();
}

}  // namespace

TEST_CASE("roll-out falls as the landing steepens and grows with speed", "[ground][rollout]") {
  for (const char* surface : {"fairway", "green", "rough"}) {
    for (double rpm : {0.0, 2500.0}) {
      double last = 1e9;
      for (double angle = 15.0; angle <= 75.0; angle += 10.0) {
        const double run = run_after_landing(surface, 22.0, angle, rpm);
        INFO(surface << " " << rpm << " rpm at " << angle << " deg: " << run << " m");
        CHECK(run < last);
        last = run;
      }
      CHECK(run_after_landing(surface, 12.0, 40.0, rpm) < run_after_landing(surface, 24.0, 40.0, rpm));
    }
  }
}

TEST_CASE("backspin shortens the run; a spinless ball always runs forward", "[ground][rollout]") {
  for (double angle : {20.0, 45.0, 70.0, 85.0}) {
    INFO(angle << " deg");
    const double none = run_after_landing("fairway", 26.0, angle, 0.0);
    CHECK(none > 0.0);  // a spinless landing runs on, never back behind where it landed
    CHECK(run_after_landing("fairway", 26.0, angle, 3000.0) < none);
  }
}

TEST_CASE("a tour drive runs out 10-30 yd on the fairway", "[ground][rollout][trackman]") {
  // TrackMan's PGA driver lands at 37-38° after 275 yd; PGA TOUR radar on measured holes
  // gave the 100th-ranked player 22 yd of roll in 2007 and 15 in 2017 (carry vs total).
  const FlatGround ground(material("fairway"));
  const ShotTrajectory t = test::fly(test::golf_launch(167, 10.9, 2686), &ground);
  const double roll_yd = (t.summary.total_m - t.summary.carry_m) / 0.9144;
  INFO("carry " << t.summary.carry_m / 0.9144 << " yd, roll " << roll_yd << " yd, landing "
                << t.summary.landing_angle_deg << " deg");
  CHECK(roll_yd > 10.0);
  CHECK(roll_yd < 30.0);
}

TEST_CASE("a wedge with tour spin checks on the green; the same landing without spin runs", "[ground][rollout]") {
  // Haake (1987-94, 721 strobe photographs on 18 UK greens): receptive greens held
  // backspin above ~3300 rpm; a PW lands at ~52° with ~8000 rpm left.
  const double wedge = run_after_landing("green", 20.0, 52.0, 8000.0);
  CHECK(wedge < 2.0);
  CHECK(run_after_landing("green", 20.0, 52.0, 2500.0) > wedge + 1.0);
}

TEST_CASE("firmer turf runs farther", "[ground][rollout]") {
  CHECK(run_after_landing("fairway", 24.0, 40.0, 2500.0, 2.0) > run_after_landing("fairway", 24.0, 40.0, 2500.0, 1.0));
  CHECK(run_after_landing("fairway", 24.0, 40.0, 2500.0, 0.5) < run_after_landing("fairway", 24.0, 40.0, 2500.0, 1.0));
}
