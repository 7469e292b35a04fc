// The integrator's error where a player sees it: carry and rest position of whole shots on
// the golf_hole terrain at the default tolerances against the same model at 1e-13. The
// defaults are as loose as this contract allows; these tests hold them to it. The error is
// not just the integrator's: a bounce turned into a roll, or a landing on the other side of
// a facet edge, would move the rest by up to 25 cm for a 0.1 mm change without the contact
// layer and the smooth bounce normal, which make both continuous.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "game/util/rng.hpp"
#include "physics/flight.hpp"
#include "physics/units.hpp"
#include "physics/world.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

struct Pair {
  ShotModel fast, tight;
};

Pair golf_hole_models() {
  const World& world = *test::assets().world("golf_hole")->world;
  FlightSettings tight;
  tight.rel_tol = 1e-13;
  tight.abs_tol = 1e-14;
  tight.bounce_rel_tol = 1e-13;
  return {test::golf_model(&world), test::golf_model(&world, {}, tight)};
}

struct Errors {
  double carry = 0.0, rest = 0.0;
};

Errors errors(const Pair& p, const LaunchState& launch) {
  const FlightSummary a = simulate_shot(p.fast, launch, false).summary;
  const FlightSummary b = simulate_shot(p.tight, launch, false).summary;
  return {std::abs(a.carry_m - b.carry_m), (a.rest_position - b.rest_position).norm()};
}

Vec3 tee() { return Vec3(0.0, golf_ball_properties().radius, 0.0); }  // ball on the ground at the origin

}  // namespace

TEST_CASE("default tolerances: the tour launches carry and rest within 1 cm of a 1e-13 reference",
          "[flight][accuracy]") {
  // TrackMan PGA Tour averages (DESIGN §4), the bench's set.
  const Pair p = golf_hole_models();
  const struct {
    double mph, deg, rpm;
  } set[] = {{167.0, 10.9, 2686.0}, {120.0, 16.3, 7097.0}, {102.0, 24.2, 9304.0}};
  for (const auto& l : set) {
    const Errors e = errors(p, launch_from_metrics(mph_to_mps(l.mph), deg_to_rad(l.deg), 0.0, rpm_to_radps(l.rpm), 0.0, tee()));
    INFO(l.mph << " mph: carry error " << e.carry << " m, rest error " << e.rest << " m");
    CHECK(e.carry < 0.004);
    CHECK(e.rest < 0.01);
  }
}

TEST_CASE("default tolerances: 1000 random golf launches on golf_hole, carry and rest against a 1e-13 reference",
          "[flight][accuracy]") {
  // 60-180 mph, 5-40° up, ±8° aim, 1500-10500 rpm, ±25° spin axis: every club from a wedge
  // to a long drive, slices and hooks, into fairway, rough, sand, green, water and out of the
  // world's bounds (the leaving point is found on the dense output, not at a step's end).
  const Pair p = golf_hole_models();
  Rng rng(2026);
  double worst_carry = 0.0, worst_rest = 0.0;
  int rest_over_1cm = 0;
  constexpr int kLaunches = 1000;
  for (int i = 0; i < kLaunches; ++i) {
    const double mph = 60.0 + 120.0 * rng.uniform(), deg = 5.0 + 35.0 * rng.uniform();
    const double aim = -8.0 + 16.0 * rng.uniform(), rpm = 1500.0 + 9000.0 * rng.uniform();
    const double axis = -25.0 + 50.0 * rng.uniform();
    const LaunchState launch = launch_from_metrics(mph_to_mps(mph), deg_to_rad(deg), deg_to_rad(aim),
                                                   rpm_to_radps(rpm), deg_to_rad(axis), tee());
    const Errors e = errors(p, launch);
    INFO("launch " << i << ": " << mph << " mph, " << deg << "°, aim " << aim << "°, " << rpm << " rpm, axis "
                   << axis << "°: carry error " << e.carry << " m, rest error " << e.rest << " m");
    // The contract is 1 cm; measured worst 0.94 mm (95th percentile 0.39 mm) at rel_tol
    // 4e-6 with a position's error judged by the speed (1.7 / 0.8 mm judged by its distance
    // from the origin), each carry step that crosses a kink of the aero law (S = s_max) taken
    // again to end there. At 1e-6 with the kink inside a step: 3.5 mm (p95 1.4 mm), and
    // 4.4-8.4 mm on other seeds (7, 19, 5).
    CHECK(e.carry < 0.004);
    // The contract: every rest within 1 cm. Measured worst: 4.7 mm. The touch's contact point
    // is taken at the ball's centre on the arc, not on the straight chord that found it: read
    // there, the smooth bounce normal would be up to a chord's sag away, at a point that
    // moves with where the integrator's steps fall, and 4 of these launches would rest
    // 1.0-1.8 cm from the reference. Where the arc meets the touched face's plane over the
    // neighbouring face, it touches that face where the arc meets its plane: taken on the
    // first face's plane, a hop onto a bunker's steepening downslope landed 2 ms early and
    // rested 1.04 cm off (launch 850 of this sample with the lift read at the whole spin).
    CHECK(e.rest < 0.01);
    worst_carry = std::max(worst_carry, e.carry);
    worst_rest = std::max(worst_rest, e.rest);
    if (e.rest >= 0.01) ++rest_over_1cm;
  }
  INFO("worst carry error " << worst_carry << " m, worst rest error " << worst_rest << " m, " << rest_over_1cm
                            << " rests over 1 cm");
  CHECK(rest_over_1cm == 0);
}

