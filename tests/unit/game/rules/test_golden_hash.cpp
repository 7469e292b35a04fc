// Determinism: a golden FNV-1a 64 hash of the state bytes of a fixed set of built-in shots
// of both sports, full flight on the asset worlds: the launch state, the final ShotState
// (time, position, velocity, spin) and the summary's numbers, as raw IEEE-754 doubles.
// Hashing state bytes rather than printed JSON (as Box2D hashes its transforms) catches a
// change in the last bit that a printed number could round away, and it does not change
// when a report's formatting does. CI runs this in the Release build and again in the
// ASan+UBSan build (`ctest -L unit` in build/fuzz, clang), so a hash that differs between
// optimisation levels or under the sanitizers fails there.
//
// What legitimately changes the hash: any change to the physics or models (impact solver,
// delivery, aero, atmosphere, flight integrator or its tolerances, bounce/roll, world
// collision), to equipment data (assets/equipment), worlds (assets/worlds, materials.toml),
// the built-in scenarios listed below, or a compiler / libm / Eigen / Bullet build that
// rounds differently (FMA contraction, -march flags, -ffast-math). An unexplained change is
// a bug.
//
// To update after an intended change: run `build/release/tests/unit_tests "[golden]" -s`,
// which prints the new hash and each shot's numbers; review them against the old ones, then
// replace kGoldenHash and say why in the commit message.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "game/content/scenario.hpp"
#include "support/test_assets.hpp"
#include "game/rules/run_shot.hpp"

namespace {

std::uint64_t fnv1a64(const void* data, std::size_t n, std::uint64_t h) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= bytes[i];
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::uint64_t hash_doubles(std::initializer_list<double> values, std::uint64_t h) {
  for (const double v : values) h = fnv1a64(&v, sizeof v, h);
  return h;
}

constexpr std::uint64_t kGoldenHash = 0xd287360afc9f1746ULL;

}  // namespace

TEST_CASE("golden hash of the state bytes of fixed built-in shots", "[golden][determinism]") {
  using namespace sweetspot;
  const char* const names[] = {"golf/driver", "golf/7-iron", "golf/heel-slice", "golf/toe-hook", "golf/into-wind",
                               "baseball/line-drive", "baseball/home-run", "baseball/pop-up"};
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char* name : names) {
    const Scenario s = load_scenario(test::assets(), name, {});
    const ShotResult r = run_scenario(s, RunOptions{true, false});
    const LaunchState& L = r.launch_state;
    const ShotState& f = r.final_state;
    const FlightSummary& m = r.trajectory.summary;
    h = hash_doubles({L.position.x(), L.position.y(), L.position.z(), L.velocity.x(), L.velocity.y(),
                      L.velocity.z(), L.spin.x(), L.spin.y(), L.spin.z()},
                     h);
    h = fnv1a64(f.y.data(), sizeof(double) * 9, h);
    h = hash_doubles({f.t, m.carry_m, m.total_m, m.apex_m, m.landing_angle_deg, m.hang_time_s}, h);
    h = hash_doubles({static_cast<double>(r.end), static_cast<double>(m.bounces)}, h);
    INFO(name << ": carry " << m.carry_m << " total " << m.total_m << " apex " << m.apex_m << " end "
              << to_string(r.end) << " t " << f.t);
  }
  char hex[19];
  std::snprintf(hex, sizeof hex, "0x%016llx", static_cast<unsigned long long>(h));
  UNSCOPED_INFO("golden hash " << hex);
  CHECK(h == kGoldenHash);
}
