#include "physics/range.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "physics/error.hpp"
#include "physics/math.hpp"

namespace sweetspot {
namespace {

std::string number(double v, int digits = 6) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

// A refused value written with as many digits as it takes to read as outside the range
// (110.0001 % is not "110 %" against an allowed (0, 110] %), in units of `scale` per SI unit.
std::string refused_number(double v, const Range& r, double scale) {
  for (int digits = 6; digits < 17; ++digits) {
    const std::string t = number(v * scale, digits);
    if (!r.contains(std::strtod(t.c_str(), nullptr) / scale)) return t;
  }
  return number(v * scale, 17);
}

// Messages are read by people: an angle's SI radian shows as degrees, the unit every input
// takes and every table shows (SI inside, display units at the edges).
struct Shown {
  double scale = 1.0;
  std::string_view unit;
};
Shown shown_unit(std::string_view si_unit) {
  if (si_unit == "rad") return {rad_to_deg(1.0), "deg"};
  return {1.0, si_unit};
}

}  // namespace

std::string range_text(const Range& si, std::string_view si_unit) {
  const Shown u = shown_unit(si_unit);
  const Range r{si.min * u.scale, si.max * u.scale, si.min_open, si.max_open};
  si_unit = u.unit;
  // A one-sided range reads as a bound ("> 0 m/s", ">= 0"), not as an interval to infinity.
  // (Built with a stream: GCC 12 warns falsely, -Wrestrict, on assigning short literals.)
  const bool no_min = std::isinf(r.min) && r.min < 0, no_max = std::isinf(r.max) && r.max > 0;
  std::ostringstream text;
  if (no_min && no_max) {
    text << "any finite number";
  } else if (no_max) {
    text << (r.min_open ? "> " : ">= ") << number(r.min);
  } else if (no_min) {
    text << (r.max_open ? "< " : "<= ") << number(r.max);
  } else {
    text << (r.min_open ? "(" : "[") << number(r.min) << ", " << number(r.max) << (r.max_open ? ")" : "]");
  }
  std::string out = text.str();
  if (!si_unit.empty()) {
    out += ' ';
    out.append(si_unit);
  }
  return out;
}

std::string range_refusal(std::string_view field, double value, const Range& r, std::string_view si_unit) {
  if (r.contains(value)) return {};
  std::string out(field);
  const Shown u = shown_unit(si_unit);
  out += " = " + refused_number(value, r, u.scale);
  if (!u.unit.empty()) {
    out += ' ';
    out.append(u.unit);
  }
  out += " is out of range (allowed " + range_text(r, si_unit) + ")";
  return out;
}

void check_range(std::string_view field, double value, const Range& r, std::string_view si_unit) {
  if (std::string why = range_refusal(field, value, r, si_unit); !why.empty()) throw InputError(why);
}

}  // namespace sweetspot
