// Hostile world meshes: truncated, empty, huge or degenerate OBJ files are rejected
// with a message naming the file, or repaired (missing normals, zero-area triangles); a
// world whose ground is missing ends shots out of bounds instead of hanging.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "game/content/gzip_file.hpp"
#include "game/content/mesh_file.hpp"
#include "game/content/world_asset.hpp"
#include "game/core/sport.hpp"
#include "physics/aero.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/launch.hpp"
#include "physics/units.hpp"
#include "physics/world.hpp"
#include "support/test_assets.hpp"

#include <sys/stat.h>

using namespace sweetspot;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path = fs::temp_directory_path() / "sweetspot_hostile_assets";
  TempDir() {
    fs::remove_all(path);
    fs::create_directories(path);
    write("w.mtl", "newmtl fairway\nKd 0 1 0\nnewmtl wall\nKd 1 1 1\n");
  }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream f(path / name, std::ios::binary);
    f << text;
    return (path / name).string();
  }
};

WorldAsset load(const std::string& path) {
  return load_world_asset(fs::temp_directory_path(), path, test::assets().materials());
}

}  // namespace

TEST_CASE("hostile OBJ: empty and truncated files are rejected naming the file", "[assets][input][hostile]") {
  const TempDir dir;
  CHECK_THROWS_WITH(load(dir.write("empty.obj", "")), Catch::Contains("empty.obj"));
  // Cut off mid-vertex, before any face.
  CHECK_THROWS_WITH(load(dir.write("cut.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv 10 0 0\nv 0 0 1")),
                    Catch::Contains("cut.obj"));
  // Cut off after a face that names vertices the file never got to.
  CHECK_THROWS_WITH(load(dir.write("dangling.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv 10 0 0\nf 1 2 3\n")),
                    Catch::Contains("dangling.obj"));
  static const char elf_like[] = "\x7f\x45\x4c\x46\x02\x01\x01\0\0\0 ]]]\xff\xfe";  // binary, NULs inside
  CHECK_THROWS_WITH(load(dir.write("garbage.obj", std::string(elf_like, sizeof elf_like - 1))),
                    Catch::Contains("garbage.obj"));
}

TEST_CASE("hostile OBJ: a short vertex, a stray statement or a face past the vertices is named by its line",
          "[assets][input][hostile]") {
  // The importer says "vertex index out of range" for all of these, naming no line.
  const TempDir dir;
  const std::string head = "mtllib w.mtl\nusemtl fairway\n";
  CHECK_THROWS_WITH(load(dir.write("short.obj", head + "v 0 0 0\nv 1 2\nv 0 0 1\nf 1 2 3\n")),
                    Catch::Contains("short.obj:4") && Catch::Contains("x, y and z") && Catch::Contains("has 2"));
  CHECK_THROWS_WITH(load(dir.write("word.obj", head + "v 0 0 0\nv 1 zero 0\nv 0 0 1\nf 1 2 3\n")),
                    Catch::Contains("word.obj:4") && Catch::Contains("'zero' is not a number"));
  CHECK_THROWS_WITH(load(dir.write("vx.obj", head + "v 0 0 0\nvx 1 0 0\nv 0 0 1\nf 1 2 3\n")),
                    Catch::Contains("vx.obj:4") && Catch::Contains("unknown statement 'vx'"));
  CHECK_THROWS_WITH(load(dir.write("past.obj", head + "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 0 1\n")),
                    Catch::Contains("past.obj:5") && Catch::Contains("corner 3 refers to vertex 3") &&
                        Catch::Contains("2 vertices are defined before"));
  CHECK_THROWS_WITH(load(dir.write("zero.obj", head + "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 0 1 2\n")),
                    Catch::Contains("zero.obj:6") && Catch::Contains("corner 1 '0'"));
  // What OBJ allows still loads: texture and normal indices, negative (relative) indices,
  // a fourth coordinate.
  const WorldAsset ok = load(dir.write("ok.obj", head + "v -10 0 -10 1\nv 10 0 -10\nv 10 0 10\nvn 0 1 0\nvt 0 0\n"
                                                        "f -1/1/1 -2/1/1 -3/1/1\n"));
  CHECK(ok.world->collision_triangles() == 1);
}

