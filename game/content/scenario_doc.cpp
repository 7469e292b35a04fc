// TOML -> flat dotted keys -> checked SI values. toml++ keeps tables sorted by key, so
// entries are re-sorted by line to report the first problem in reading order.
#include "game/content/scenario_doc.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "game/content/quantity_text.hpp"
#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

std::string_view parent_section_of(std::string_view key) {
  const auto dot = key.rfind('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}

void flatten(const toml::table& table, const std::string& prefix, const std::string& source,
             ScenarioDoc& doc) {
  for (auto&& [k, node] : table) {
    if (k.str().find('.') != std::string_view::npos || k.str().empty()) {
      // `"swing.speed" = ...` is one key with a dot in its name, not swing.speed: refuse it
      // rather than let it pass for the nested key.
      throw InputError(source + ":" + std::to_string(node.source().begin.line) + ": \"" + std::string(k.str()) +
                       "\": a quoted key may not be empty or contain '.'; write it as a table key ([section] key = ...)");
    }
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    DocEntry e;
    e.key = key;
    e.line = static_cast<int>(node.source().begin.line);
    e.origin = source + ":" + std::to_string(e.line);
    e.kind_name = toml_type_name(node.type());
    if (const auto* sub = node.as_table()) {
      e.kind = RawKind::Other;
      doc.sections.push_back(e);
      flatten(*sub, key, source, doc);
      continue;
    }
    switch (node.type()) {
      case toml::node_type::string: e.kind = RawKind::String; break;
      case toml::node_type::integer: e.kind = RawKind::Integer; break;
      case toml::node_type::floating_point: e.kind = RawKind::Float; break;
      case toml::node_type::boolean: e.kind = RawKind::Boolean; break;
      case toml::node_type::array: e.kind = RawKind::Array; break;
      default: e.kind = RawKind::Other; break;
    }
    if (e.kind == RawKind::Boolean) {
      e.text = *node.value_exact<bool>() ? "true" : "false";
    } else if (e.kind == RawKind::Array) {
      e.text = "[";
      const auto& arr = *node.as_array();
      for (std::size_t i = 0; i < arr.size(); ++i) {
        std::string item;
        if (arr[i].is_boolean() || !toml_scalar_text(arr[i], item)) {
          e.kind = RawKind::Other;
          e.kind_name = std::string("array of ") + toml_type_name(arr[i].type()) + "s";
          break;
        }
        if (i > 0) e.text += ", ";
        e.text += item;
      }
      e.text += "]";
    } else if (e.kind != RawKind::Other) {
      toml_scalar_text(node, e.text);
    }
    doc.entries.push_back(std::move(e));
  }
}

[[noreturn]] void fail(const std::string& origin, std::string_view key, const std::string& what,
                       const KeySpec* spec = nullptr) {
  std::string msg = origin + ": " + std::string(key) + ": " + what;
  if (spec != nullptr) msg += "; allowed: " + range_text(*spec);
  throw InputError(msg);
}

// One element of a quantity: the one rule of quantity_text.hpp, then the parameter's range.
double check_number(const KeySpec& spec, const Range* range, std::string_view text, const std::string& origin) {
  const std::string_view t = trim_blanks(text);
  double v = 0.0;
  try {
    v = read_quantity(t, spec.dim);
  } catch (const InputError& e) {
    fail(origin, spec.key, e.what(), &spec);
  }
  if (!(range ? *range : kAnyFinite).contains(v) || !std::isfinite(v)) {
    fail(origin, spec.key, "'" + std::string(t) + "' is out of range", &spec);
  }
  return v;
}

std::vector<std::string_view> split_list(std::string_view text) {
  std::string_view s = trim_blanks(text);
  if (!s.empty() && s.front() == '[' && s.back() == ']') s = s.substr(1, s.size() - 2);
  std::vector<std::string_view> out;
  if (trim_blanks(s).empty()) return out;
  while (true) {
    const auto comma = s.find(',');
    out.push_back(trim_blanks(s.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    s.remove_prefix(comma + 1);
  }
  return out;
}

bool in_choices(std::string_view choices, std::string_view v) {
  while (true) {
    const auto bar = choices.find('|');
    if (choices.substr(0, bar) == v) return true;
    if (bar == std::string_view::npos) return false;
    choices.remove_prefix(bar + 1);
  }
}

}  // namespace

const DocEntry* ScenarioDoc::find(std::string_view key) const {
  for (const auto& e : entries) {
    if (e.key == key) return &e;
  }
  return nullptr;
}

ScenarioDoc parse_toml_doc(std::string_view toml_text, const std::string& source) {
  ScenarioDoc doc;
  doc.source = source;
  toml::table table;
  try {
    table = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(source + ":" + std::to_string(e.source().begin.line) + ":" +
                     std::to_string(e.source().begin.column) + ": malformed TOML: " +
                     std::string(e.description()));
  }
  flatten(table, "", source, doc);
  auto by_line = [](const DocEntry& a, const DocEntry& b) { return a.line < b.line; };
  std::stable_sort(doc.entries.begin(), doc.entries.end(), by_line);
  std::stable_sort(doc.sections.begin(), doc.sections.end(), by_line);
  return doc;
}

ScenarioDoc read_toml_doc(const std::filesystem::path& path) {
  return parse_toml_doc(read_data_file(path, "scenario"), path.string());
}

std::string set_key(std::string_view assignment) {
  const auto eq = assignment.find('=');
  return eq == std::string_view::npos ? std::string() : std::string(trim_blanks(assignment.substr(0, eq)));
}

void apply_set(ScenarioDoc& doc, std::string_view assignment, std::string_view origin_in) {
  const std::string origin = origin_in.empty() ? "--set " + std::string(assignment) : std::string(origin_in);
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos) {
    throw InputError(origin + ": expected key=value in dotted form, e.g. --set swing.speed=105mph");
  }
  const std::string key(trim_blanks(assignment.substr(0, eq)));
  const std::string value(trim_blanks(assignment.substr(eq + 1)));
  if (key.empty()) throw InputError(origin + ": empty key; expected key=value, e.g. --set swing.speed=105mph");
  DocEntry e;
  e.key = key;
  e.text = value;
  e.kind = RawKind::Text;
  e.kind_name = "text";
  e.origin = origin;
  for (auto& existing : doc.entries) {
    if (existing.key == key) {
      // A command-line value replaces the file's; two command-line values for one key
      // would silently drop one of them (and with it any error it has), so they are refused.
      if (existing.line == 0)
        throw InputError(origin + ": " + key + " is already set by " + existing.origin + "; give each key once");
      existing = e;
      return;
    }
  }
  doc.entries.push_back(e);
}

CheckedValue check_value(const KeySpec& spec, std::string_view text, RawKind kind,
                         std::string_view kind_name, const std::string& origin) {
  CheckedValue out;
  out.spec = &spec;
  out.origin = origin;
  const bool textual = kind == RawKind::String || kind == RawKind::Text;
  auto wrong_type = [&](const std::string& expected) {
    fail(origin, spec.key, "wrong type: expected " + expected + ", got " + std::string(kind_name), &spec);
  };
  switch (spec.type) {
    case ValueType::Quantity: {
      if (!(textual || kind == RawKind::Integer || kind == RawKind::Float)) {
        wrong_type(needs_unit(spec.dim) ? "a quantity with a unit such as \"113mph\"" : "a number");
      }
      if (kind != RawKind::Text && kind != RawKind::String && needs_unit(spec.dim)) {
        fail(origin, spec.key,
             "missing unit: write the value as a string with a unit, e.g. \"" + std::string(trim_blanks(text)) + std::string(spec.unit) + "\"",
             &spec);
      }
      out.number = check_number(spec, spec.range[0], text, origin);
      break;
    }
    case ValueType::QuantityList: {
      if (!(textual || kind == RawKind::Array)) {
        wrong_type("a list of " + std::to_string(spec.list_size) + " quantities such as [\"10mm\", \"0mm\"]");
      }
      const auto items = split_list(text);
      if (static_cast<int>(items.size()) != spec.list_size) {
        fail(origin, spec.key,
             "expected " + std::to_string(spec.list_size) + " values, got " + std::to_string(items.size()) +
                 " in '" + std::string(text) + "'",
             &spec);
      }
      for (size_t i = 0; i < items.size(); ++i)
        out.list.push_back(check_number(spec, spec.range[std::min<size_t>(i, 2)], items[i], origin));
      break;
    }
    case ValueType::Choice: {
      if (!textual) wrong_type("a string");
      const std::string v(trim_blanks(text));
      if (!in_choices(spec.choices, v)) fail(origin, spec.key, "unknown value '" + v + "'", &spec);
      out.text = v;
      break;
    }
    case ValueType::Name: {
      if (!textual) wrong_type("a name (string)");
      out.text = std::string(trim_blanks(text));
      if (out.text.empty()) fail(origin, spec.key, "empty name (leave the key out for the default)");
      break;
    }
    case ValueType::Text: {
      if (!textual) wrong_type("a string");
      out.text = std::string(text);
      break;
    }
    case ValueType::Bool: {
      const std::string v(trim_blanks(text));
      if (kind != RawKind::Boolean && !(kind == RawKind::Text && (v == "true" || v == "false"))) {
        wrong_type("true or false");
      }
      out.text = v;
      break;
    }
  }
  return out;
}

CheckedDoc::CheckedDoc(const ScenarioDoc& doc, const Schema& schema, const SportCatalog* sports)
    : source_(doc.source), schema_(&schema) {
  strikes_ = kAnyStrike;
  std::string sport_origin;  // where the sport was given: the file's line or "--set sport=..."
  if (const KeySpec* sport_spec = schema.find("sport", kAnyStrike)) {
    const DocEntry* e = doc.find("sport");
    if (e == nullptr) {
      throw InputError(doc.source + ": missing key 'sport'" +
                       (sports ? " (allowed: " + sports->names() + ")" : std::string()));
    }
    const auto v = check_value(*sport_spec, e->text, e->kind, e->kind_name, e->origin);
    sport_origin = e->origin;
    if (sports != nullptr) {
      try {
        sport_ = &sports->get(v.text);
      } catch (const InputError& err) {
        fail(e->origin, "sport", err.what());
      }
      strikes_ = sport_->impactor == ImpactorKind::Club ? kClubKeys : kBatKeys;
    }
  }
  const std::string sport_word = sport_ == nullptr ? std::string() : " for " + sport_->name;
  // "unknown key (allowed in [swing] for golf: ...)", or, for a section this sport has no
  // keys in ([bat] in a golf scenario), say so instead of listing nothing.
  const auto unknown_in = [&](std::string_view section) {
    const std::string keys = schema.keys_in_section(section, strikes_);
    if (keys.empty()) return "unknown key ([" + std::string(section) + "] has no keys" + sport_word + ")";
    return "unknown key (allowed in [" + std::string(section) + "]" + sport_word + ": " + keys + ")";
  };

  for (const auto& s : doc.sections) {
    if (schema.has_section(s.key)) continue;
    // A key written as a table (`[update]` for `update = false`) holds no value: refused,
    // not read as the key left out.
    if (schema.find(s.key, kAnyStrike) != nullptr) fail(s.origin, s.key, "a value, not a table: write " + s.key + " = ...");
    const auto parent = parent_section_of(s.key);
    if (!parent.empty() && schema.has_section(parent)) {
      fail(s.origin, s.key, unknown_in(parent));
    }
    fail(s.origin, s.key, "unknown section (sections of a " + std::string(schema.name) + ": " +
                              schema.section_names() + ")");
  }

  for (const auto& e : doc.entries) {
    const KeySpec* spec = schema.find(e.key, strikes_);
    if (spec == nullptr) {
      if (const KeySpec* other = schema.find(e.key, kAnyStrike)) {
        const bool club = (other->strikes & kClubKeys) != 0;
        // A sport switched by --set leaves the file's keys of the other sport: say which set it.
        const std::string switched = sport_origin.rfind("--set", 0) == 0
                                         ? " (" + sport_origin + "; a scenario's sport is not switched by --set: pick a scenario of that sport)"
                                         : std::string();
        fail(e.origin, e.key, std::string("applies to scenarios that swing a ") + (club ? "club" : "bat") +
                                  "; this one is " + (sport_ ? sport_->name : std::string("another sport")) + switched);
      }
      const auto section = parent_section_of(e.key);
      if (!section.empty() && schema.has_section(section)) {
        fail(e.origin, e.key, unknown_in(section));
      }
      fail(e.origin, e.key, "unknown key (allowed sections of a " + std::string(schema.name) + ": " +
                                schema.section_names() + ")");
    }
    values_[e.key] = check_value(*spec, e.text, e.kind, e.kind_name, e.origin);
    raw_[e.key] = e.text;
    order_.push_back(e.key);
  }

  // Every expectation needs its tolerance and the other way round.
  for (const auto& key : order_) {
    if (key.rfind("expect.", 0) != 0 || key == "expect.contact") continue;
    const bool is_tol = key.size() > 4 && key.compare(key.size() - 4, 4, "_tol") == 0;
    const std::string partner = is_tol ? key.substr(0, key.size() - 4) : key + "_tol";
    if (values_.count(partner) == 0) {
      fail(values_.at(key).origin, key,
           is_tol ? "a tolerance without its expected value " + partner
                  : "an expected value without its tolerance; add " + partner);
    }
  }

  // Schema defaults that apply to this sport, so every getter is a plain lookup.
  for (const auto& spec : schema.keys) {
    if (spec.default_text.empty() || (spec.strikes & strikes_) == 0) continue;
    if (values_.count(spec.key) != 0) continue;
    CheckedValue v = check_value(spec, spec.default_text, RawKind::Text, "text", "default");
    v.from_default = true;
    values_.emplace(std::string(spec.key), std::move(v));
  }
}

const CheckedValue& CheckedDoc::get(std::string_view key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) {
    const KeySpec* spec = schema_->find(key, strikes_);
    std::string msg = source_ + ": missing key '" + std::string(key) + "'";
    if (spec != nullptr) msg += " (" + std::string(spec->doc) + "); allowed: " + range_text(*spec);
    throw InputError(msg);
  }
  return it->second;
}

bool CheckedDoc::has(std::string_view key) const {
  const auto it = values_.find(key);
  return it != values_.end() && !it->second.from_default;
}

double CheckedDoc::quantity(std::string_view key) const { return get(key).number; }
std::vector<double> CheckedDoc::list(std::string_view key) const { return get(key).list; }
std::string CheckedDoc::text(std::string_view key) const { return get(key).text; }
bool CheckedDoc::flag(std::string_view key) const { return get(key).text == "true"; }

std::optional<double> CheckedDoc::quantity_if_set(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return get(key).number;
}

std::optional<std::string> CheckedDoc::text_if_set(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return get(key).text;
}

std::string CheckedDoc::origin(std::string_view key) const {
  const auto it = values_.find(key);
  return it == values_.end() ? source_ : it->second.origin;
}

std::string CheckedDoc::raw_text(std::string_view key) const {
  const auto it = raw_.find(key);
  return it == raw_.end() ? std::string() : it->second;
}

}  // namespace sweetspot
