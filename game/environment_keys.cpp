#include "game/environment_keys.hpp"

#include <array>

#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

struct Key {
  const char* name;
  Dimension dim;
  double Environment::*field;
};

constexpr std::array<Key, 9> kKeys{{
    {"temperature", Dimension::Temperature, &Environment::temperature},
    {"pressure", Dimension::Pressure, &Environment::pressure},
    {"altitude", Dimension::Length, &Environment::altitude},
    {"humidity", Dimension::Fraction, &Environment::humidity},
    {"wind_speed", Dimension::Speed, &Environment::wind_speed},
    {"wind_direction", Dimension::Angle, &Environment::wind_direction},
    {"wind_reference_height", Dimension::Length, &Environment::wind_reference_height},
    {"wind_roughness_length", Dimension::Length, &Environment::wind_roughness_length},
    {"wind_power_exponent", Dimension::Dimensionless, &Environment::wind_power_exponent},
}};

}  // namespace

std::string environment_key_names() {
  std::string s;
  for (const Key& k : kKeys) s += std::string(s.empty() ? "" : ", ") + k.name;
  return s + ", wind_profile";
}

void set_environment_key(Environment& env, std::string_view key, std::string_view value) {
  constexpr std::string_view prefix = "environment.";
  if (key.substr(0, prefix.size()) == prefix) key.remove_prefix(prefix.size());
  if (key == "wind_profile") {
    if (value == "log") env.wind_profile = WindProfile::Logarithmic;
    else if (value == "power") env.wind_profile = WindProfile::PowerLaw;
    else if (value == "uniform") env.wind_profile = WindProfile::Uniform;
    else throw InputError("environment.wind_profile = '" + std::string(value) + "' (allowed: log, power, uniform)");
    return;
  }
  for (const Key& k : kKeys) {
    if (key == k.name) {
      try {
        env.*k.field = parse_quantity(value, k.dim);
      } catch (const InputError& e) {
        throw InputError("environment." + std::string(key) + ": " + e.what());
      }
      return;
    }
  }
  throw InputError("unknown key 'environment." + std::string(key) + "' (allowed: environment.{" +
                   environment_key_names() + "})");
}

}  // namespace sweetspot
