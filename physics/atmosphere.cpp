#include "physics/atmosphere.hpp"

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

std::string range_error(const char* field, double value, const char* range) {
  std::ostringstream s;
  s << "environment." << field << " = " << value << " is out of range (allowed " << range << ")";
  return s.str();
}

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
  // The negated comparisons also reject NaN.
  if (!(e.temperature >= 223.15 && e.temperature <= 333.15))
    return range_error("temperature", e.temperature, "223.15..333.15 K, i.e. -50..60 C");
  if (!(e.pressure == 0.0 || (e.pressure >= 30000.0 && e.pressure <= 110000.0)))
    return range_error("pressure", e.pressure, "0 (from altitude) or 30000..110000 Pa");
  if (!(e.altitude >= -500.0 && e.altitude <= 6000.0))
    return range_error("altitude", e.altitude, "-500..6000 m");
  if (!(e.humidity >= 0.0 && e.humidity <= 1.0))
    return range_error("humidity", e.humidity, "0..1 (0..100%)");
  if (!(e.wind_speed >= 0.0 && e.wind_speed <= 60.0))
    return range_error("wind_speed", e.wind_speed, "0..60 m/s");
  if (!std::isfinite(e.wind_direction))
    return range_error("wind_direction", e.wind_direction, "a finite angle");
  if (!(e.wind_reference_height >= 0.5 && e.wind_reference_height <= 100.0))
    return range_error("wind_reference_height", e.wind_reference_height, "0.5..100 m");
  if (!(e.wind_roughness_length >= 1e-4 && e.wind_roughness_length <= 1.0 &&
        e.wind_roughness_length < e.wind_reference_height))
    return range_error("wind_roughness_length", e.wind_roughness_length,
                       "1e-4..1 m and below wind_reference_height");
  if (!(e.wind_power_exponent >= 0.0 && e.wind_power_exponent <= 1.0))
    return range_error("wind_power_exponent", e.wind_power_exponent, "0..1");
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

Vec3 wind_at(const Environment& env, double height) {
  if (env.wind_speed == 0.0) return Vec3::Zero();
  double speed = env.wind_speed;
  switch (env.wind_profile) {
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
