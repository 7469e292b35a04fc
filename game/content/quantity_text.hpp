// The one rule for quantities written by people, in every file and on every flag:
// a value with a physical dimension carries its unit ("113mph", "10.5deg", "50%"); only a
// dimensionless value (e, µ, a count) is written bare. `speed = 113` meaning 113 m/s is a
// trap, so we ask (README: Units). The unit parser itself lives in physics/units.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "physics/range.hpp"
#include "physics/units.hpp"

namespace sweetspot {

/// True when `dim` needs a unit in text: everything but Dimensionless (fractions too: "50%").
bool needs_unit(Dimension dim);

/// The text after a quantity's number ("mph" of "113 mph"), trimmed; "" for a bare number,
/// all of it when it does not start with a number.
std::string_view unit_part(std::string_view text);

/// True when something follows the number ("113mph"); a malformed number counts as having
/// a unit so the parser reports it properly.
bool has_unit(std::string_view text);

/// Parses `text` as a quantity of `dim` under the rule above. Throws InputError (without an
/// origin; callers prefix the file:line, key or flag): "missing unit in '113' (a speed needs
/// one of: m/s, mph, ...)", or the parser's message.
double read_quantity(std::string_view text, Dimension dim);

/// "" when `value_si` (read from `text`) lies in `range`; else the refusal in the unit it was
/// written in, with SI beside it: "speed = 400 mph is out of range (allowed [0.22, 201] mph;
/// in SI [0.1, 90] m/s)". A bare number or an SI unit is answered in SI alone.
std::string written_range_refusal(std::string_view name, std::string_view text, double value_si, Dimension dim,
                                  const Range& range);

/// A command-line flag's quantity: read_quantity, then the range. InputError names the
/// flag as written ("--speed 130mph: pitch speed = 58.1 m/s is out of range ...").
double flag_quantity(std::string_view flag, std::string_view text, Dimension dim, const Range* range = nullptr);

/// "[10mm, 0mm]" or "10mm, 0mm": each element by read_quantity.
std::vector<double> read_quantity_list(std::string_view text, Dimension dim);

}  // namespace sweetspot
