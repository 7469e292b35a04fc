#include "game/scenario/scenario_air.hpp"

#include "physics/error.hpp"

namespace sweetspot {

Environment environment_from(const CheckedDoc& doc) {
  Environment env;
  env.temperature = doc.quantity("environment.temperature");
  if (auto p = doc.quantity_if_set("environment.pressure")) env.pressure = *p;
  env.altitude = doc.quantity("environment.altitude");
  env.humidity = doc.quantity("environment.humidity");
  env.wind_speed = doc.quantity("environment.wind_speed");
  env.wind_direction = doc.quantity("environment.wind_direction");
  const std::string profile = doc.text("environment.wind_profile");
  env.wind_profile = profile == "power"     ? WindProfile::PowerLaw
                     : profile == "uniform" ? WindProfile::Uniform
                                            : WindProfile::Logarithmic;
  // The schema's ranges sit inside the atmosphere's; this guards against them drifting.
  if (const std::string why = validate_environment(env); !why.empty()) {
    throw InputError(doc.source() + ": environment: " + why);
  }
  return env;
}

const AeroModel& aero_from(const CheckedDoc& doc) {
  if (auto name = doc.text_if_set("aero.model")) {
    try {
      return aero_model(*name);
    } catch (const InputError& e) {
      throw InputError(doc.origin("aero.model") + ": aero.model: " + e.what());
    }
  }
  return default_aero_model(to_string(doc.sport()));
}

}  // namespace sweetspot
