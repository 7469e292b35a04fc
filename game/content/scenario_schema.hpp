// The scenario schema: every key a scenario file, `--set` or a flag may name, with its
// type, physical dimension, allowed range, display unit and default. One table is the
// single source of truth for validation, error messages (which quote the range), `--set`
// and documentation. Ranges are not restated here: each key points at the Range beside its
// physics parameter (physics/*.hpp), so the schema, the flags and the UI sliders agree with
// the physics validators by construction.
//
// Files are TOML; keys are dotted (`swing.speed`). Quantities carry units ("113mph",
// "-1.3deg"); a bare number is accepted only for dimensionless keys (e, µ).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "physics/range.hpp"
#include "physics/units.hpp"

namespace sweetspot {

/// Which strikes a key applies to (bit mask): the sport's profile says whether its
/// scenarios swing a club or a bat; launch-only keys apply to both.
enum StrikeMask : std::uint8_t { kClubKeys = 1, kBatKeys = 2, kAnyStrike = 3 };

enum class ValueType : std::uint8_t {
  Quantity,      ///< one number with a unit of `dim` (bare only for Dimensionless)
  QuantityList,  ///< `list_size` numbers of `dim`: a TOML array or text "[10mm, 0mm]"
  Choice,        ///< one of `choices` ("none|textbook|coulomb")
  Name,          ///< a name resolved later (sport, equipment, world, aero model)
  Text,          ///< free text (description)
  Bool,          ///< true / false
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();
/// Any finite value (expectations).
inline constexpr Range kAnyFinite{};

struct KeySpec {
  std::string_view key;            ///< dotted key, e.g. "swing.speed"
  ValueType type = ValueType::Quantity;
  Dimension dim = Dimension::Dimensionless;
  /// The parameter's range (SI), or one per element of a list; null = any finite value.
  std::array<const Range*, 3> range{};
  int list_size = 0;               ///< QuantityList: exact number of elements
  std::string_view choices;        ///< Choice: allowed values separated by '|'
  std::string_view unit;           ///< display unit for ranges in messages and sliders ("mph"); "" = SI
  std::uint8_t strikes = kAnyStrike;  ///< StrikeMask
  std::string_view default_text;   ///< parsed like a file value; "" = no fixed default
  std::string_view doc;            ///< one line for `--help`-style listings
};

/// A set of keys. A key may appear twice with different strike masks (a club's and a bat's
/// `swing.speed` have different defaults and ranges).
struct Schema {
  std::string_view name;           ///< "scenario" or "impact case", for messages
  std::vector<KeySpec> keys;

  /// The spec for `key` that applies to `strikes` (pass kAnyStrike to accept any), or nullptr.
  const KeySpec* find(std::string_view key, std::uint8_t strikes) const;
  /// True when some key starts with "section.".
  bool has_section(std::string_view section) const;
  /// Comma-separated keys of `section` for `strikes`.
  std::string keys_in_section(std::string_view section, std::uint8_t strikes) const;
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
  const Range* range = nullptr;    ///< the values the quantity can take (SI); nullptr: any finite
};
const std::vector<ExpectSpec>& scenario_expectations();
const std::vector<ExpectSpec>& impact_case_expectations();

/// SI value expressed in `unit` of dimension `dim` ("mph", "deg"); `unit` "" returns `si`.
double si_to_unit(double si, std::string_view unit, Dimension dim);
/// A value in `unit` of dimension `dim` -> SI (the inverse of si_to_unit).
double unit_to_si(double value, std::string_view unit, Dimension dim);
/// "335.5 mph" style text with `digits` significant digits.
std::string format_quantity(double si, std::string_view unit, Dimension dim, int digits = 6);
/// The allowed range of a key as text in its display unit and in SI, e.g.
/// "0 mph < swing.speed <= 201.3 mph (0 .. 90 m/s)"; choices list their values.
std::string range_text(const KeySpec& spec);

}  // namespace sweetspot
