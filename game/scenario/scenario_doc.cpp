// TOML -> flat dotted keys -> checked SI values. toml++ keeps tables sorted by key, so
// entries are re-sorted by line to report the first problem in reading order.
#include "game/scenario/scenario_doc.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::string_view section_of(std::string_view key) {
  const auto dot = key.rfind('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}

std::string number_text(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
  return std::string(buf, res.ptr);
}

const char* type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table: return "table";
    case toml::node_type::array: return "array";
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "float";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    default: return "value";
  }
}

// Scalar node -> text; false when the node is not a string or number.
bool scalar_text(const toml::node& n, std::string& out) {
  if (auto s = n.value_exact<std::string>()) {
    out = *s;
    return true;
  }
  if (auto i = n.value_exact<std::int64_t>()) {
    out = std::to_string(*i);
    return true;
  }
  if (auto d = n.value_exact<double>()) {
    out = number_text(*d);
    return true;
  }
  return false;
}

void flatten(const toml::table& table, const std::string& prefix, const std::string& source,
             ScenarioDoc& doc) {
  for (auto&& [k, node] : table) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    DocEntry e;
    e.key = key;
    e.line = static_cast<int>(node.source().begin.line);
    e.origin = source + ":" + std::to_string(e.line);
    e.kind_name = type_name(node.type());
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
        if (!scalar_text(arr[i], item)) {
          e.kind = RawKind::Other;
          e.kind_name = std::string("array of ") + type_name(arr[i].type()) + "s";
          break;
        }
        if (i > 0) e.text += ", ";
        e.text += item;
      }
      e.text += "]";
    } else if (e.kind != RawKind::Other) {
      scalar_text(node, e.text);
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

// True when something follows the number ("113mph", "8e-6kg*m^2"); a malformed number
// counts as having a unit so parse_quantity reports it properly.
bool has_unit(std::string_view t) {
  const char* first = t.data();
  const char* last = t.data() + t.size();
  if (first != last && (*first == '+' || *first == '-')) ++first;
  double v = 0.0;
  const auto res = std::from_chars(first, last, v);
  if (res.ec == std::errc::invalid_argument) return true;
  return !trim(std::string_view(res.ptr, static_cast<std::size_t>(last - res.ptr))).empty();
}

bool is_dimensional(Dimension d) { return d != Dimension::Dimensionless && d != Dimension::Fraction; }

// One element of a quantity: requires a unit for dimensional keys, then parses and checks
// the range.
double check_number(const KeySpec& spec, std::string_view text, const std::string& origin) {
  const std::string_view t = trim(text);
  if (t.empty()) fail(origin, spec.key, "empty value", &spec);
  if (is_dimensional(spec.dim) && !has_unit(t)) {
    fail(origin, spec.key,
         "missing unit in '" + std::string(t) + "' (a " + std::string(dimension_name(spec.dim)) +
             " needs one of: " + accepted_units(spec.dim) + ")",
         &spec);
  }
  double v = 0.0;
  try {
    v = parse_quantity(t, spec.dim);
  } catch (const InputError& e) {
    fail(origin, spec.key, e.what(), &spec);
  }
  const bool below = spec.min_exclusive ? !(v > spec.min) : !(v >= spec.min);
  if (below || !(v <= spec.max)) {
    fail(origin, spec.key, "'" + std::string(t) + "' is out of range", &spec);
  }
  return v;
}

std::vector<std::string_view> split_list(std::string_view text) {
  std::string_view s = trim(text);
  if (!s.empty() && s.front() == '[' && s.back() == ']') s = s.substr(1, s.size() - 2);
  std::vector<std::string_view> out;
  if (trim(s).empty()) return out;
  while (true) {
    const auto comma = s.find(',');
    out.push_back(trim(s.substr(0, comma)));
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
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError("cannot read '" + path.string() + "': no such file");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError("cannot read '" + path.string() + "': it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path.string() + "': permission denied or unreadable");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_toml_doc(ss.str(), path.string());
}

void apply_set(ScenarioDoc& doc, std::string_view assignment, std::string_view origin_in) {
  const std::string origin = origin_in.empty() ? "--set " + std::string(assignment) : std::string(origin_in);
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos) {
    throw InputError(origin + ": expected key=value in dotted form, e.g. --set swing.speed=105mph");
  }
  const std::string key(trim(assignment.substr(0, eq)));
  const std::string value(trim(assignment.substr(eq + 1)));
  if (key.empty()) throw InputError(origin + ": empty key; expected key=value, e.g. --set swing.speed=105mph");
  DocEntry e;
  e.key = key;
  e.text = value;
  e.kind = RawKind::Text;
  e.kind_name = "text";
  e.origin = origin;
  for (auto& existing : doc.entries) {
    if (existing.key == key) {
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
        wrong_type(is_dimensional(spec.dim) ? "a quantity with a unit such as \"113mph\"" : "a number");
      }
      if (kind != RawKind::Text && kind != RawKind::String && is_dimensional(spec.dim)) {
        fail(origin, spec.key,
             "missing unit: write the value as a string with a unit, e.g. \"" + std::string(trim(text)) + std::string(spec.unit) + "\"",
             &spec);
      }
      out.number = check_number(spec, text, origin);
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
      for (const auto item : items) out.list.push_back(check_number(spec, item, origin));
      break;
    }
    case ValueType::Choice: {
      if (!textual) wrong_type("a string");
      const std::string v(trim(text));
      if (!in_choices(spec.choices, v)) fail(origin, spec.key, "unknown value '" + v + "'", &spec);
      out.text = v;
      break;
    }
    case ValueType::Name: {
      if (!textual) wrong_type("a name (string)");
      out.text = std::string(trim(text));
      if (out.text.empty()) fail(origin, spec.key, "empty name");
      break;
    }
    case ValueType::Text: {
      if (!textual) wrong_type("a string");
      out.text = std::string(text);
      break;
    }
    case ValueType::Bool: {
      const std::string v(trim(text));
      if (kind != RawKind::Boolean && !(kind == RawKind::Text && (v == "true" || v == "false"))) {
        wrong_type("true or false");
      }
      out.text = v;
      break;
    }
  }
  return out;
}

CheckedDoc::CheckedDoc(const ScenarioDoc& doc, const Schema& schema)
    : source_(doc.source), schema_(&schema) {
  if (const KeySpec* sport_spec = schema.find("sport", 0)) {
    const DocEntry* e = doc.find("sport");
    if (e == nullptr) {
      throw InputError(doc.source + ": missing key 'sport'; allowed: " + range_text(*sport_spec));
    }
    const auto v = check_value(*sport_spec, e->text, e->kind, e->kind_name, e->origin);
    sport_ = static_cast<std::uint8_t>(v.text == "golf" ? Sport::Golf : Sport::Baseball);
  }
  const std::string sport_word = sport_ == 0 ? std::string() : std::string(" for ") + to_string(sport());

  for (const auto& s : doc.sections) {
    if (schema.has_section(s.key) || schema.find(s.key, 0) != nullptr) continue;
    const auto parent = section_of(s.key);
    if (!parent.empty() && schema.has_section(parent)) {
      fail(s.origin, s.key, "unknown key (keys in [" + std::string(parent) + "]" + sport_word + ": " +
                                schema.keys_in_section(parent, sport_) + ")");
    }
    fail(s.origin, s.key, "unknown section (sections of a " + std::string(schema.name) + ": " +
                              schema.section_names() + ")");
  }

  for (const auto& e : doc.entries) {
    const KeySpec* spec = schema.find(e.key, sport_);
    if (spec == nullptr) {
      if (const KeySpec* other = schema.find(e.key, 0)) {
        const bool golf = (other->sports & kGolfOnly) != 0;
        fail(e.origin, e.key, std::string("applies to ") + (golf ? "golf" : "baseball") +
                                  " scenarios only; this one is " + to_string(sport()));
      }
      const auto section = section_of(e.key);
      if (!section.empty() && schema.has_section(section)) {
        fail(e.origin, e.key, "unknown key (keys in [" + std::string(section) + "]" + sport_word + ": " +
                                  schema.keys_in_section(section, sport_) + ")");
      }
      fail(e.origin, e.key, "unknown key (sections of a " + std::string(schema.name) + ": " +
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
    if (spec.default_text.empty() || (sport_ != 0 && (spec.sports & sport_) == 0)) continue;
    if (values_.count(spec.key) != 0) continue;
    CheckedValue v = check_value(spec, spec.default_text, RawKind::Text, "text", "default");
    v.from_default = true;
    values_.emplace(std::string(spec.key), std::move(v));
  }
}

const CheckedValue& CheckedDoc::get(std::string_view key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) {
    const KeySpec* spec = schema_->find(key, sport_);
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
