// Quantity parsing. One table maps unit spellings to an affine conversion (scale, offset)
// into SI per dimension; the parser splits number and unit and looks the unit up.
#include "physics/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>

#include "physics/math.hpp"

namespace sweetspot {
namespace {

struct UnitDef {
  Dimension dim;
  std::string_view spelling;
  double scale;   // SI = value * scale + offset
  double offset;
};

constexpr std::array kUnits{
    UnitDef{Dimension::Speed, "m/s", 1.0, 0.0},
    UnitDef{Dimension::Speed, "mps", 1.0, 0.0},
    UnitDef{Dimension::Speed, "mph", kMpsPerMph, 0.0},
    UnitDef{Dimension::Speed, "km/h", kMpsPerKph, 0.0},
    UnitDef{Dimension::Speed, "kph", kMpsPerKph, 0.0},
    UnitDef{Dimension::Speed, "ft/s", kMetresPerFoot, 0.0},
    UnitDef{Dimension::Speed, "fps", kMetresPerFoot, 0.0},
    UnitDef{Dimension::Angle, "deg", kPi / 180.0, 0.0},
    UnitDef{Dimension::Angle, "rad", 1.0, 0.0},
    UnitDef{Dimension::AngularVelocity, "rpm", kRadPerSecPerRpm, 0.0},
    UnitDef{Dimension::AngularVelocity, "rps", 2.0 * kPi, 0.0},
    UnitDef{Dimension::AngularVelocity, "rad/s", 1.0, 0.0},
    UnitDef{Dimension::AngularVelocity, "deg/s", kPi / 180.0, 0.0},
    UnitDef{Dimension::Temperature, "C", 1.0, kKelvinAtZeroCelsius},
    UnitDef{Dimension::Temperature, "F", 5.0 / 9.0, kKelvinAtZeroCelsius - 32.0 * 5.0 / 9.0},
    UnitDef{Dimension::Temperature, "K", 1.0, 0.0},
    UnitDef{Dimension::Mass, "g", 1e-3, 0.0},
    UnitDef{Dimension::Mass, "kg", 1.0, 0.0},
    UnitDef{Dimension::Mass, "oz", kKgPerOunce, 0.0},
    UnitDef{Dimension::Mass, "lb", kKgPerPound, 0.0},
    UnitDef{Dimension::Length, "mm", 1e-3, 0.0},
    UnitDef{Dimension::Length, "cm", 1e-2, 0.0},
    UnitDef{Dimension::Length, "m", 1.0, 0.0},
    UnitDef{Dimension::Length, "km", 1e3, 0.0},
    UnitDef{Dimension::Length, "in", kMetresPerInch, 0.0},
    UnitDef{Dimension::Length, "ft", kMetresPerFoot, 0.0},
    UnitDef{Dimension::Length, "yd", kMetresPerYard, 0.0},
    UnitDef{Dimension::Length, "mi", kMetresPerMile, 0.0},
    UnitDef{Dimension::Fraction, "%", 0.01, 0.0},
    UnitDef{Dimension::Pressure, "Pa", 1.0, 0.0},
    UnitDef{Dimension::Pressure, "hPa", 100.0, 0.0},
    UnitDef{Dimension::Pressure, "kPa", 1000.0, 0.0},
    UnitDef{Dimension::Pressure, "mbar", 100.0, 0.0},
    UnitDef{Dimension::Pressure, "inHg", kPascalPerInHg, 0.0},
    UnitDef{Dimension::Pressure, "atm", kPascalPerAtm, 0.0},
    UnitDef{Dimension::Time, "s", 1.0, 0.0},
    UnitDef{Dimension::Time, "ms", 1e-3, 0.0},
    UnitDef{Dimension::Time, "us", 1e-6, 0.0},
    UnitDef{Dimension::Time, "min", 60.0, 0.0},
    UnitDef{Dimension::Time, "h", 3600.0, 0.0},
    UnitDef{Dimension::Inertia, "kg*m^2", 1.0, 0.0},
    UnitDef{Dimension::Inertia, "kgm2", 1.0, 0.0},
    UnitDef{Dimension::Inertia, "g*cm^2", 1e-7, 0.0},
    UnitDef{Dimension::Inertia, "gcm2", 1e-7, 0.0},
};

[[noreturn]] void fail(std::string_view text, Dimension dim, std::string_view why) {
  std::string msg = "invalid ";
  msg += dimension_name(dim);
  msg += " '";
  msg += text;
  msg += "': ";
  msg += why;
  if (dim != Dimension::Dimensionless) {
    msg += " (accepted units: ";
    msg += accepted_units(dim);
    msg += ")";
  }
  throw InputError(msg);
}

}  // namespace

std::string_view dimension_name(Dimension d) {
  switch (d) {
    case Dimension::Speed: return "speed";
    case Dimension::Angle: return "angle";
    case Dimension::AngularVelocity: return "spin rate";
    case Dimension::Temperature: return "temperature";
    case Dimension::Mass: return "mass";
    case Dimension::Length: return "length";
    case Dimension::Fraction: return "fraction";
    case Dimension::Pressure: return "pressure";
    case Dimension::Time: return "time";
    case Dimension::Inertia: return "moment of inertia";
    case Dimension::Dimensionless: return "number";
  }
  return "quantity";
}

std::string_view si_unit_name(Dimension d) {
  switch (d) {
    case Dimension::Speed: return "m/s";
    case Dimension::Angle: return "rad";
    case Dimension::AngularVelocity: return "rad/s";
    case Dimension::Temperature: return "K";
    case Dimension::Mass: return "kg";
    case Dimension::Length: return "m";
    case Dimension::Fraction: return "";
    case Dimension::Pressure: return "Pa";
    case Dimension::Time: return "s";
    case Dimension::Inertia: return "kg*m^2";
    case Dimension::Dimensionless: return "";
  }
  return "";
}

std::string accepted_units(Dimension d) {
  std::string out;
  for (const auto& u : kUnits) {
    if (u.dim != d) continue;
    if (!out.empty()) out += ", ";
    out += u.spelling;
  }
  return out.empty() ? "none (a bare number)" : out;
}

double parse_quantity(std::string_view text, Dimension dim) {
  const std::string_view s = trim_blanks(text);
  if (s.empty()) fail(text, dim, "empty value");
  double value = 0.0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (*first == '+') ++first;  // from_chars rejects a leading '+', people write it
  // from_chars would accept "nan"/"inf"; name them explicitly instead.
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) fail(text, dim, "number out of range");
  if (ec != std::errc() || ptr == first) fail(text, dim, "missing or malformed number");
  if (!std::isfinite(value)) fail(text, dim, "NaN and infinity are not allowed");
  const std::string_view unit = trim_blanks(std::string_view(ptr, static_cast<size_t>(last - ptr)));
  if (unit.empty()) return value;  // bare number: SI
  for (const auto& u : kUnits) {
    if (u.dim == dim && u.spelling == unit) {
      const double si = value * u.scale + u.offset;
      if (!std::isfinite(si)) fail(text, dim, "value out of range");
      return si;
    }
  }
  fail(text, dim, "unknown unit '" + std::string(unit) + "'");
}

std::vector<double> parse_quantity_list(std::string_view text, Dimension dim) {
  std::string_view s = trim_blanks(text);
  if (!s.empty() && s.front() == '[') {
    if (s.back() != ']') fail(text, dim, "list opened with '[' is not closed with ']'");
    s = s.substr(1, s.size() - 2);
  }
  std::vector<double> out;
  if (trim_blanks(s).empty()) return out;
  while (true) {
    const size_t comma = s.find(',');
    out.push_back(parse_quantity(s.substr(0, comma), dim));
    if (comma == std::string_view::npos) break;
    s.remove_prefix(comma + 1);
  }
  return out;
}

std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace sweetspot
