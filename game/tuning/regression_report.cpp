#include "game/tuning/regression_report.hpp"

#include <cstdint>

#include "game/util/xml_text.hpp"

namespace sweetspot {
namespace {

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
    out += "  <testsuite name=\"" + xml_escape(c.name) + "\" file=\"" + xml_escape(c.path.string()) + "\" tests=\"" +
           std::to_string(c.rows.size()) + "\" failures=\"" + std::to_string(case_failures) + "\" errors=\"0\">\n";
    for (const auto& r : c.rows) {
      out += "    <testcase classname=\"regress." + xml_escape(c.name) + "\" name=\"" + xml_escape(r.quantity) + "\"";
      if (r.pass) {
        out += "/>\n";
        continue;
      }
      const std::string tol = r.numeric ? with_unit(r.tolerance, r.unit) : "exact";
      const std::string delta = r.numeric ? ", delta " + with_unit(r.delta, r.unit) : "";
      const std::string message =
          r.quantity + ": expected " + r.expected + ", actual " + r.got + delta + ", tolerance " + tol;
      out += ">\n      <failure type=\"drift\" message=\"" + xml_escape(message) + "\">";
      out += xml_escape("expected: " + r.expected + "\nactual: " + r.got + "\n" +
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
