// Hostile world meshes (issue 9): truncated, empty, huge or degenerate OBJ files are rejected
// with a message naming the file, or repaired (missing normals, zero-area triangles); a
// world whose ground is missing ends shots out of bounds instead of hanging.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "game/content/world_asset.hpp"
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
