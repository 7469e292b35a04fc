#include "physics/atmosphere.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

constexpr double kSeaLevelPressure = 101325.0;  // Pa
constexpr double kSeaLevelTemperature = 288.15; // K, ISA
constexpr double kLapseRate = 0.0065;           // K/m, ISA troposphere
// g M / (R L) for dry air: 9.80665 · 0.0289644 / (8.31446 · 0.0065)
constexpr double kBarometricExponent = 5.25588;
constexpr double kGasConstantDryAir = 287.058;  // J/(kg·K)
constexpr double kGasConstantVapour = 461.495;  // J/(kg·K)

}  // namespace

const char* to_string(WindProfile p) {
  switch (p) {
    case WindProfile::Logarithmic: return "log";
    case WindProfile::PowerLaw: return "power";
    case WindProfile::Uniform: return "uniform";
  }
  return "?";
}

std::string validate_environment(const Environment& e) {
  const auto bad = [](const char* field, double v, const Range& r, const char* unit) {
    return range_refusal(std::string("environment.") + field, v, r, unit);
  };
  if (auto w = bad("temperature", e.temperature, Environment::kTemperature, "K"); !w.empty()) return w;
  if (e.pressure != 0.0) {
    if (auto w = bad("pressure", e.pressure, Environment::kPressure, "Pa"); !w.empty()) return w + " (or unset: from altitude)";
  }
  if (auto w = bad("altitude", e.altitude, Environment::kAltitude, "m"); !w.empty()) return w;
  if (auto w = bad("humidity", e.humidity, Environment::kHumidity, ""); !w.empty()) return w;
  if (auto w = bad("wind_speed", e.wind_speed, Environment::kWindSpeed, "m/s"); !w.empty()) return w;
  if (auto w = bad("wind_direction", e.wind_direction, Environment::kWindDirection, "rad"); !w.empty()) return w;
  if (auto w = bad("wind_reference_height", e.wind_reference_height, Environment::kWindReferenceHeight, "m");
      !w.empty())
    return w;
  if (auto w = bad("wind_roughness_length", e.wind_roughness_length, Environment::kWindRoughnessLength, "m");
      !w.empty())
    return w;
  if (auto w = bad("wind_roughness_length (at most wind_reference_height / 10 for the log law)",
                   e.wind_roughness_length, Range{Environment::kWindRoughnessLength.min, e.wind_reference_height / 10.0}, "m");
      !w.empty())
    return w;
  if (auto w = bad("wind_power_exponent", e.wind_power_exponent, Environment::kWindPowerExponent, ""); !w.empty())
    return w;
  // Hurricane force is a wind at 10 m: a wind given at another height is held to it there.
  const double at10 = beaufort_wind(e);
  if (at10 > Environment::kHurricaneWind * (1.0 + 1e-12)) {
    std::ostringstream s;
    s << "environment.wind_speed = " << e.wind_speed << " m/s at wind_reference_height " << e.wind_reference_height
      << " m is " << at10 << " m/s at 10 m: past hurricane force (allowed up to " << Environment::kHurricaneWind
      << " m/s at 10 m, Beaufort 12)";
    return s.str();
  }
  return {};
}

void check_environment(const Environment& env) {
  const std::string why = validate_environment(env);
  if (!why.empty()) throw InputError(why);
}

double standard_pressure(double altitude) {
  return kSeaLevelPressure *
         std::pow(1.0 - kLapseRate * altitude / kSeaLevelTemperature, kBarometricExponent);
}

double station_pressure(const Environment& env) {
  return env.pressure > 0.0 ? env.pressure : standard_pressure(env.altitude);
}

double saturation_vapour_pressure(double t) {
  const double c = t - 273.15;
  return 611.21 * std::exp((18.678 - c / 234.5) * (c / (257.14 + c)));
}

double air_density(const Environment& env) {
  const double p = station_pressure(env);
  const double pv = env.humidity * saturation_vapour_pressure(env.temperature);
  const double pd = p - pv;
  return pd / (kGasConstantDryAir * env.temperature) + pv / (kGasConstantVapour * env.temperature);
}

double air_viscosity(double t) { return 1.458e-6 * t * std::sqrt(t) / (t + 110.4); }

Vec3 wind_at(const Environment& env, double height) { return wind_at(env, height, env.wind_profile); }

Vec3 wind_at(const Environment& env, double height, WindProfile profile) {
  if (env.wind_speed == 0.0) return Vec3::Zero();
  height = std::min(height, kSurfaceLayerTop);
  double speed = env.wind_speed;
  switch (profile) {
    case WindProfile::Uniform: break;
    case WindProfile::Logarithmic: {
      const double z0 = env.wind_roughness_length;
      // Below the roughness length the log law has no meaning: the air is still.
      speed = height <= z0 ? 0.0
                           : env.wind_speed * std::log(height / z0) /
                                 std::log(env.wind_reference_height / z0);
      break;
    }
    case WindProfile::PowerLaw:
      speed = height <= 0.0 ? 0.0
                            : env.wind_speed *
                                  std::pow(height / env.wind_reference_height, env.wind_power_exponent);
      break;
  }
  return speed * Vec3(std::cos(env.wind_direction), 0.0, std::sin(env.wind_direction));
}

}  // namespace sweetspot