TEST_CASE("default tolerances: launches that once rested over 1 cm from the 1e-13 reference", "[flight][accuracy]") {
  // From the 1 000-launch sample above drawn with other seeds.
  const Pair p = golf_hole_models();
  const struct {
    const char* why;
    double mph, deg, aim, rpm, axis;
  } cases[] = {
      // A roll from the fairway across a corner of rough whose faces are coplanar up to
      // round-off. The ball sits 2 nm under the rough's plane at the seam; the sweep for
      // ground in between meets the rough's own face 5 cm on, and a step run there on the
      // fairway's resistance rests 20.6 mm from the reference, whose step falls otherwise.
      {"roll across a corner of another material", 100.26578330707068, 10.98401499393778, -2.7315313171085265,
       10477.319547548082, -11.047241195156953},
  };
  for (const auto& c : cases) {
    const Errors e = errors(p, launch_from_metrics(mph_to_mps(c.mph), deg_to_rad(c.deg), deg_to_rad(c.aim),
                                                   rpm_to_radps(c.rpm), deg_to_rad(c.axis), tee()));
    INFO(c.why << ": carry error " << e.carry << " m, rest error " << e.rest << " m");
    CHECK(e.rest < 0.005);
  }
}

TEST_CASE("a shot is the same wherever the world sits: golf_hole translated by 2 km", "[flight][accuracy][frame]") {
  // Frame independence: the same launches on the course and on a copy moved 2 km east, 30 m
  // up and 2 km north end at the same place, moved. The step controller judges a position's
  // error by the ball's speed, not by its distance from the origin; judged by the distance,
  // the copy's steps would fall elsewhere and its rests move by up to 3.2 mm (carries
  // 3.2 mm). Measured: carries equal, rests within 8 µm (round-off in the moved mesh's
  // coordinates).
  const WorldDescription& d0 = test::assets().world("golf_hole")->description();
  const Vec3 shift(2000.0, 30.0, 2000.0);
  WorldDescription d1 = d0;
  for (WorldMesh& m : d1.meshes)
    for (Vec3& v : m.vertices) v += shift;
  d1.origin += shift;
  d1.bounds_min += shift;
  d1.bounds_max += shift;
  const World w0(d0), w1(d1);
  const ShotModel m0 = test::golf_model(&w0), m1 = test::golf_model(&w1);
  Rng rng(2026);
  double worst_carry = 0.0, worst_rest = 0.0;
  for (int i = 0; i < 300; ++i) {
    const double mph = 60.0 + 120.0 * rng.uniform(), deg = 5.0 + 35.0 * rng.uniform();
    const double aim = -8.0 + 16.0 * rng.uniform(), rpm = 1500.0 + 9000.0 * rng.uniform();
    const double axis = -25.0 + 50.0 * rng.uniform();
    const auto launch = [&](const Vec3& at) {
      return launch_from_metrics(mph_to_mps(mph), deg_to_rad(deg), deg_to_rad(aim), rpm_to_radps(rpm),
                                 deg_to_rad(axis), at);
    };
    const FlightSummary a = simulate_shot(m0, launch(tee()), false).summary;
    const FlightSummary b = simulate_shot(m1, launch(tee() + shift), false).summary;
    INFO("launch " << i << ": " << mph << " mph, " << deg << "°, aim " << aim << "°");
    CHECK(a.end == b.end);
    worst_carry = std::max(worst_carry, std::abs(a.carry_m - b.carry_m));
    worst_rest = std::max(worst_rest, (a.rest_position + shift - b.rest_position).norm());
  }
  INFO("worst carry difference " << worst_carry << " m, worst rest difference " << worst_rest << " m");
  CHECK(worst_carry < 1e-6);
  CHECK(worst_rest < 1e-4);
}
