// The air the ball flies through: density from temperature, pressure (or altitude through
// the standard atmosphere) and humidity, and wind that grows with height over the ground.
//
// Environment is an immutable parameter set (SI). validate_environment() is called once
// where the values enter (scenario, CLI); air_density() and wind_at() are hot-path and
// assume validated input.
#pragma once

#include <string>

#include "physics/math.hpp"

namespace sweetspot {

/// How wind speed grows with height above the ground.
enum class WindProfile {
  Logarithmic,  ///< neutral surface layer: u(h) = u_ref ln(h/z0) / ln(h_ref/z0); 0 below z0
  PowerLaw,     ///< u(h) = u_ref (h/h_ref)^alpha
  Uniform,      ///< u(h) = u_ref at every height (textbook problems, tests)
};

const char* to_string(WindProfile p);

/// Weather at the course or ballpark. Defaults (DESIGN §4): sea level, 21 °C (70 °F), 50 %
/// relative humidity, calm.
struct Environment {
  double temperature = 294.15;  ///< K; 294.15 = 21 °C = 70 °F. Allowed 223.15..333.15 (-50..60 °C)
  double pressure = 0.0;        ///< Pa, station pressure; 0 -> from `altitude` via the ISA. Allowed 0 or 30000..110000
  double altitude = 0.0;        ///< m above sea level; Denver's Coors Field 1580 m, "mile high" 1609 m. Allowed -500..6000
  double humidity = 0.5;        ///< relative humidity 0..1
  double wind_speed = 0.0;      ///< m/s at wind_reference_height; a breezy day 5 m/s. Allowed 0..60
  double wind_direction = 0.0;  ///< rad, direction the wind blows TOWARD: 0 = tailwind (+x), +pi/2 = toward +z (right)
  double wind_reference_height = 10.0;  ///< m where wind_speed is measured (weather stations: 10 m). Allowed 0.5..100
  WindProfile wind_profile = WindProfile::Logarithmic;
  double wind_roughness_length = 0.03;  ///< m, z0 of the log profile; mown grass / open fairway 0.01..0.05. Allowed 1e-4..1
  double wind_power_exponent = 1.0 / 7.0;  ///< alpha of the power law; open terrain 0.14. Allowed 0..1
};

/// Empty when `env` is valid, otherwise a message naming the field and its allowed range.
std::string validate_environment(const Environment& env);
/// Throws InputError with validate_environment()'s message.
void check_environment(const Environment& env);

/// Station pressure (Pa) of the International Standard Atmosphere at `altitude` (m),
/// troposphere formula: 101325 (1 - 0.0065 h / 288.15)^5.25588.
double standard_pressure(double altitude);

/// Station pressure actually used: env.pressure, or standard_pressure(env.altitude) when 0.
double station_pressure(const Environment& env);

/// Saturation vapour pressure of water (Pa) at temperature `t` (K), Buck (1996).
double saturation_vapour_pressure(double t);

/// Moist-air density, kg/m³: dry air and water vapour as ideal gases,
/// ρ = p_d/(R_d T) + p_v/(R_v T) with p_v = RH · e_s(T). 1.2041 at 20 °C, 101325 Pa, dry.
double air_density(const Environment& env);

/// Dynamic viscosity of air (Pa·s) at `t` (K), Sutherland's law; 1.81e-5 at 20 °C.
double air_viscosity(double t);

/// Wind velocity (m/s, horizontal) at `height` (m) above the ground.
Vec3 wind_at(const Environment& env, double height);

}  // namespace sweetspot
