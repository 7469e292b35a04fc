// The library of published references behind `sweetspot validate` (docs/validation.md):
// assets/validation/*.toml, each a [sources.KEY] table per publication and [[case]]
// entries naming one published value, the conditions it was measured under (scenario keys,
// as `--set`), a tolerance from the source's own spread and why. Read here, checked whole,
// run by game/tuning/validation.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "physics/units.hpp"

namespace sweetspot {

struct ValidationSource {
  std::string key;      ///< "trackman_lpga"
  std::string authors;
  std::string title;
  int year = 0;
  std::string where;    ///< URL, journal and pages, book and chapter
  std::string origin;   ///< "file:line"
};

/// What a case measures: a shot's launch or flight, or a pitch's movement.
struct ValidationQuantity {
  std::string_view name;
  Dimension dim;
  bool pitch;   ///< measured on a pitch (`scenario = "pitch:TYPE"`) rather than a shot
  bool flight;  ///< a shot's quantity that needs the flight, not just the launch
};

/// Every quantity a case may name (docs/validation.md lists them with their meaning).
const std::vector<ValidationQuantity>& validation_quantities();
/// The tags a case may carry; its first tag is its sport.
const std::vector<std::string_view>& validation_tags();

struct ValidationCase {
  std::string id;
  std::string source;               ///< a ValidationSource key
  std::vector<std::string> tags;    ///< tags[0] is the sport
  bool fitted = false;              ///< a model constant was fitted to this value
  std::string scenario;             ///< built-in name, path, "pitch:TYPE", or "" (the sport's empty shot)
  std::vector<std::string> set;     ///< "key=value", applied in order
  std::vector<std::string> baseline;///< non-empty: the published value is quantity(set) - quantity(set + baseline)
  const ValidationQuantity* quantity = nullptr;
  double published = 0.0;           ///< SI
  double tolerance = 0.0;           ///< SI, > 0
  std::string unit;                 ///< the unit `published` was written in ("yd", "rpm"), for display
  std::string why;                  ///< where the tolerance comes from
  std::string origin;               ///< "file:line" of the [[case]]

  bool is_pitch() const { return quantity != nullptr && quantity->pitch; }
  /// The pitch type of a "pitch:TYPE" scenario ("" otherwise).
  std::string pitch_type() const;
};

struct ValidationLibrary {
  std::vector<ValidationSource> sources;
  std::vector<ValidationCase> cases;  ///< file name order, then file order

  const ValidationSource* source(std::string_view key) const;
};

/// Reads every *.toml in `dir` (name order), or the one file `dir` names. Refuses, naming
/// file:line and key: unknown keys, a duplicate source key or case id, a case naming a source
/// no file defines, an unknown tag or quantity, a sport tag that is not first, a quantity
/// whose unit does not fit, a tolerance <= 0, a `set` entry without '=', a pitch quantity
/// without "pitch:TYPE" or the other way round, an empty library.
ValidationLibrary load_validation_library(const std::filesystem::path& dir);

}  // namespace sweetspot
