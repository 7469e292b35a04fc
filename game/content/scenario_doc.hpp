// Scenario documents: a TOML file flattened to dotted keys, with `--set key=value`
// overrides on top, then checked against a Schema into typed SI values.
//
// Two stages so errors can name their origin precisely:
//   ScenarioDoc   raw text per key plus where it came from ("golf/driver.toml:7" or
//                 "--set swing.speed=200mph"); built by parse_toml_doc / read_toml_doc /
//                 apply_set.
//   CheckedDoc    every key known, of the right type, parsed with its unit, finite and in
//                 range; throws InputError naming the origin, the key and the allowed range.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/scenario_schema.hpp"
#include "game/core/sport.hpp"

namespace sweetspot {

/// The TOML type a value had in the file (or Text for a `--set` value, which may be any).
enum class RawKind : std::uint8_t { String, Integer, Float, Boolean, Array, Other, Text };

struct DocEntry {
  std::string key;      ///< dotted key
  std::string text;     ///< value as text: string contents, number, "true", or "[a, b]"
  RawKind kind = RawKind::Text;
  std::string kind_name;  ///< TOML type for messages ("boolean", "table", "array of tables")
  std::string origin;   ///< "path:line" or "--set key=value"
  int line = 0;         ///< 1-based line in the file; 0 for --set
};

struct ScenarioDoc {
  std::string source;                ///< file path (or built-in name) for messages
  std::vector<DocEntry> entries;     ///< file order; a --set replaces or appends
  std::vector<DocEntry> sections;    ///< table headers seen ([swing]), to catch unknown empty ones

  const DocEntry* find(std::string_view key) const;
};

/// Parses TOML text. Malformed TOML -> InputError "source:line:col: malformed TOML: ...".
ScenarioDoc parse_toml_doc(std::string_view toml_text, const std::string& source);
/// Reads and parses a file; a missing or unreadable file -> InputError naming the path.
ScenarioDoc read_toml_doc(const std::filesystem::path& path);
/// Applies one `--set key=value` (value text as on the command line: "105mph",
/// "[10mm,0mm]", "textbook"). Only the shape is checked here; CheckedDoc validates it.
/// `origin` names the flag in messages (default "--set key=value"; `shot --e 0.7` passes
/// "--e 0.7").
void apply_set(ScenarioDoc& doc, std::string_view assignment, std::string_view origin = {});

/// The key of a `--set key=value` assignment as apply_set reads it (trimmed); "" without '='.
std::string set_key(std::string_view assignment);

/// A validated value in SI.
struct CheckedValue {
  const KeySpec* spec = nullptr;
  double number = 0.0;              ///< Quantity
  std::vector<double> list;         ///< QuantityList
  std::string text;                 ///< Choice, Name, Text; Bool as "true"/"false"
  std::string origin;               ///< where it came from; "default" for schema defaults
  bool from_default = false;
};

class CheckedDoc {
 public:
  /// Validates every entry of `doc` against `schema`. If the schema has a `sport` key it is
  /// read first (required; one of `sports`) and its impactor (club or bat) decides which
  /// keys apply. Throws InputError on the first problem in file order.
  CheckedDoc(const ScenarioDoc& doc, const Schema& schema, const SportCatalog* sports = nullptr);

  /// The sport's profile; nullptr when the schema has no sport key.
  const SportProfile* sport() const { return sport_; }
  /// kClubKeys or kBatKeys for a scenario; kAnyStrike without a sport.
  std::uint8_t strikes() const { return strikes_; }
  const std::string& source() const { return source_; }

  /// True when the document itself sets `key` (not counting defaults).
  bool has(std::string_view key) const;
  /// The value, or the schema default; InputError "missing key" when neither exists.
  double quantity(std::string_view key) const;
  std::vector<double> list(std::string_view key) const;
  std::string text(std::string_view key) const;
  bool flag(std::string_view key) const;
  /// The value only when the document sets it (no default).
  std::optional<double> quantity_if_set(std::string_view key) const;
  std::optional<std::string> text_if_set(std::string_view key) const;
  /// Where `key` came from ("file:line", "--set ...", or "default").
  std::string origin(std::string_view key) const;
  /// The value's text as written (for `--update` and reports); "" when absent.
  std::string raw_text(std::string_view key) const;
  /// Every key set by the document, in file order.
  const std::vector<std::string>& keys() const { return order_; }

 private:
  const CheckedValue& get(std::string_view key) const;
  std::string source_;
  const Schema* schema_ = nullptr;
  const SportProfile* sport_ = nullptr;
  std::uint8_t strikes_ = kAnyStrike;
  std::map<std::string, CheckedValue, std::less<>> values_;
  std::map<std::string, std::string, std::less<>> raw_;
  mutable std::map<std::string, CheckedValue, std::less<>> defaults_;
  std::vector<std::string> order_;
};

/// Checks one value text against a spec (the same rules as a file value); `origin` goes
/// into the message. Exposed for the UI's edit fields and for tests.
CheckedValue check_value(const KeySpec& spec, std::string_view text, RawKind kind,
                         std::string_view kind_name, const std::string& origin);

}  // namespace sweetspot
