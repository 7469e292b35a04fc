// Golf's rules on a shot: where the ball ends decides it (water, out of bounds, in play).
#include <catch2/catch.hpp>

#include "game/rules/run_shot.hpp"
#include "game/rules/golf_rules.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

ShotEnd end_on(const char* material) {
  WorldDescription d;
  d.name = "strip";
  d.materials = test::assets().materials();
  int m = -1;
  for (size_t i = 0; i < d.materials.size(); ++i)
    if (d.materials[i].name == material) m = static_cast<int>(i);
  REQUIRE(m >= 0);
  WorldMesh g;
  g.material = m;
  g.vertices = {Vec3(-50, 0, -50), Vec3(400, 0, -50), Vec3(400, 0, 50), Vec3(-50, 0, 50)};
  g.indices = {0, 2, 1, 0, 3, 2};
  d.meshes = {g};
  d.bounds_min = Vec3(-60, -5, -60);
  d.bounds_max = Vec3(410, 300, 60);
  const World world(d);
  const ShotModel model = test::golf_model(&world);
  GolfShotRules rules(nullptr, model);
  ShotState s = start_state(test::golf_launch(120.0, 16.3, 7097.0).launch);
  while (!s.ended) step(model, s);
  return rules.outcome(s);
}

}  // namespace

TEST_CASE("golf: the surface the ball ends on decides the outcome", "[rules][golf]") {
  CHECK(end_on("fairway") == ShotEnd::Rest);
  CHECK(end_on("water") == ShotEnd::Water);
  CHECK(end_on("out_of_bounds") == ShotEnd::OutOfBounds);
}

TEST_CASE("golf: a ball that leaves the world is out of bounds", "[rules][golf]") {
  const Assets& A = test::assets();
  ShotSpec spec;  // a driver hit 60 degrees left: off the hole's 140 m wide world
  spec.strike = ClubStrike{};
  spec.placement.aim = deg_to_rad(-60.0);
  CHECK(run_shot(resolve(spec, A), "hooked").end == ShotEnd::OutOfBounds);
}