TEST_CASE("hostile OBJ: degenerate and non-finite geometry", "[assets][input][hostile]") {
  const TempDir dir;
  // Only zero-area triangles: nothing to stand on -> rejected, not an empty world.
  CHECK_THROWS_WITH(load(dir.write("flat.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 1\n")),
                    Catch::Contains("flat.obj") && Catch::Contains("no collidable triangles"));
  CHECK_THROWS_WITH(load(dir.write("inf.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv inf 0 0\nv 0 0 10\nf 1 3 2\n")),
                    Catch::Contains("inf.obj") && Catch::Contains("finite"));
  // Huge coordinates: refused with the limit, before Bullet sees them.
  CHECK_THROWS_WITH(load(dir.write("far.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv 1e30 0 0\nv 0 0 10\nf 1 3 2\n")),
                    Catch::Contains("far.obj") && Catch::Contains("100000 m"));
  // No normals (no vn lines, faces without //n): repaired, normals come from the winding.
  const WorldAsset asset = load(dir.write(
      "nonormals.obj", "mtllib w.mtl\nusemtl fairway\nv -100 0 -100\nv 300 0 -100\nv 300 0 100\nv -100 0 100\nf 1 4 3\nf 1 3 2\n"));
  REQUIRE(asset.description().meshes.size() == 1);
  const World& world = *asset.world;
  SurfaceContact under;
  REQUIRE(world.support(Vec3(50.0, 0.03, 0.0), 0.021335, 0.05, &under));
  CHECK(under.normal.y() == Approx(1.0));
}

TEST_CASE("hostile OBJ: a huge file is refused by size before it is read", "[assets][input][hostile]") {
  const TempDir dir;
  const fs::path p = dir.path / "huge.obj";
  {
    std::ofstream f(p, std::ios::binary);
    f << "mtllib w.mtl\n";
  }
  // A sparse file: the size check must refuse it without assimp reading 300 MiB.
  fs::resize_file(p, kMaxWorldMeshBytes + 1);
  CHECK_THROWS_WITH(load(p.string()), Catch::Contains("huge.obj") && Catch::Contains("over the limit"));
}

TEST_CASE("hostile world: only a far wall, no ground under the shot -> left the world, bounded", "[assets][world][hostile]") {
  const TempDir dir;
  const WorldAsset asset = load(dir.write(
      "noground.obj", "mtllib w.mtl\nusemtl wall\nv 2000 -5 -10\nv 2000 -5 10\nv 2000 5 10\nv 2000 5 -10\nf 1 2 3\nf 1 3 4\n"));
  const test::FlightCase in = test::golf_launch(167.1, 10.9, 2686);
  const ShotTrajectory t = test::fly(in, asset.world.get());
  CHECK(t.summary.end == EndReason::LeftWorld);
  CHECK(t.stats.flight_steps + t.stats.roll_steps < in.settings.max_steps);
  CHECK(t.summary.total_time_s < in.settings.max_time);
}

