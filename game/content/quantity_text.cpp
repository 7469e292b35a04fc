#include "game/content/quantity_text.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "game/content/scenario_schema.hpp"
#include "physics/error.hpp"

namespace sweetspot {

bool needs_unit(Dimension dim) { return dim != Dimension::Dimensionless; }

std::string_view unit_part(std::string_view t) {
  t = trim_blanks(t);
  const char* first = t.data();
  const char* last = t.data() + t.size();
  if (first != last && (*first == '+' || *first == '-')) ++first;
  double v = 0.0;
  const auto res = std::from_chars(first, last, v);
  if (res.ec == std::errc::invalid_argument) return t;
  return trim_blanks(std::string_view(res.ptr, static_cast<std::size_t>(last - res.ptr)));
}

bool has_unit(std::string_view t) { return trim_blanks(t).empty() || !unit_part(t).empty(); }

double read_quantity(std::string_view text, Dimension dim) {
  const std::string_view t = trim_blanks(text);
  if (t.empty()) throw InputError("empty value (a " + std::string(dimension_name(dim)) + " is needed)");
  if (needs_unit(dim) && !has_unit(t)) {
    throw InputError("missing unit in '" + std::string(t) + "' (a " + std::string(dimension_name(dim)) +
                     " needs one of: " + accepted_units(dim) + ")");
  }
  return parse_quantity(t, dim);
}

std::vector<double> read_quantity_list(std::string_view text, Dimension dim) {
  std::string_view s = trim_blanks(text);
  if (!s.empty() && s.front() == '[' && s.back() == ']') s = s.substr(1, s.size() - 2);
  std::vector<double> out;
  if (trim_blanks(s).empty()) return out;
  for (;;) {
    const auto comma = s.find(',');
    out.push_back(read_quantity(s.substr(0, comma), dim));
    if (comma == std::string_view::npos) break;
    s.remove_prefix(comma + 1);
  }
  return out;
}

std::string written_range_refusal(std::string_view name, std::string_view text, double value_si, Dimension dim,
                                  const Range& range) {
  if (range.contains(value_si)) return {};
  const std::string_view si_unit = si_unit_name(dim);
  const std::string unit(unit_part(text));
  if (!unit.empty() && unit != si_unit) {
    const auto shown = [&](double si) { return std::isfinite(si) ? si_to_unit(si, unit, dim) : si; };
    Range in_unit = range;
    in_unit.min = shown(range.min);
    in_unit.max = shown(range.max);
    std::string why = range_refusal(name, shown(value_si), in_unit, unit);
    if (!si_unit.empty()) why.insert(why.size() - 1, "; in SI " + range_text(range, si_unit));
    return why;
  }
  return range_refusal(name, value_si, range, si_unit);
}

double flag_quantity(std::string_view flag, std::string_view text, Dimension dim, const Range* range) {
  const std::string where = std::string(flag) + " " + std::string(text);
  double v = 0.0;
  try {
    v = read_quantity(text, dim);
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
  if (range != nullptr) {
    const std::string name(std::string(flag).substr(flag.find_first_not_of('-')));
    if (const std::string why = written_range_refusal(name, text, v, dim, *range); !why.empty())
      throw InputError(where + ": " + why);
  }
  return v;
}

}  // namespace sweetspot
