// Roll-out after the carry: how far a landing ball runs on the shipped turf, by
// landing angle, speed, spin and firmness, against what tour shots and greens do.
#include <catch2/catch.hpp>

#include <cmath>
#include <utility>

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

namespace {

// Carry and total (yd) of a launch on the shipped flat fairway.
std::pair<double, double> carry_and_total(double mph, double launch_deg, double rpm) {
  const FlatGround ground(material("fairway"));
  test::FlightCase c = test::golf_launch(mph, launch_deg, rpm);
  c.record_samples = false;
  const FlightSummary s = test::fly(c, &ground).summary;
  return {s.carry_m / 0.9144, s.total_m / 0.9144};
}

}  // namespace

TEST_CASE("a shallow landing runs on about as much farther as its shorter carry, not more",
          "[ground][rollout][layer]") {
  // Launch/spin trade-offs: a 120 mph ball launched at 10° (lands at ~19°) instead of 14°
  // (~28°), both at 2200 rpm, carries ~20 yd less and gets back only about half of it on the
  // ground: its total is ~10 yd shorter. Golf Digest's 2008 TrackMan loft test: a 75 mph
  // swinger's 9° driver rolled 32 yd and totalled within a yard of drivers carrying 15-20 yd
  // farther. Before the turf's layer the 10° ball rolled 74 yd and finished 8 yd past the 14°.
  const auto low = carry_and_total(120, 10, 2200), high = carry_and_total(120, 14, 2200);
  const double low_roll = low.second - low.first, high_roll = high.second - high.first;
  INFO("10 deg: carry " << low.first << " roll " << low_roll << "; 14 deg: carry " << high.first << " roll "
                        << high_roll);
  CHECK(low_roll > high_roll);                      // the flatter landing still runs farther
  CHECK(high.second - low.second > 5.0);            // but finishes shorter: ~10 yd
  CHECK(high.second - low.second < 15.0);
  CHECK(low_roll < 50.0);                           // about half the 74 yd
}

TEST_CASE("a tour drive gets its most total from a landing near 40 degrees", "[ground][rollout][layer]") {
  // S. Sackett (TrackMan fitting, "The forgotten number in driver fitting"): the landing
  // angle for the most consistent bounce and roll is around 40°; flatter trades carry for a
  // roll that does not pay it back. At the tour's 167 mph and ~2600 rpm, the launch that
  // totals farthest lands between 30° and 45° (a worm-burner landing at 23° used to total
  // 10 yd more than the tour's 10.9° launch).
  double best_total = 0.0, best_landing = 0.0;
  for (double launch = 6.0; launch <= 18.0; launch += 1.0) {
    const FlatGround ground(material("fairway"));
    test::FlightCase c = test::golf_launch(167, launch, 2600);
    c.record_samples = false;
    const FlightSummary s = test::fly(c, &ground).summary;
    if (s.total_m > best_total) {
      best_total = s.total_m;
      best_landing = s.landing_angle_deg;
    }
  }
  INFO("most total " << best_total / 0.9144 << " yd, landing at " << best_landing << " deg");
  CHECK(best_landing > 30.0);
  CHECK(best_landing < 45.0);
}