TEST_CASE("hostile files: a FIFO, a device or a directory is refused before reading", "[assets][input][hostile]") {
  const TempDir dir;
  const fs::path fifo = dir.path / "pipe.obj";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(load(fifo.string()), Catch::Contains("pipe.obj") && Catch::Contains("not a regular file"));
  CHECK_THROWS_WITH(load("/dev/zero"), Catch::Contains("/dev/zero") && Catch::Contains("not a regular file"));
  CHECK_THROWS_WITH(load(dir.path.string() + "/"), Catch::Contains("directory"));
  // A material library that is a FIFO would block assimp forever: refused, naming it.
  const fs::path mtl_fifo = dir.path / "pipe.mtl";
  REQUIRE(::mkfifo(mtl_fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(load(dir.write("usespipe.obj", "mtllib pipe.mtl\nusemtl fairway\nv 0 0 0\nv 10 0 0\nv 0 0 10\nf 1 3 2\n")),
                    Catch::Contains("pipe.mtl") && Catch::Contains("not a regular file"));
}

namespace {
// A V-shaped ditch along z at x = 30 m: the ground falls from y = 0 at x = 0 to -depth at the
// crease and rises again to y = 0 at x = 60 m (a ditch a ball could fall through).
std::string v_ditch(double depth, double half_width = 30.0) {
  const double a = 30.0 - half_width, b = 30.0 + half_width;
  std::string s = "mtllib w.mtl\nusemtl fairway\n";
  const auto v = [&](double x, double y, double z) {
    s += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  };
  v(-20, 0, -40), v(-20, 0, 40), v(a, 0, 40), v(a, 0, -40);               // 1-4: flat before
  v(30, -depth, -40), v(30, -depth, 40);                                // 5-6: the crease
  v(b, 0, -40), v(b, 0, 40), v(200, 0, 40), v(200, 0, -40);              // 7-10: flat after
  s += "f 1 2 3\nf 1 3 4\nf 4 3 6\nf 4 6 5\nf 5 6 8\nf 5 8 7\nf 7 8 9\nf 7 9 10\n";
  return s;
}
double ditch_floor(double x, double depth, double half_width) {
  const double d = std::abs(x - 30.0);
  return d >= half_width ? 0.0 : -depth * (1.0 - d / half_width);
}
}  // namespace

TEST_CASE("hostile world: a ball in a V-shaped crease comes to rest in it, above the ground", "[assets][world][hostile]") {
  const TempDir dir;
  // Gentle to knife-edge creases; chips that land in them, putts that roll in, a drive over.
  struct Case { double depth, half_width, mph, launch_deg, rpm; };
  for (const Case c : {Case{1.0, 30.0, 50, 30, 5000}, Case{3.0, 6.0, 45, 35, 6000}, Case{5.0, 2.0, 45, 35, 6000},
                       Case{8.0, 1.0, 43, 40, 7000}, Case{2.0, 0.3, 45, 35, 6000}, Case{1.0, 30.0, 10, 1, 0},
                       Case{3.0, 6.0, 20, 2, 0}, Case{5.0, 2.0, 75, 25, 7500}}) {
    const WorldAsset asset = load(dir.write("ditch.obj", v_ditch(c.depth, c.half_width)));
    const test::FlightCase in = test::golf_launch(c.mph, c.launch_deg, c.rpm);
    const ShotTrajectory t = test::fly(in, asset.world.get());
    const Vec3 p = t.summary.rest_position;
    INFO("depth " << c.depth << " m, half width " << c.half_width << " m, " << c.mph << " mph: end "
                  << to_string(t.summary.end) << " at " << p.transpose() << ", " << t.summary.bounces << " bounces, "
                  << t.stats.flight_steps + t.stats.roll_steps << " steps");
    CHECK(t.summary.end == EndReason::Rest);
    // Above the ground everywhere along the path (1 mm of contact slop).
    for (const auto& s : t.samples) {
      if (s.position.x() < -20.0 || s.position.x() > 200.0) continue;
      const double floor = ditch_floor(s.position.x(), c.depth, c.half_width);
      if (s.position.y() < floor - 1e-3) {
        FAIL_CHECK("below the ground at t = " << s.t << " s: y " << s.position.y() << " < floor " << floor);
        break;
      }
    }
    CHECK(t.stats.flight_steps + t.stats.roll_steps < in.settings.max_steps / 2);
    CHECK(t.summary.bounces < 100);
  }
}

TEST_CASE("hostile world: a ball running along a steep trough rolls in it and rests, not 200 000 bounces", "[assets][world][hostile]") {
  // A trough along the line of play (x): walls from z = -w to the floor line at z = 0,
  // depth h (5 m deep with a 1 m half-width: 79 deg walls), flat ground before.
  const TempDir dir;
  for (const double h : {5.0, 10.0, 0.5}) {
    const double w = h == 10.0 ? 10.0 : 1.0;
    std::string obj = "mtllib w.mtl\nusemtl fairway\n";
    for (const double x : {-30.0, 0.0, 20.0, 450.0})
      for (const double z : {-70.0, -w, 0.0, w, 70.0})
        obj += "v " + std::to_string(x) + " " + (z == 0.0 && x >= 20.0 ? std::to_string(-h) : "0") + " " + std::to_string(z) + "\n";
    // Quads (as triangles) between rows of 5 vertices, winding up.
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 4; ++col) {
        const int a = row * 5 + col + 1, b = a + 1, c = a + 6, d = a + 5;
        obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\nf " + std::to_string(a) +
               " " + std::to_string(c) + " " + std::to_string(d) + "\n";
      }
    const WorldAsset asset = load(dir.write("trough.obj", obj));
    for (const auto& shot : {test::golf_launch(10, 0, 0), test::golf_launch(167.1, 10.9, 2686), test::golf_launch(60, 30, 6000)}) {
      const ShotTrajectory t = test::fly(shot, asset.world.get());
      const Vec3 p = t.summary.rest_position;
      INFO("depth " << h << " m: end " << to_string(t.summary.end) << " at " << p.transpose() << " after "
                    << t.summary.bounces << " bounces");
      CHECK(t.summary.end == EndReason::Rest);
      CHECK(p.y() > -h);  // above the trough's floor
      CHECK(t.summary.bounces < 100);
    }
  }
}

TEST_CASE("hostile OBJ: a NaN corner of a quad is refused, not triangulated away", "[assets][input][hostile]") {
  // Triangulated, the corner and its triangles are dropped by assimp, leaving a hole in the
  // ground with only a note about a zero-area triangle.
  const TempDir dir;
  const std::string obj = dir.write("nanquad.obj", "mtllib w.mtl\nusemtl fairway\nv -30 0 -70\nv -30 0 70\nv 450 nan 70\n"
                                                   "v 450 0 -70\nf 1 2 3 4\n");
  CHECK_THROWS_WITH(load(obj), Catch::Contains("nanquad.obj") && Catch::Contains("not a finite number"));
}

TEST_CASE("hostile OBJ: a polygon of more than kMaxFaceCorners corners is refused before triangulating",
          "[assets][input][hostile]") {
  // One 100 000-corner face keeps assimp's triangulation busy past the importer's 120 s
  // limit. The corner count is checked first; 256 corners still load.
  const TempDir dir;
  const auto polygon = [&](const std::string& name, unsigned corners) {
    std::string text = "mtllib w.mtl\nusemtl fairway\n";
    for (unsigned i = 0; i < corners; ++i) {
      const double a = 2.0 * kPi * i / corners;
      // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
      text += "v ";
      text += std::to_string(100.0 * std::cos(a));
      text += " 0 ";
      text += std::to_string(-100.0 * std::sin(a));
      text += '\n';
    }
    text += "f";
    for (unsigned i = 1; i <= corners; ++i) {
      text += ' ';
      text += std::to_string(i);
    }
    return dir.write(name, text + "\n");
  };
  CHECK_THROWS_WITH(load(polygon("many.obj", kMaxFaceCorners + 1)),
                    Catch::Contains("many.obj") && Catch::Contains("257 corners") && Catch::Contains("at most 256"));
  const WorldAsset ok = load(polygon("ok.obj", kMaxFaceCorners));
  CHECK(ok.world->collision_triangles() == static_cast<int>(kMaxFaceCorners) - 2);
}

TEST_CASE("hostile world TOML: coordinates beyond the world limit and an unknown sport are refused at their line",
          "[assets][input][hostile]") {
  const TempDir dir;
  dir.write("g.obj", "mtllib w.mtl\nusemtl fairway\nv -30 0 -70\nv -30 0 70\nv 450 0 70\nf 1 2 3\n");
  CHECK_THROWS_WITH(load(dir.write("pin.toml", "mesh = \"g.obj\"\npin = [\"1e300m\", \"0m\", \"0m\"]\n")),
                    Catch::Contains("pin.toml:2") && Catch::Contains("out of range"));
  CHECK_THROWS_WITH(load(dir.write("box.toml", "mesh = \"g.obj\"\nbounds_min = [\"-1e15m\", \"-10m\", \"-70m\"]\n")),
                    Catch::Contains("box.toml:2") && Catch::Contains("bounds_min"));
  CHECK_THROWS_WITH(load(dir.write("fence.toml", "mesh = \"g.obj\"\nfence_line = [[\"0m\", \"0m\"], [\"1e9m\", \"0m\"]]\n")),
                    Catch::Contains("fence.toml:2") && Catch::Contains("fence_line"));
  // Within the coordinate limit but off the world: a home run no ball could reach.
  CHECK_THROWS_WITH(load(dir.write("far.toml", "mesh = \"g.obj\"\nfence_line = [[\"0m\", \"0m\"],\n  [\"1e5m\", \"0m\"]]\n")),
                    Catch::Contains("far.toml:3") && Catch::Contains("fence_line") && Catch::Contains("point 1") &&
                        Catch::Contains("outside the world"));
  const SportCatalog& sports = test::assets().sports();
  CHECK_THROWS_WITH(load_world_asset(fs::temp_directory_path(), dir.write("tennis.toml", "sport = \"tennis\"\nmesh = \"g.obj\"\n"),
                                     test::assets().materials(), &sports),
                    Catch::Contains("tennis.toml:1") && Catch::Contains("unknown sport 'tennis'"));
  CHECK_NOTHROW(load_world_asset(fs::temp_directory_path(), dir.write("golf.toml", "sport = \"golf\"\nmesh = \"g.obj\"\n"),
                                 test::assets().materials(), &sports));
}

TEST_CASE("gzipped world meshes: read as the OBJ they hold; corrupt, truncated or bomb data refused naming the file",
          "[assets][input][hostile]") {
  const TempDir dir;
  const std::string obj = "mtllib w.mtl\nusemtl fairway\nv -50 0 -50\nv 50 0 -50\nv 50 0 50\nv -50 0 50\nf 1 3 2\nf 1 4 3\n";
  const std::string packed = gzip_bytes(obj);
  const WorldAsset plain = load(dir.write("plain.obj", obj));
  const WorldAsset zipped = load(dir.write("zipped.obj.gz", packed));
  REQUIRE(zipped.description().meshes.size() == plain.description().meshes.size());
  CHECK(zipped.description().meshes[0].vertices == plain.description().meshes[0].vertices);
  CHECK(zipped.description().name == "zipped");
  // A line error is named by the .gz file and the line of the text inside it.
  CHECK_THROWS_WITH(load(dir.write("short.obj.gz", gzip_bytes("v 0 0 0\nv 1 0\n"))),
                    Catch::Contains("short.obj.gz:2") && Catch::Contains("needs x, y and z"));
  CHECK_THROWS_WITH(load(dir.write("garbage.obj.gz", obj)), Catch::Contains("garbage.obj.gz") && Catch::Contains("not gzip"));
  CHECK_THROWS_WITH(load(dir.write("cut.obj.gz", packed.substr(0, packed.size() / 2))),
                    Catch::Contains("cut.obj.gz") && Catch::Contains("truncated"));
  // Zeros compress ~1000:1: a small file that inflates past the limit is refused as it passes
  // it (the world loader's limit is kMaxWorldMeshBytes; a smaller one here keeps the test fast).
  const std::string bomb = gzip_bytes(std::string(std::size_t{4} << 20, '\0'));
  CHECK(bomb.size() < (std::size_t{64} << 10));
  CHECK_THROWS_WITH(read_gzip_file(dir.write("bomb.obj.gz", bomb), "world mesh", std::uintmax_t{1} << 20),
                    Catch::Contains("bomb.obj.gz") && Catch::Contains("inflates to more than 1048576"));
}
