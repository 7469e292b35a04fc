#include "game/tuning/regression_report.hpp"

#include <cstdint>

namespace sweetspot {
namespace {

/// Length of the valid UTF-8 sequence at s[i] (1..4), or 0 when it is not one.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto b = static_cast<unsigned char>(s[i]);
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if (b < 0x80) return 1;
  if ((b & 0xE0) == 0xC0) n = 2, cp = b & 0x1F;
  else if ((b & 0xF0) == 0xE0) n = 3, cp = b & 0x0F;
  else if ((b & 0xF8) == 0xF0) n = 4, cp = b & 0x07;
  else return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto c = static_cast<unsigned char>(s[i + k]);
    if ((c & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (c & 0x3F);
  }
  // Overlong forms, surrogates and code points past U+10FFFF are not valid UTF-8; U+FFFE/F
  // are not XML characters.
  static constexpr std::uint32_t kMin[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kMin[n] || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF || cp == 0xFFFE || cp == 0xFFFF) return 0;
  return n;
}

/// `text` escaped for an XML attribute or element.
std::string xml(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const std::size_t n = utf8_length(text, i);
    if (n == 0 || (n == 1 && static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r')) {
      out += "\xEF\xBF\xBD";  // U+FFFD: XML 1.0 has no escape for these
      ++i;
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      case '\t': out += "&#9;"; break;
      default: out.append(text, i, n);
    }
    i += n;
  }
  return out;
}

std::string with_unit(const std::string& number, const std::string& unit) {
  return unit.empty() ? number : number + " " + unit;
}

}  // namespace

std::string regression_junit(const std::vector<RegressionCaseResult>& results) {
  int checks = 0, failures = 0;
  for (const auto& c : results)
    for (const auto& r : c.rows) ++checks, failures += r.pass ? 0 : 1;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites name=\"sweetspot regress\" tests=\"" + std::to_string(checks) + "\" failures=\"" +
         std::to_string(failures) + "\" errors=\"0\">\n";
  for (const auto& c : results) {
    int case_failures = 0;
    for (const auto& r : c.rows) case_failures += r.pass ? 0 : 1;
    out += "  <testsuite name=\"" + xml(c.name) + "\" file=\"" + xml(c.path.string()) + "\" tests=\"" +
           std::to_string(c.rows.size()) + "\" failures=\"" + std::to_string(case_failures) + "\" errors=\"0\">\n";
    for (const auto& r : c.rows) {
      out += "    <testcase classname=\"regress." + xml(c.name) + "\" name=\"" + xml(r.quantity) + "\"";
      if (r.pass) {
        out += "/>\n";
        continue;
      }
      const std::string tol = r.numeric ? with_unit(r.tolerance, r.unit) : "exact";
      const std::string delta = r.numeric ? ", delta " + with_unit(r.delta, r.unit) : "";
      const std::string message =
          r.quantity + ": expected " + r.expected + ", actual " + r.got + delta + ", tolerance " + tol;
      out += ">\n      <failure type=\"drift\" message=\"" + xml(message) + "\">";
      out += xml("expected: " + r.expected + "\nactual: " + r.got + "\n" +
                 (r.numeric ? "delta: " + with_unit(r.delta, r.unit) + "\n" : "") + "tolerance: " + tol + "\n" +
                 "where: " + r.origin + "\n");
      out += "</failure>\n    </testcase>\n";
    }
    out += "  </testsuite>\n";
  }
  out += "</testsuites>\n";
  return out;
}

nlohmann::json regression_json(const std::vector<RegressionCaseResult>& results) {
  nlohmann::json cases = nlohmann::json::array();
  int checks = 0, failed = 0;
  for (const auto& c : results) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& r : c.rows) {
      nlohmann::json row{{"quantity", r.quantity}, {"pass", r.pass},   {"expected", r.expected},
                         {"got", r.got},           {"origin", r.origin}};
      if (r.numeric) {
        row["delta"] = r.delta;
        row["tolerance"] = r.tolerance;
        row["unit"] = r.unit;
        row["expected_si"] = r.expected_si;
        row["got_si"] = r.got_si;
        row["tolerance_si"] = r.tolerance_si;
        row["si_unit"] = r.si_unit;
      }
      rows.push_back(std::move(row));
      ++checks;
      failed += r.pass ? 0 : 1;
    }
    cases.push_back({{"name", c.name},
                     {"path", c.path.string()},
                     {"reference", c.reference},
                     {"passed", c.passed()},
                     {"checks", std::move(rows)}});
  }
  return {{"cases", std::move(cases)}, {"checks", checks}, {"failed", failed}};
}

}  // namespace sweetspot
