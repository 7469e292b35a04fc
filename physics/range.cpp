#include "physics/range.hpp"

#include <sstream>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

std::string number(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace

std::string range_text(const Range& r, std::string_view si_unit) {
  std::string out = r.min_open ? "(" : "[";
  out += number(r.min) + ", " + number(r.max);
  out += r.max_open ? ")" : "]";
  if (!si_unit.empty()) {
    out += ' ';
    out.append(si_unit);
  }
  return out;
}

std::string range_refusal(std::string_view field, double value, const Range& r, std::string_view si_unit) {
  if (r.contains(value)) return {};
  std::string out(field);
  out += " = " + number(value);
  if (!si_unit.empty()) {
    out += ' ';
    out.append(si_unit);
  }
  out += " is out of range (allowed " + range_text(r, si_unit) + ")";
  return out;
}

void check_range(std::string_view field, double value, const Range& r, std::string_view si_unit) {
  if (std::string why = range_refusal(field, value, r, si_unit); !why.empty()) throw InputError(why);
}

}  // namespace sweetspot
