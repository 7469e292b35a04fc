#include "game/content/quantity_text.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

bool needs_unit(Dimension dim) { return dim != Dimension::Dimensionless; }

std::string_view unit_part(std::string_view t) {
  t = trim(t);
  const char* first = t.data();
  const char* last = t.data() + t.size();
  if (first != last && (*first == '+' || *first == '-')) ++first;
  double v = 0.0;
  const auto res = std::from_chars(first, last, v);
  if (res.ec == std::errc::invalid_argument) return t;
  return trim(std::string_view(res.ptr, static_cast<std::size_t>(last - res.ptr)));
}

bool has_unit(std::string_view t) { return trim(t).empty() || !unit_part(t).empty(); }

double read_quantity(std::string_view text, Dimension dim) {
  const std::string_view t = trim(text);
  if (t.empty()) throw InputError("empty value (a " + std::string(dimension_name(dim)) + " is needed)");
  if (needs_unit(dim) && !has_unit(t)) {
    throw InputError("missing unit in '" + std::string(t) + "' (a " + std::string(dimension_name(dim)) +
                     " needs one of: " + accepted_units(dim) + ")");
  }
  return parse_quantity(t, dim);
}

std::vector<double> read_quantity_list(std::string_view text, Dimension dim) {
  std::string_view s = trim(text);
  if (!s.empty() && s.front() == '[' && s.back() == ']') s = s.substr(1, s.size() - 2);
  std::vector<double> out;
  if (trim(s).empty()) return out;
  for (;;) {
    const auto comma = s.find(',');
    out.push_back(read_quantity(s.substr(0, comma), dim));
    if (comma == std::string_view::npos) break;
    s.remove_prefix(comma + 1);
  }
  return out;
}

double flag_quantity(std::string_view flag, std::string_view text, Dimension dim, const Range* range) {
  const std::string where = std::string(flag) + " " + std::string(text);
  double v = 0.0;
  try {
    v = read_quantity(text, dim);
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
  if (range != nullptr && !range->contains(v)) {
    // The refusal speaks the unit the value was written in ("--spin 9000rpm: ... allowed
    // [0, 4000] rpm"), not SI: the unit's scale and offset come from reading 0 and 1 of it.
    const std::string unit(unit_part(text));
    const std::string name(std::string(flag).substr(flag.find_first_not_of('-')));
    std::string why = range_refusal(name, v, *range, si_unit_name(dim));
    if (!unit.empty()) {
      const double offset = parse_quantity("0" + unit, dim), scale = parse_quantity("1" + unit, dim) - offset;
      const auto shown = [&](double si) { return std::isfinite(si) ? (si - offset) / scale : si; };
      Range in_unit = *range;
      in_unit.min = shown(range->min);
      in_unit.max = shown(range->max);
      if (scale > 0.0) why = range_refusal(name, shown(v), in_unit, unit);
    }
    throw InputError(where + ": " + why);
  }
  return v;
}

}  // namespace sweetspot
