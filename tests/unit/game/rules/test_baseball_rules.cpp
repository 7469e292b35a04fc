// Baseball's rules on a shot: over the fence is a home run (decided on the path, before
// any landing behind the fence), off the wall is in play, into the stands is dead.
#include <catch2/catch.hpp>

#include <memory>

#include "game/rules/run_shot.hpp"
#include "game/rules/baseball_rules.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

WorldMesh plane(int material, double half) {
  WorldMesh m;
  m.material = material;
  m.vertices = {Vec3(-half, 0, -half), Vec3(half, 0, -half), Vec3(half, 0, half), Vec3(-half, 0, half)};
  m.indices = {0, 2, 1, 0, 3, 2};
  return m;
}

// A field with a 3 m wall across it at x = 100 m (facing home plate) and stands beyond.
WorldAsset park() {
  WorldDescription d;
  d.name = "park";
  const auto& mats = test::assets().materials();
  d.materials = mats;
  const auto index = [&](const char* name) {
    for (size_t i = 0; i < mats.size(); ++i)
      if (mats[i].name == name) return static_cast<int>(i);
    FAIL(name);
    return -1;
  };
  WorldMesh field = plane(index("grass"), 99.9);
  WorldMesh stands;
  stands.material = index("out_of_bounds");
  stands.vertices = {Vec3(100, 0, -120), Vec3(200, 0, -120), Vec3(200, 0, 120), Vec3(100, 0, 120)};
  stands.indices = {0, 2, 1, 0, 3, 2};
  WorldMesh wall;
  wall.material = index("wall");
  wall.vertices = {Vec3(100, 0, -60), Vec3(100, 0, 60), Vec3(100, 3, 60), Vec3(100, 3, -60)};
  wall.indices = {0, 1, 2, 0, 2, 3};  // normal -x: faces home plate
  d.meshes = {field, stands, wall};
  d.bounds_min = Vec3(-120, -5, -130);
  d.bounds_max = Vec3(210, 500, 130);
  WorldAsset a;
  a.name = "park";
  a.sport = "baseball";
  a.fence_height = 3.0;
  a.fence_line = {Vec3(100, 0, -60), Vec3(100, 0, 60)};
  a.world = std::make_unique<const World>(std::move(d));
  return a;
}

struct Played {
  ShotEnd end;
  ShotTrajectory trajectory;
};

Played play(const WorldAsset& w, double mph, double deg, double direction_deg = 0.0) {
  const ShotModel model = test::baseball_model(w.world.get());
  BaseballShotRules rules(&w, model);
  const LaunchState l = launch_from_metrics(mph_to_mps(mph), deg_to_rad(deg), deg_to_rad(direction_deg),
                                            rpm_to_radps(2000.0), 0.0, Vec3(0.0, 0.9, 0.0));
  ShotState s = start_state(l);
  TrajectoryRecorder rec(s, true);
  bool over = false;
  while (!s.ended && !over) {
    const ShotState before = s;
    const ShotEvent ev = step(rules.model(), s);
    rec.add(before, s, ev);
    over = rules.observe(before, s, ev);
  }
  return {rules.outcome(s), rec.finish(s)};
}

}  // namespace

TEST_CASE("a ball over the fence is a home run; one below the top rebounds off the wall", "[rules][baseball]") {
  const WorldAsset w = park();
  const Played hr = play(w, 103.0, 28.0);
  CHECK(hr.end == ShotEnd::HomeRun);
  CHECK(hr.trajectory.summary.carry_m > 120.0);  // the batted-ball distance to field level beyond the wall
  const Played liner = play(w, 100.0, 10.0);     // one hop, reaches x = 100 m about 1.25 m up
  CHECK(liner.end == ShotEnd::Rest);
  CHECK(liner.trajectory.summary.rest_position.x() < 100.0);
  bool rebounded = false;
  for (const auto& s : liner.trajectory.samples) rebounded = rebounded || (s.position.x() > 90.0 && s.velocity.x() < -1.0);
  CHECK(rebounded);
}

