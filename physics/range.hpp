// Allowed ranges of parameters. Each physics parameter struct states the range of every
// field right beside the field (`static constexpr Range kClubSpeed{...}`); its one validator
// checks it, and the scenario schema, the command-line flags and the UI sliders read the
// same constant, so a value has exactly one allowed range everywhere (README: Conventions).
//
// Ranges are SI. A message quotes them in SI here; the schema quotes them in the key's
// display unit too.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

namespace sweetspot {

struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< true: min itself is not allowed (a speed must be > 0)
  bool max_open = false;

  /// False for NaN. Closed ends allow a relative 1e-12 of round-off, so a bound written in
  /// another unit ("-50C", "-58F", "110mph") that lands a few ulps outside the SI constant
  /// still counts as the bound itself (it is, to the precision of the input).
  constexpr bool contains(double v) const {
    const double slack_lo = min_open ? 0.0 : 1e-12 * (min < 0 ? -min : min);
    const double slack_hi = max_open ? 0.0 : 1e-12 * (max < 0 ? -max : max);
    const bool lo = min_open ? v > min : v >= min - slack_lo;
    const bool hi = max_open ? v < max : v <= max + slack_hi;
    return lo && hi;
  }
};

/// "(0, 90] m/s": the range in SI with the unit given; an angle (si_unit "rad") in degrees,
/// "[0, 70] deg", as people read and write it.
std::string range_text(const Range& r, std::string_view si_unit);

/// Empty when `value` is in `r`; otherwise "FIELD = VALUE UNIT is out of range (allowed
/// RANGE)", an angle in degrees. `field` names the parameter as users write it ("swing.speed").
std::string range_refusal(std::string_view field, double value, const Range& r, std::string_view si_unit);

/// Throws InputError with range_refusal()'s message when `value` is outside `r`.
void check_range(std::string_view field, double value, const Range& r, std::string_view si_unit);

}  // namespace sweetspot
