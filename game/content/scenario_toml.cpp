#include "game/content/scenario_toml.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace sweetspot {

std::string quantity_text(double value, const std::string& unit) {
  // The shortest text that reads back as the same double: "0.808", never "0.808000028".
  char buf[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (std::strtod(buf, nullptr) == value) break;
  }
  return std::string(buf) + unit;
}

double float_as_decimal(float value) {
  // A slider's 0.808f is 0.808000028... as a double; the user set 0.808.
  char buf[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, static_cast<double>(value));
    if (static_cast<float>(std::strtod(buf, nullptr)) == value) break;
  }
  return std::strtod(buf, nullptr);
}

std::string quantity_list_text(const std::vector<double>& values, const std::string& unit) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out += ", ";
    out += quantity_text(values[i], unit);
  }
  return out + "]";
}

namespace {

std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// "[10mm, 0mm]" -> ["10mm", "0mm"]; a value already in TOML array syntax with quoted
// elements passes through unchanged.
std::string toml_array(const std::string& text) {
  std::string inner = text.substr(1, text.size() - 2);
  if (inner.find('"') != std::string::npos) return text;
  std::string out = "[";
  std::stringstream ss(inner);
  std::string item;
  bool first = true;
  while (std::getline(ss, item, ',')) {
    const auto b = item.find_first_not_of(" \t");
    const auto e = item.find_last_not_of(" \t");
    if (b == std::string::npos) continue;
    if (!first) out += ", ";
    out += toml_string(item.substr(b, e - b + 1));
    first = false;
  }
  return out + "]";
}

/// True for text that is a finite number and nothing else ("0.808", "-1e-3"): TOML takes it
/// bare. Quantities with a unit ("30mph") stay strings.
bool is_plain_number(const std::string& text) {
  // TOML's integer/float grammar: [+-] (0 | [1-9][0-9]*) [.[0-9]+] [(e|E)[+-][0-9]+], read by
  // hand (GCC 12's <regex> trips -Wmaybe-uninitialized in the sanitizer build).
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    return i - from;
  };
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t int_start = i;
  const std::size_t int_digits = digits();
  if (int_digits == 0 || (int_digits > 1 && text[int_start] == '0')) return false;
  if (i < text.size() && text[i] == '.') {
    ++i;
    if (digits() == 0) return false;
  }
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == text.size() && std::isfinite(std::strtod(text.c_str(), nullptr));
}

std::string toml_value(const DocEntry& e) {
  switch (e.kind) {
    case RawKind::Integer:
    case RawKind::Float:
    case RawKind::Boolean:
      return e.text;
    case RawKind::Array:
      return toml_array(e.text);
    case RawKind::Text:
      if (!e.text.empty() && e.text.front() == '[' && e.text.back() == ']') return toml_array(e.text);
      if (is_plain_number(e.text)) return e.text;  // a dimensionless override (e, µ): bare, as files write it
      return toml_string(e.text);
    default:
      return toml_string(e.text);
  }
}

}  // namespace

std::string scenario_toml(const Scenario& scenario) {
  // Top-level keys first, then one table per section in the order the document first
  // mentions it, so a saved file reads like the built-in it came from.
  std::ostringstream out;
  out << "# Saved from the Sweetspot window (scenario " << scenario.name << ").\n";
  std::vector<std::string> sections;
  std::map<std::string, std::vector<const DocEntry*>> by_section;
  for (const DocEntry& e : scenario.doc.entries) {
    const auto dot = e.key.find('.');
    if (dot == std::string::npos) {
      out << e.key << " = " << toml_value(e) << "\n";
      continue;
    }
    const std::string section = e.key.substr(0, dot);
    if (!by_section.count(section)) sections.push_back(section);
    by_section[section].push_back(&e);
  }
  for (const std::string& section : sections) {
    out << "\n[" << section << "]\n";
    for (const DocEntry* e : by_section[section])
      out << e->key.substr(section.size() + 1) << " = " << toml_value(*e) << "\n";
  }
  return out.str();
}

}  // namespace sweetspot
