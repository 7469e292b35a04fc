// The air the ball flies through: density from temperature, pressure (or altitude through
// the standard atmosphere) and humidity, and wind that grows with height over the ground.
//
// Environment is an immutable parameter set (SI). validate_environment() is called once
// where the values enter (scenario, CLI); air_density() and wind_at() are hot-path and
// assume validated input.
#pragma once

#include <algorithm>
#include <string>

#include "physics/math.hpp"
#include "physics/range.hpp"

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
  double temperature = 294.15;  ///< K; 294.15 = 21 °C = 70 °F
  /// -50..60 °C: the Buck vapour-pressure fit and the ideal-gas density hold there.
  static constexpr Range kTemperature{223.15, 333.15};
  double pressure = 0.0;        ///< Pa, station pressure; 0 -> from `altitude` via the ISA
  /// When set (not 0): from a 6000 m summit's ~47 kPa down to a deep mine's ~110 kPa.
  static constexpr Range kPressure{30000.0, 110000.0};
  double altitude = 0.0;        ///< m above sea level; Denver's Coors Field 1580 m, "mile high" 1609 m
  static constexpr Range kAltitude{-500.0, 6000.0};  ///< the Dead Sea shore to the highest courses and beyond
  double humidity = 0.5;        ///< relative humidity 0..1
  static constexpr Range kHumidity{0.0, 1.0};
  double wind_speed = 0.0;      ///< m/s at wind_reference_height; a breezy day 5 m/s
  /// Up to hurricane force, Beaufort 12's 32.7 m/s (73 mph): a wind in which no golf or
  /// baseball is played. Past it a ball's hops take from the wind more than the turf takes
  /// back: a drive hops on at the wind's pace until the time limit (14 km at 60 m/s). The
  /// Beaufort scale is a wind at 10 m: validate_environment() also holds beaufort_wind() to
  /// kHurricaneWind.
  static constexpr double kHurricaneWind = 32.7;   ///< m/s at 10 m, Beaufort 12
  static constexpr double kBeaufortHeight = 10.0;  ///< m
  static constexpr Range kWindSpeed{0.0, kHurricaneWind};
  double wind_direction = 0.0;  ///< rad, direction the wind blows TOWARD: 0 = tailwind (+x), +pi/2 = toward +z (right)
  static constexpr Range kWindDirection{-2.0 * kPi, 2.0 * kPi};
  double wind_reference_height = 10.0;  ///< m where wind_speed is measured (weather stations: 10 m)
  static constexpr Range kWindReferenceHeight{0.5, 100.0};
  WindProfile wind_profile = WindProfile::Logarithmic;
  double wind_roughness_length = 0.03;  ///< m, z0 of the log profile; mown grass / open fairway 0.01..0.05
  /// From 5 mm, the Davenport–Wieringa classification's "smooth" land (the least rough
  /// ground, class 2; open grass is 30 mm, class 3), to 1 m (a town): the land a course or a
  /// ballpark stands on, which is also where a landed ball lies (ground_wind_at). Over calm
  /// water's 0.1 mm a golf ball resting on the grass would sit in 47 % of the 10 m wind, and
  /// under 5 mm a hurricane keeps a landed ball hopping to the time limit. The log law also
  /// needs z0 <= h_ref / 10 (the surface layer well above the roughness elements), else its
  /// ratio ln(h/z0)/ln(h_ref/z0) blows up as z0 nears the reference height.
  static constexpr Range kWindRoughnessLength{5e-3, 1.0};
  double wind_power_exponent = 1.0 / 7.0;  ///< alpha of the power law; open terrain 0.14
  static constexpr Range kWindPowerExponent{0.0, 1.0};
};

/// The wind profiles describe the atmospheric surface layer, ~100 m deep: above this height
/// the wind is held at its value here.
inline constexpr double kSurfaceLayerTop = 100.0;  // m

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

/// Wind velocity (m/s, horizontal) at `height` (m) in the given profile, whatever env's.
Vec3 wind_at(const Environment& env, double height, WindProfile profile);

/// The wind on a ball once it has landed (its hops and its roll) at centre `height` (m): the
/// log law of the environment's roughness length, whatever profile the flight uses. Every
/// real wind meets the ground through the surface layer, where it falls to nothing in the
/// grass (a golf ball's centre, 21 mm up, sits below a fairway's z0 of 30 mm) and to 60 %
/// of the 10 m wind at 1 m. A uniform profile is a launch monitor's convention for the air a
/// shot flies through, and a power law is fitted to heights of metres: carried down to the
/// turf they would blow a landed ball along with the wind of the flag (in a 20 m/s uniform
/// tailwind a tour drive would hop on for kilometres).
inline Vec3 ground_wind_at(const Environment& env, double height) {
  return wind_at(env, height, WindProfile::Logarithmic);
}

/// The wind speed at Beaufort's 10 m (m/s) that the ball meets: the larger of the flight
/// profile's and the turf's log law through the same reference (a uniform wind given at 2 m
/// is that at 10 m, but the log law through it is stronger there).
inline double beaufort_wind(const Environment& env) {
  return std::max(wind_at(env, Environment::kBeaufortHeight).norm(),
                  ground_wind_at(env, Environment::kBeaufortHeight).norm());
}

}  // namespace sweetspot
