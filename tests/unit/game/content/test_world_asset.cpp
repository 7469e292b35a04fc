// The generated world assets load through assimp and behave: the hole is playable, the
// ballpark has its stated fence, and broken files are rejected or repaired with a message.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "game/content/assets.hpp"
#include "game/rules/run_shot.hpp"
#include "support/test_assets.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/units.hpp"

using namespace sweetspot;
namespace fs = std::filesystem;

namespace {

bool has_material(const WorldDescription& d, const std::string& name) {
  for (const auto& m : d.meshes)
    if (d.materials[static_cast<size_t>(m.material)].name == name) return true;
  return false;
}

// A launch on the shipped worlds through the one way in (ShotSpec -> run_shot), so the
// sport's rules apply.
ShotResult launch(const char* sport, double mph, double deg, double rpm, double dir_deg = 0.0) {
  return run_shot(resolve(test::launch_spec(sport, mph, deg, rpm, dir_deg), test::assets()), "test");
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream f(p);
  f << text;
}

}  // namespace

TEST_CASE("golf_hole asset: materials, pin, size", "[assets][world]") {
  const WorldAsset& a = *test::assets().world("golf_hole");
  const WorldDescription& d = a.description();
  CHECK(a.name == "golf_hole");
  CHECK(a.sport == "golf");
  for (const char* m : {"tee", "fairway", "rough", "sand", "green", "water", "flag"}) {
    INFO(m);
    CHECK(has_material(d, m));
  }
  REQUIRE(a.pin.has_value());
  CHECK(a.pin->x() == Approx(405.0));
  CHECK(d.notes.empty());
  const World& world = *a.world;
  CHECK(world.collision_triangles() > 10000);
  CHECK(world.collision_triangles() < 50000);
  SurfaceContact under;
  REQUIRE(world.support(Vec3(0.0, 0.0213, 0.0), 0.021335, 0.01, &under));
  CHECK(world.material(under.material).kind == SurfaceKind::Tee);
  under = SurfaceContact{};
  REQUIRE(world.support(Vec3(a.pin->x(), a.pin->y() + 0.0213, a.pin->z()), 0.021335, 0.05, &under));
  CHECK(world.material(under.material).kind == SurfaceKind::Green);
  CHECK(under.normal.x() < -0.01);  // the green slopes up toward the back
}

TEST_CASE("TrackMan launches on the golf hole: same carry as flat ground, end at rest", "[assets][world]") {
  const World& world = *test::assets().world("golf_hole")->world;
  for (const auto& [mph, deg, rpm] : {std::tuple{167.0, 10.9, 2686.0}, {120.0, 16.3, 7097.0}, {102.0, 24.2, 9304.0}}) {
    INFO(mph);
    const test::FlightCase in = test::golf_launch(mph, deg, rpm);
    const FlightSummary flat = test::fly(in).summary;
    const FlightSummary hole = test::fly(in, &world).summary;
    // The fairway undulates by tens of centimetres: carry moves by well under 1 %.
    CHECK(hole.carry_m == Approx(flat.carry_m).epsilon(0.01));
    CHECK(hole.end == EndReason::Rest);
    CHECK(hole.total_m > 0.9 * hole.carry_m);
  }
}

TEST_CASE("ballpark asset: fence at 330 ft on the lines and 400 ft to centre", "[assets][world]") {
  const WorldAsset& a = *test::assets().world("ballpark");
  const WorldDescription& d = a.description();
  for (const char* m : {"dirt", "grass", "warning_track", "wall", "foul_line"}) {
    INFO(m);
    CHECK(has_material(d, m));
  }
  REQUIRE(a.fence_line.size() >= 3);
  const auto dist_ft = [](const Vec3& p) { return m_to_ft(std::hypot(p.x(), p.z())); };
  CHECK(dist_ft(a.fence_line.front()) == Approx(330.0).epsilon(1e-4));
  CHECK(dist_ft(a.fence_line.back()) == Approx(330.0).epsilon(1e-4));
  CHECK(dist_ft(a.fence_line[a.fence_line.size() / 2]) == Approx(400.0).epsilon(1e-4));
  CHECK(a.fence_line.front().z() < 0.0);  // left field first
  CHECK(m_to_ft(a.fence_height) == Approx(10.0).epsilon(1e-3));
}

