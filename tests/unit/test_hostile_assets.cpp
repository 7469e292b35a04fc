// Hostile world meshes (issue 9): truncated, empty, huge or degenerate OBJ files are rejected
// with a message naming the file, or repaired (missing normals, zero-area triangles); a
// world whose ground is missing ends shots out of bounds instead of hanging.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "game/assets/assets.hpp"
#include "physics/aero.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/launch.hpp"
#include "physics/units.hpp"
#include "physics/world.hpp"

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

FlightInput golf_drive() {
  FlightInput in;
  in.aero = &aero_model("ferguson2022");
  in.ball = golf_ball_properties();
  in.launch = launch_from_metrics(74.7, deg_to_rad(10.9), 0.0, rpm_to_radps(2686), 0.0, Vec3(0.0, in.ball.radius, 0.0));
  return in;
}

}  // namespace

TEST_CASE("hostile OBJ: empty and truncated files are rejected naming the file", "[assets][input][hostile]") {
  const TempDir dir;
  CHECK_THROWS_WITH(load_world(dir.write("empty.obj", "")), Catch::Contains("empty.obj"));
  // Cut off mid-vertex, before any face.
  CHECK_THROWS_WITH(load_world(dir.write("cut.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv 10 0 0\nv 0 0 1")),
                    Catch::Contains("cut.obj"));
  // Cut off after a face that names vertices the file never got to.
  CHECK_THROWS_WITH(load_world(dir.write("dangling.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv 10 0 0\nf 1 2 3\n")),
                    Catch::Contains("dangling.obj"));
  static const char elf_like[] = "\x7f\x45\x4c\x46\x02\x01\x01\0\0\0 ]]]\xff\xfe";  // binary, NULs inside
  CHECK_THROWS_WITH(load_world(dir.write("garbage.obj", std::string(elf_like, sizeof elf_like - 1))),
                    Catch::Contains("garbage.obj"));
}

TEST_CASE("hostile OBJ: degenerate and non-finite geometry", "[assets][input][hostile]") {
  const TempDir dir;
  // Only zero-area triangles: nothing to stand on -> rejected, not an empty world.
  CHECK_THROWS_WITH(load_world(dir.write("flat.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 1\n")),
                    Catch::Contains("flat.obj") && Catch::Contains("no triangles"));
  CHECK_THROWS_WITH(load_world(dir.write("inf.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv inf 0 0\nv 0 0 10\nf 1 3 2\n")),
                    Catch::Contains("inf.obj") && Catch::Contains("finite"));
  // Huge coordinates: refused with the limit, before Bullet sees them.
  CHECK_THROWS_WITH(load_world(dir.write("far.obj", "mtllib w.mtl\nusemtl fairway\nv 0 0 0\nv 1e30 0 0\nv 0 0 10\nf 1 3 2\n")),
                    Catch::Contains("far.obj") && Catch::Contains("100000 m"));
  // No normals (no vn lines, faces without //n): repaired, normals come from the winding.
  const WorldDescription d = load_world(dir.write(
      "nonormals.obj", "mtllib w.mtl\nusemtl fairway\nv -100 0 -100\nv 300 0 -100\nv 300 0 100\nv -100 0 100\nf 1 4 3\nf 1 3 2\n"));
  REQUIRE(d.meshes.size() == 1);
  const World world(d);
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
  CHECK_THROWS_WITH(load_world(p.string()), Catch::Contains("huge.obj") && Catch::Contains("MiB"));
}

TEST_CASE("hostile world: only a far wall, no ground under the shot -> out of bounds, bounded", "[assets][world][hostile]") {
  const TempDir dir;
  const WorldDescription d = load_world(dir.write(
      "noground.obj", "mtllib w.mtl\nusemtl wall\nv 2000 -5 -10\nv 2000 -5 10\nv 2000 5 10\nv 2000 5 -10\nf 1 2 3\nf 1 3 4\n"));
  const World world(d);
  FlightInput in = golf_drive();
  FlightStats st;
  const ShotTrajectory t = simulate_shot(in, &world, &st);
  CHECK(t.summary.end == EndReason::OutOfBounds);
  CHECK(st.flight_steps + st.roll_steps < in.settings.max_steps);
  CHECK(t.summary.total_time_s < in.settings.max_time);
}
