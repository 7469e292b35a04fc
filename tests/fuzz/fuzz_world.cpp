// libFuzzer target: a world from raw bytes, the TOML and its OBJ mesh (and material library)
// as a user would hand them over. The input is cut at the first two "\n===\n" markers into
// world.toml, world.obj and world.mtl, written to a private folder and loaded through
// load_world_asset, the path every command takes. A world that loads then catches a chip
// and a putt: each ends in a named reason within the time and step bounds, at a finite
// position, never below the lowest vertex of the mesh. Rejection must be an InputError.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "game/content/world_asset.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/launch.hpp"
#include "physics/units.hpp"
#include "physics/world.hpp"
#include "support/test_assets.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path& folder() {
  static const fs::path dir = [] {
    std::string tmpl = (fs::temp_directory_path() / "sweetspot_fuzz_world_XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) std::abort();
    return fs::path(tmpl);
  }();
  return dir;
}

void put(const fs::path& p, std::string_view bytes) {
  std::ofstream f(p, std::ios::binary | std::ios::trunc);
  f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kCut = "\n===\n";
  const std::size_t a = text.find(kCut);
  const std::size_t b = a == std::string_view::npos ? a : text.find(kCut, a + kCut.size());
  const std::string_view toml = text.substr(0, a);
  const std::string_view obj = a == std::string_view::npos ? std::string_view{} : text.substr(a + kCut.size(), b - a - kCut.size());
  const std::string_view mtl = b == std::string_view::npos ? std::string_view{} : text.substr(b + kCut.size());
  put(folder() / "world.toml", toml);
  put(folder() / "world.obj", obj);
  put(folder() / "world.mtl", mtl);
  try {
    const sweetspot::WorldAsset w =
        sweetspot::load_world_asset(folder(), (folder() / "world.toml").string(), sweetspot::test::assets().materials());
    double lowest = 0.0;
    for (const auto& m : w.description().meshes)
      for (const auto& v : m.vertices) lowest = std::min(lowest, v.y());
    for (const auto& shot : {sweetspot::test::golf_launch(45, 35, 6000), sweetspot::test::golf_launch(8, 0, 0)}) {
      sweetspot::test::FlightCase c = shot;
      c.launch.position = w.description().origin + sweetspot::Vec3(0.0, c.ball.radius, 0.0);
      c.record_samples = false;
      const sweetspot::ShotTrajectory t = sweetspot::test::fly(c, w.world.get());
      const sweetspot::Vec3 p = t.summary.rest_position;
      if (!p.allFinite()) std::abort();
      if (t.summary.end == sweetspot::EndReason::StepLimit) std::abort();
      if (t.summary.end == sweetspot::EndReason::Rest && p.y() < lowest - 0.05) std::abort();  // through the ground
    }
  } catch (const sweetspot::InputError&) {
  }
  return 0;
}