TEST_CASE("ballpark: a long fly ball is a home run, a liner off the wall rebounds", "[assets][world][fence]") {
  const ShotResult hr = launch("baseball", 103.0, 28.0, 2000.0);
  CHECK(hr.end == ShotEnd::HomeRun);
  CHECK(m_to_ft(hr.trajectory.summary.carry_m) > 400.0);
  // 95 mph at 25° toward right-centre reaches the 369 ft wall below its top.
  const ShotResult wall = launch("baseball", 95.0, 25.0, 2000.0, 30.0);
  CHECK(wall.end != ShotEnd::HomeRun);
  CHECK(wall.trajectory.summary.total_m < wall.trajectory.summary.carry_m - 5.0);  // came back off the wall
  // A pop-up stays in the infield and rests there.
  const ShotResult pop = launch("baseball", 70.0, 60.0, 2500.0);
  CHECK(pop.end == ShotEnd::Rest);
  CHECK(pop.trajectory.summary.total_m < 60.0);
}

TEST_CASE("default worlds come from the sport profiles; unknown names list the worlds", "[assets][input]") {
  CHECK(test::assets().sport("golf").default_world == "golf_hole");
  CHECK(test::assets().sport("baseball").default_world == "ballpark");
  CHECK_THROWS_AS(test::assets().sport("cricket"), InputError);
  CHECK_THROWS_WITH(test::assets().world("moon"), Catch::Contains("golf_hole") && Catch::Contains("ballpark"));
  CHECK(test::assets().world("none") == nullptr);
  CHECK(test::assets().world("golf_hole") == test::assets().world("golf_hole"));  // loaded once
}

TEST_CASE("broken world meshes: NaN rejected, zero-area repaired, unknown material named", "[assets][input]") {
  const fs::path dir = fs::temp_directory_path() / "sweetspot_test_world";
  fs::create_directories(dir);
  write(dir / "w.mtl", "newmtl fairway\nKd 0 1 0\nnewmtl lava\nKd 1 0 0\n");
  write(dir / "ok.obj", "mtllib w.mtl\nv 0 0 0\nv 10 0 0\nv 0 0 10\nv 5 0 0\nusemtl fairway\nf 1 3 2\nf 1 4 2\n");
  const auto load = [&](const fs::path& p) { return load_world_asset(dir, p.string(), test::assets().materials()); };
  const WorldAsset ok_asset = load(dir / "ok.obj");
  const WorldDescription& ok = ok_asset.description();
  REQUIRE(ok.meshes.size() == 1);
  CHECK(ok.meshes[0].indices.size() == 3);
  REQUIRE(ok.notes.size() == 1);
  CHECK(ok.notes[0].find("zero-area") != std::string::npos);
  write(dir / "nan.obj", "mtllib w.mtl\nv 0 0 0\nv nan 0 0\nv 0 0 10\nusemtl fairway\nf 1 3 2\n");
  CHECK_THROWS_WITH(load(dir / "nan.obj"), Catch::Contains("nan.obj") && Catch::Contains("finite"));
  write(dir / "lava.obj", "mtllib w.mtl\nv 0 0 0\nv 10 0 0\nv 0 0 10\nusemtl lava\nf 1 3 2\n");
  CHECK_THROWS_WITH(load(dir / "lava.obj"), Catch::Contains("lava") && Catch::Contains("fairway"));
  write(dir / "bad.toml", "name = \"bad\"\nmesh = \"ok.obj\"\nbounds_min = [\"1m\", \"2m\"]\n");
  CHECK_THROWS_WITH(load(dir / "bad.toml"), Catch::Contains("bad.toml:3") && Catch::Contains("bounds_min"));
  fs::remove_all(dir);
}

