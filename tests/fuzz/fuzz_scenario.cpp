// libFuzzer target: the scenario loader from raw bytes. The bytes are a TOML scenario
// document; it is parsed (parse_toml_doc), validated and resolved (scenario_from_doc), then
// delivered to a launch without the flight (run_scenario with fly = false) so every input
// stays fast. Rejection must be an InputError; any other exception, a crash, a hang, or a
// NaN/inf anywhere in the launch is a finding (abort), and its input is kept in
// tests/fuzz/corpus/scenario/ with a unit test reproducing it.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "game/content/scenario.hpp"
#include "support/test_assets.hpp"
#include "game/content/scenario_doc.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace {

void require_finite(double v) {
  if (!std::isfinite(v)) std::abort();
}

void require_finite(const sweetspot::Vec3& v) {
  for (int i = 0; i < 3; ++i) require_finite(v[i]);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const sweetspot::ScenarioDoc doc = sweetspot::parse_toml_doc(text, "fuzz.toml");
    const sweetspot::Scenario s = sweetspot::scenario_from_doc(sweetspot::test::assets(), doc, "fuzz");
    sweetspot::RunOptions options;
    options.fly = false;
    const sweetspot::ShotResult r = sweetspot::run_scenario(s, options);
    require_finite(r.launch_state.position);
    require_finite(r.launch_state.velocity);
    require_finite(r.launch_state.spin);
    require_finite(r.launch.ball_speed);
    require_finite(r.launch.vertical_angle);
    require_finite(r.launch.horizontal_angle);
    require_finite(r.smash_factor);
    require_finite(r.impact.normal_impulse);
    require_finite(r.impact.tangential_impulse);
    require_finite(r.impact.energy_loss);
  } catch (const sweetspot::InputError&) {
    // A clear rejection: the only acceptable way to refuse bytes.
  }
  return 0;
}
