// `environment.KEY=VALUE` settings (CLI --set, scenario files): one table of keys, their
// units and the Environment field each sets, so the CLI and scenarios accept the same names.
#pragma once

#include <string>
#include <string_view>

#include "physics/atmosphere.hpp"

namespace sweetspot {

/// Sets one Environment field from text with units, e.g. ("temperature", "90F"),
/// ("altitude", "1600m"), ("wind_speed", "10mph"), ("wind_direction", "180deg"),
/// ("humidity", "30%"), ("wind_profile", "log"). `key` may carry the "environment." prefix.
/// Throws InputError naming the key and the accepted keys/units; the value's range is
/// checked by validate_environment() after all keys are applied.
void set_environment_key(Environment& env, std::string_view key, std::string_view value);

/// "temperature, pressure, altitude, ..." for help texts and error messages.
std::string environment_key_names();

}  // namespace sweetspot