TEST_CASE("the exact BVH sweep agrees with Bullet's convexSweepTest on the asset worlds", "[assets][world][sweep]") {
  // DESIGN §5 names convexSweepTest; the default narrow phase is the closed-form one. On
  // random sweeps over both worlds (ground, banks, the fence) they must find the same
  // first contact: same hit or miss, and the same place to within Bullet's GJK tolerance
  // (which stops short by up to a few mm on a 30 m sweep; the exact one is checked against
  // a brute-force reference in test_sphere_sweep.cpp).
  for (const char* name : {"golf_hole", "ballpark"}) {
    const WorldDescription& d = test::assets().world(name)->description();
    const World exact(d, SweepMethod::BvhExact);
    const World bullet(d, SweepMethod::BulletConvexSweep);
    std::uint64_t s = 20261123;
    auto uniform = [&s] {
      s = s * 6364136223846793005ULL + 1442695040888963407ULL;
      return static_cast<double>(s >> 11) * 0x1.0p-53;
    };
    int hits = 0, compared = 0, started_touching = 0, edge_hits = 0;
    double worst = 0.0;
    for (int i = 0; i < 3000; ++i) {
      // One draw a statement: the order a constructor's arguments are evaluated in is
      // unspecified (GCC and Clang differ), and the cases must be the same in every build.
      const Vec3 lo = d.bounds_min, hi = d.bounds_max;
      Vec3 from, motion;
      from.x() = lo.x() + (hi.x() - lo.x()) * uniform();
      from.y() = lo.y() + 12.0 * uniform() + 2.0;
      from.z() = lo.z() + (hi.z() - lo.z()) * uniform();
      motion.x() = 60.0 * (uniform() - 0.5);
      motion.y() = -12.0 * uniform() - 4.0;
      motion.z() = 60.0 * (uniform() - 0.5);
      const double r = name[0] == 'g' ? 0.021335 : 0.0366;
      SurfaceContact a, b;
      const bool ha = exact.sweep(from, from + motion, r, &a, nullptr);
      const bool hb = bullet.sweep(from, from + motion, r, &b, nullptr);
      ++compared;
      INFO(name << " sweep " << i << " exact f " << (ha ? a.fraction : -1.0) << " bullet f "
                << (hb ? b.fraction : -1.0) << " n " << (ha ? a.normal.transpose() : b.normal.transpose())
                << " from " << from.transpose() << " motion " << motion.transpose());
      // A sweep that starts already touching a face it moves into is a contact at once
      // here; Bullet's cast (allowed penetration 0) reports nothing there and would let the
      // ball sink. Those starts are counted, not compared.
      if (ha && a.fraction == 0.0) {
        ++started_touching;
        continue;
      }
      REQUIRE(ha == hb);
      if (!ha) continue;
      ++hits;
      // GJK conservative advancement stops a little short (its tolerance); never later.
      const double gap = (a.fraction - b.fraction) * motion.norm();
      worst = std::max(worst, gap);
      CHECK(gap > -1e-9);
      CHECK(gap < 0.01);
      // The exact contact really touches: at the contact the ball is within a nanometre of
      // the world (a sphere 1 nm larger, nudged toward the face, touches it from the start:
      // a sweep with no motion is no sweep) and its centre lies in front of the
      // face, at most one radius from its plane (exactly one on the face, less on an edge or
      // a corner). Bullet's first face agrees unless both lie within its tolerance.
      const Vec3 centre = from + a.fraction * motion;
      SurfaceContact touch;
      CHECK(exact.sweep(centre, centre - 1e-6 * a.normal, r + 1e-9, &touch, nullptr));
      CHECK(touch.fraction == 0.0);
      CHECK(a.normal.dot(centre - a.point) > 0.0);
      CHECK(a.normal.dot(centre - a.point) <= r + 1e-9);
      if (a.normal.dot(centre - a.point) < r - 1e-9) ++edge_hits;
      if (a.normal.dot(b.normal) < 1.0 - 1e-9) CHECK(gap < 0.01);
    }
    UNSCOPED_INFO(name << ": " << hits << " hits of " << compared << " (" << started_touching
                        << " started touching, " << edge_hits << " on an edge or corner), worst contact gap " << worst << " m");
    CHECK(hits > 600);
    CHECK(started_touching < compared / 10);
  }
}
