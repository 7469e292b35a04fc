// The scenario schema: every key a scenario file or `--set` may name, with its type,
// physical dimension, allowed range and default. One table is the single source of truth
// for validation, error messages (which quote the range), `--set` and documentation.
//
// Files are TOML; keys are dotted (`swing.speed`). Quantities carry units ("113mph",
// "-1.3deg"); a bare number is accepted only for dimensionless keys (e, µ) and fractions.
// Ranges are physical limits plus resource bounds (speeds ≤ 150 m/s, spin ≤ 20000 rpm) so
// no input can make the simulation run away.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "physics/units.hpp"

namespace sweetspot {

enum class Sport : std::uint8_t { Golf = 1, Baseball = 2 };
const char* to_string(Sport s);

/// Which sports accept a key (bit mask of Sport values).
enum SportMask : std::uint8_t { kGolfOnly = 1, kBaseballOnly = 2, kAnySport = 3 };

enum class ValueType : std::uint8_t {
  Quantity,      ///< one number with a unit of `dim` (bare only for Dimensionless/Fraction)
  QuantityList,  ///< `list_size` numbers of `dim`: a TOML array or text "[10mm, 0mm]"
  Choice,        ///< one of `choices` ("none|textbook|coulomb")
  Name,          ///< a name resolved later (equipment, world, aero model)
  Text,          ///< free text (description)
  Bool,          ///< true / false
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// Resource bounds shared by every speed and spin key (SI).
inline constexpr double kMaxSpeed = 150.0;                    ///< m/s (335.5 mph)
inline constexpr double kMaxSpin = 20000.0 * kRadPerSecPerRpm; ///< rad/s (20000 rpm)

struct KeySpec {
  std::string_view key;            ///< dotted key, e.g. "swing.speed"
  ValueType type = ValueType::Quantity;
  Dimension dim = Dimension::Dimensionless;
  double min = -kInf;              ///< SI, inclusive unless min_exclusive
  double max = kInf;               ///< SI, inclusive
  bool min_exclusive = false;
  int list_size = 0;               ///< QuantityList: exact number of elements
  std::string_view choices;        ///< Choice: allowed values separated by '|'
  std::string_view unit;           ///< display unit for ranges in messages ("mph"); "" = SI
  std::uint8_t sports = kAnySport; ///< SportMask
  std::string_view default_text;   ///< parsed like a file value; "" = no fixed default
  std::string_view doc;            ///< one line for `--help`-style listings
};

/// A set of keys. A key may appear twice with different sport masks (golf and baseball
/// `swing.speed` have different defaults and ranges).
struct Schema {
  std::string_view name;           ///< "scenario" or "impact case", for messages
  std::vector<KeySpec> keys;

  /// The spec for `key` that applies to `sport` (pass 0 to accept any sport), or nullptr.
  const KeySpec* find(std::string_view key, std::uint8_t sport) const;
  /// True when some key (for any sport) starts with "section.".
  bool has_section(std::string_view section) const;
  /// Comma-separated keys of `section` for `sport` (all sections' names when empty).
  std::string keys_in_section(std::string_view section, std::uint8_t sport) const;
  /// Comma-separated section names, for "unknown section" messages.
  std::string section_names() const;
};

const Schema& scenario_schema();
const Schema& impact_case_schema();

/// Quantities an `expect.NAME` / `expect.NAME_tol` pair may check, per schema.
struct ExpectSpec {
  std::string_view name;           ///< "ball_speed"
  Dimension dim;
  std::string_view unit;           ///< display unit in the regression table
  int list_size;                   ///< 0 = scalar, 3 = vector
};
const std::vector<ExpectSpec>& scenario_expectations();
const std::vector<ExpectSpec>& impact_case_expectations();

/// SI value expressed in `unit` of dimension `dim` ("mph", "deg"); `unit` "" returns `si`.
double si_to_unit(double si, std::string_view unit, Dimension dim);
/// "335.5 mph" style text with `digits` significant digits.
std::string format_quantity(double si, std::string_view unit, Dimension dim, int digits = 6);
/// The allowed range of a key as text, e.g. "0 mph < swing.speed <= 335.536 mph (150 m/s)";
/// choices list their values.
std::string range_text(const KeySpec& spec);

}  // namespace sweetspot