TEST_CASE("crossing the fence and landing behind it in one step is still a home run", "[rules][baseball]") {
  // Constructed step: the ball at x = 95 m, 8 m up, and 0.3 s later on the stands at
  // x = 125 m. The fence line is crossed on the way, well above the 3 m wall.
  const WorldAsset w = park();
  const ShotModel model = test::baseball_model(w.world.get());
  BaseballShotRules rules(&w, model);
  ShotState before;
  before.t = 4.0;
  before.y << 95.0, 8.0, 0.0, 100.0, -10.0, 0.0, 0.0, 0.0, 0.0;
  ShotState after = before;
  after.t = 4.3;
  after.y << 125.0, model.ball.radius, 0.0, 98.0, -16.0, 0.0, 0.0, 0.0, 0.0;
  after.landed = true;
  ShotEvent ev;
  ev.kind = ShotEventKind::Landing;
  ev.velocity_in = Vec3(98.0, -16.0, 0.0);
  const auto at = rules.fence_crossing(before, after, ev.velocity_in);
  REQUIRE(at.has_value());
  CHECK(at->x() == Approx(100.0).margin(0.5));
  CHECK(at->y() > 3.0);
  CHECK(rules.observe(before, after, ev));
  CHECK(rules.outcome(after) == ShotEnd::HomeRun);
}

TEST_CASE("a ball first landing in the stands around the wall is dead; one leaving the world is out", "[rules][baseball]") {
  const WorldAsset w = park();
  // Pulled down the line past the end of the wall (|z| > 60 m) into the stands.
  const Played foul = play(w, 105.0, 30.0, -40.0);
  CHECK(foul.end == ShotEnd::OutOfBounds);
}

TEST_CASE("the shipped ballpark: the built-in home run clears the fence, the pop-up stays in", "[rules][baseball]") {
  const Assets& A = test::assets();
  ShotSpec spec;
  spec.sport = "baseball";
  spec.strike = BatStrike{};
  auto& b = std::get<BatStrike>(spec.strike);
  b.swing.bat_speed = mph_to_mps(75.0);
  b.swing.attack_angle = deg_to_rad(12.0);
  b.swing.undercut = 0.013;
  CHECK(run_shot(resolve(spec, A), "hr").end == ShotEnd::HomeRun);
  b.swing.undercut = 0.045;  // well under the ball: a pop-up
  CHECK(run_shot(resolve(spec, A), "pop").end == ShotEnd::Rest);
}

TEST_CASE("a ball that bounces or rolls into the stands is dead there", "[rules][baseball]") {
  const WorldAsset w = park();
  // A low liner past the end of the wall (|z| > 60 m): it lands on the grass and skips on
  // into the stands at x = 100 m, where it is dead, not carried on across them.
  const Played skip = play(w, 100.0, 4.0, -40.0);
  CHECK(skip.end == ShotEnd::OutOfBounds);
  CHECK(skip.trajectory.summary.landing_position.x() < 100.0);
  CHECK(skip.trajectory.summary.rest_position.x() < 110.0);
}

TEST_CASE("the shipped ballpark: the stands' front wall keeps a ground ball in foul ground in play", "[rules][baseball]") {
  const WorldAsset& park = *test::assets().world("ballpark");
  // Rule 2.01: the stands begin 60 ft outside each foul line. A hard grounder pulled 30 deg
  // foul of the first-base line rolls to that wall, rebounds and rests in foul ground.
  for (double side : {-1.0, 1.0}) {
    const Played g = play(park, 90.0, 3.0, side * 75.0);
    INFO("side " << side << ": rest at " << g.trajectory.summary.rest_position.transpose());
    CHECK(g.end == ShotEnd::Rest);
    const Vec3 r = g.trajectory.summary.rest_position;
    const double outside = std::max(-(r.x() + r.z()), -(r.x() - r.z())) / std::sqrt(2.0);
    CHECK(outside > 0.0);
    CHECK(outside < 60.0 * 0.3048);
    double reached = 0.0;  // it got to the wall: within a ball's radius and a little of it
    for (const TrajectorySample& p : g.trajectory.samples)
      reached = std::max(reached, std::max(-(p.position.x() + p.position.z()), -(p.position.x() - p.position.z())) / std::sqrt(2.0));
    CHECK(reached > 60.0 * 0.3048 - 0.3);
  }
}
