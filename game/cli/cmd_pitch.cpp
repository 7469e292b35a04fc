// `sweetspot pitch TYPE`: one pitch from the release point to the plate (DESIGN §9 JSON):
// where it crosses, how long it flew, its induced vertical and horizontal break and the
// seam-shifted wake's share of them.
#include <iostream>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "game/cli/command.hpp"
#include "game/report/report.hpp"
#include "game/content/quantity_text.hpp"
#include "game/modes/baseball/pitching.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot::cli {
namespace {

struct PitchOptions {
  std::string type;
  std::string speed, spin;
  bool lefty = false, json = false;
};

RunFn setup_pitch(CLI::App& sub) {
  auto o = std::make_shared<PitchOptions>();
  sub.add_option("type", o->type, "four-seam, sinker, cutter, slider, curveball or changeup")->required();
  sub.add_option("--speed", o->speed, "out-of-hand speed with its unit, e.g. 97mph (default: the league average)");
  sub.add_option("--spin", o->spin, "total spin, e.g. 2500rpm (default: the league average)");
  sub.add_flag("--left", o->lefty, "a left-handed pitcher");
  sub.add_flag("--json", o->json, "print the DESIGN §9 JSON");
  return [o](const Assets& assets) -> int {
    const std::vector<PitchType> types = load_pitch_types(assets);
    PitchCall call;
    call.type = pitch_type(types, o->type);
    call.left_handed = o->lefty;
    if (!o->speed.empty()) call.type.speed = flag_quantity("--speed", o->speed, Dimension::Speed, &PitchType::kSpeed);
    if (!o->spin.empty()) call.type.spin = flag_quantity("--spin", o->spin, Dimension::AngularVelocity, &PitchType::kSpin);
    const PitchFlight f = throw_pitch(assets, call);
    const PitchMovement m = statcast_movement(assets, f);
    if (o->json) {
      const nlohmann::json j = {{"type", call.type.type},
                                {"release_speed_mps", call.type.speed},
                                {"spin_rpm", radps_to_rpm(call.type.spin)},
                                {"flight_time_s", f.flight_time},
                                {"plate_position_m", {f.plate.x(), f.plate.y(), f.plate.z()}},
                                {"induced_vertical_break_m", m.induced_vertical_break},
                                {"horizontal_break_m", m.horizontal_break},
                                {"seam_wake_vertical_m", m.seam_wake_vertical},
                                {"seam_wake_horizontal_m", m.seam_wake_horizontal}};
      std::cout << json_text(j) << "\n";
    } else {
      std::printf("%s (%s-handed)\n  release speed  %.1f mph\n  spin           %.0f rpm\n  flight time    %.3f s\n"
                  "  plate speed    %.1f mph\n  crosses at     %.2f ft high, %+.2f ft (+ first-base side)\n"
                  "  induced vertical break  %+.1f in\n  horizontal break        %+.1f in\n"
                  "    of which seam-shifted wake  %+.1f in up, %+.1f in (+ first-base side)\n",
                  call.type.type.c_str(), o->lefty ? "left" : "right", mps_to_mph(call.type.speed),
                  radps_to_rpm(call.type.spin), f.flight_time, mps_to_mph(f.plate_velocity.norm()), m_to_ft(f.plate.y()),
                  m_to_ft(f.plate.z()), 12.0 * m_to_ft(m.induced_vertical_break), 12.0 * m_to_ft(m.horizontal_break),
                  12.0 * m_to_ft(m.seam_wake_vertical), 12.0 * m_to_ft(m.seam_wake_horizontal));
    }
    return 0;
  };
}

const CommandRegistrar pitch_command{42, "pitch", "throw a pitch type to the plate: flight time, plate crossing, break (§9)", setup_pitch};

}  // namespace
}  // namespace sweetspot::cli
