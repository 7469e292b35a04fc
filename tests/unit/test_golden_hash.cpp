// Determinism: a golden FNV-1a 64 hash of the DESIGN §6 JSON (`shot --json`) of a fixed set
// of built-in shots of both sports, full flight on the asset worlds. CI runs this in the
// Release build and again in the ASan+UBSan build (`ctest -L unit` in build/asan), so a
// hash that differs between optimisation levels or under the sanitizers fails there.
//
// What legitimately changes the hash: any change to the physics or models (impact solver,
// delivery, aero, atmosphere, flight integrator or its tolerances, bounce/roll, world
// collision), to equipment data (assets/equipment), worlds (assets/worlds, materials.toml),
// the built-in scenarios listed below, the JSON keys or their formatting (game/report), or
// a different compiler / libm / Eigen / Bullet build that rounds differently (e.g. FMA
// contraction, -march flags, -ffast-math). An unexplained change is a bug.
//
// To update after an intended change: run `build/release/tests/unit_tests "[golden]" -s`,
// which prints the new hash and each shot's JSON; review the JSON diff against the old
// numbers, then replace kGoldenHash and say why in the commit message.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "game/scenario/scenario.hpp"

namespace {

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t h = 0xcbf29ce484222325ULL) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

constexpr std::uint64_t kGoldenHash = 0x63b5a773493afb15ULL;

}  // namespace

TEST_CASE("golden hash of the shot JSON of fixed built-in shots", "[golden][determinism]") {
  const char* const names[] = {"golf/driver", "golf/7-iron", "golf/heel-slice", "golf/toe-hook", "golf/into-wind",
                               "baseball/line-drive", "baseball/home-run", "baseball/pop-up"};
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char* name : names) {
    const auto s = sweetspot::load_scenario(name, {});
    const std::string text = sweetspot::shot_json(sweetspot::run_scenario(s), s).dump();
    INFO(name << ": " << text);
    h = fnv1a64(text, h);
    h = fnv1a64("\n", h);
  }
  char hex[19];
  std::snprintf(hex, sizeof hex, "0x%016llx", static_cast<unsigned long long>(h));
  UNSCOPED_INFO("golden hash " << hex);
  CHECK(h == kGoldenHash);
}
