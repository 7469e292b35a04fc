// The one TOML reader of every data file (scenarios, equipment, materials, aero models,
// sports, worlds, courses, regression cases): it refuses what is not a regular file or is
// over a stated size before reading a byte, reports syntax errors as "path:line:col", and
// reads values under one rule (game/content/quantity_text.hpp: units on every dimensional
// value; one value per key; arrays of the stated length; no empty names), so the files
// cannot drift apart in what they accept.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "physics/range.hpp"
#include "physics/units.hpp"

namespace sweetspot {

/// Data files are small; anything larger is a mistake (or /dev/zero). Meshes have their own limit.
inline constexpr std::uintmax_t kMaxDataFileBytes = std::uintmax_t{1} << 20;  // 1 MiB

/// The bytes of a regular file of at most `max_bytes`, read whole. Throws InputError naming
/// the path for a missing file, a directory, a FIFO or device, a file over the limit, or a
/// read error. `what` names the file's role in messages ("scenario", "world mesh").
/// The checks of read_data_file without reading: returns the size in bytes.
std::uintmax_t check_data_file(const std::filesystem::path& path, std::string_view what,
                               std::uintmax_t max_bytes = kMaxDataFileBytes);
std::string read_data_file(const std::filesystem::path& path, std::string_view what,
                           std::uintmax_t max_bytes = kMaxDataFileBytes);

class TomlFile {
 public:
  /// read_data_file + parse. InputError "path:line:col: malformed TOML: ...".
  static TomlFile read(const std::filesystem::path& path, std::string_view what);
  /// Parses text; `source` names it in messages.
  static TomlFile parse(std::string_view text, std::string source);

  const toml::table& root() const { return root_; }
  const std::string& source() const { return source_; }
  /// "path:line" of a node.
  std::string where(const toml::node& n) const;
  [[noreturn]] void fail(const toml::node& n, std::string_view key, std::string_view message) const;
  /// `message` (which may start with this file's "path:line: ") with `context` ("club
  /// 'driver'") put right after that location, for loaders that read named entries.
  std::string in_context(const std::string& message, const std::string& context) const;

  /// Refuses any key of `t` not in `allowed` ("unknown key 'x' (allowed: a, b)").
  void only_keys(const toml::table& t, std::string_view what, std::initializer_list<std::string_view> allowed) const;
  /// The node at `key` or fail "missing (what it is)".
  const toml::node& required(const toml::table& t, std::string_view key, std::string_view what) const;
  const toml::table& table(const toml::node& n, std::string_view key) const;

  /// A quantity of `dim` under the one rule; checked against `range` (SI) when given.
  double quantity(const toml::node& n, std::string_view key, Dimension dim, const Range* range = nullptr) const;
  double quantity_or(const toml::table& t, std::string_view key, Dimension dim, double fallback,
                     const Range* range = nullptr) const;
  /// A whole number written as a TOML integer (not 1.5, not "1"), within `range`.
  int whole_number(const toml::node& n, std::string_view key, const Range& range) const;
  /// An array of exactly `count` quantities (count 0: any length ≥ 1).
  std::vector<double> quantities(const toml::node& n, std::string_view key, Dimension dim, std::size_t count,
                                 const Range* range = nullptr) const;
  /// [[x, y], ...] pairs of quantities.
  std::vector<std::pair<double, double>> pairs(const toml::node& n, std::string_view key, Dimension dx,
                                               Dimension dy) const;
  /// A non-empty string.
  std::string text(const toml::node& n, std::string_view key) const;
  std::string text_or(const toml::table& t, std::string_view key, std::string fallback) const;
  bool boolean(const toml::node& n, std::string_view key) const;
  /// The tables of an array of tables ([[club]]); fails when missing or empty if `required`.
  std::vector<const toml::table*> tables(const toml::table& t, std::string_view key, bool required) const;

 private:
  TomlFile(toml::table root, std::string source) : root_(std::move(root)), source_(std::move(source)) {}
  toml::table root_;
  std::string source_;
};

/// The text of a scalar TOML node (string contents, shortest round-trip number, "true"),
/// or false when the node is not a string, number or boolean.
bool toml_scalar_text(const toml::node& n, std::string& out);
/// "string", "integer", "table", ... for messages.
const char* toml_type_name(toml::node_type t);

}  // namespace sweetspot
