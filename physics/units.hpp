// Unit conversions and quantity parsing ("113mph", "10.5deg", "2686rpm").
//
// Quantities in files and on the command line carry their unit. The parser reads a bare
// number as SI (m/s, rad, rad/s, K, kg, m, fraction 0..1, Pa, s); scenario keys and CLI
// flags with a physical dimension refuse a bare number as "missing unit" (README: Units).
// Display units appear only at the edges (reports, UI); inside, everything is SI.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "physics/error.hpp"

namespace sweetspot {

// ---- exact conversion factors ----------------------------------------------------------
inline constexpr double kMetresPerInch = 0.0254;
inline constexpr double kMetresPerFoot = 0.3048;
inline constexpr double kMetresPerYard = 0.9144;
inline constexpr double kMetresPerMile = 1609.344;
inline constexpr double kMpsPerMph = kMetresPerMile / 3600.0;  // 0.44704
inline constexpr double kMpsPerKph = 1000.0 / 3600.0;
inline constexpr double kRadPerSecPerRpm = 2.0 * 3.14159265358979323846 / 60.0;
inline constexpr double kKgPerPound = 0.45359237;
inline constexpr double kKgPerOunce = kKgPerPound / 16.0;
inline constexpr double kPascalPerInHg = 3386.389;
inline constexpr double kPascalPerAtm = 101325.0;
inline constexpr double kKelvinAtZeroCelsius = 273.15;

inline constexpr double mph_to_mps(double mph) { return mph * kMpsPerMph; }
inline constexpr double mps_to_mph(double mps) { return mps / kMpsPerMph; }
inline constexpr double rpm_to_radps(double rpm) { return rpm * kRadPerSecPerRpm; }
inline constexpr double radps_to_rpm(double w) { return w / kRadPerSecPerRpm; }
inline constexpr double m_to_yd(double m) { return m / kMetresPerYard; }
inline constexpr double yd_to_m(double yd) { return yd * kMetresPerYard; }
inline constexpr double m_to_ft(double m) { return m / kMetresPerFoot; }
inline constexpr double ft_to_m(double ft) { return ft * kMetresPerFoot; }
inline constexpr double celsius_to_kelvin(double c) { return c + kKelvinAtZeroCelsius; }
inline constexpr double fahrenheit_to_kelvin(double f) {
  return (f - 32.0) * (5.0 / 9.0) + kKelvinAtZeroCelsius;
}
inline constexpr double kelvin_to_fahrenheit(double k) {
  return (k - kKelvinAtZeroCelsius) * (9.0 / 5.0) + 32.0;
}

/// What a quantity measures; decides which units are accepted and the SI result.
enum class Dimension {
  Speed,            // m/s      : m/s, mps, mph, km/h, kph, ft/s, fps
  Angle,            // rad      : deg, rad
  AngularVelocity,  // rad/s    : rpm, rps, rad/s, deg/s
  Temperature,      // K        : C, F, K
  Mass,             // kg       : g, kg, oz, lb
  Length,           // m        : mm, cm, m, km, in, ft, yd, mi
  Fraction,         // 0..1     : %, or bare
  Pressure,         // Pa       : Pa, hPa, kPa, mbar, inHg, atm
  Time,             // s        : s, ms, us, min
  Inertia,          // kg·m²    : kg*m^2, kgm2, g*cm^2, gcm2
  Dimensionless,    // bare number only (e, µ, counts)
};

/// Human-readable name ("speed", "angle", ...), for error messages.
std::string_view dimension_name(Dimension d);
/// The SI unit of `d` as text ("m/s", "rad", "kg*m^2"; "" for fractions and numbers).
std::string_view si_unit_name(Dimension d);
/// The accepted unit spellings for `d`, e.g. "m/s, mph, km/h, kph, ft/s, fps".
std::string accepted_units(Dimension d);

/// `s` without leading and trailing spaces and tabs.
std::string_view trim_blanks(std::string_view s);

/// Parses "113mph", "113 mph", "-1.3deg", "5%", "0.83" into SI. Throws InputError naming
/// the text, the dimension and the accepted units on: a missing or malformed number, an
/// unknown unit, trailing garbage, NaN or infinity.
double parse_quantity(std::string_view text, Dimension dim);

/// Parses a bracketed list "[10mm, 0mm]" (or "10mm,0mm") of quantities of one dimension.
std::vector<double> parse_quantity_list(std::string_view text, Dimension dim);

}  // namespace sweetspot
