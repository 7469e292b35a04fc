#include "game/tuning/validation_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "game/content/scenario_schema.hpp"
#include "game/util/xml_text.hpp"

namespace sweetspot {
namespace {

// `si` in the unit the case wrote; a difference (a change, a tolerance) without the unit's
// offset (none of the quantities has one today, but a temperature would).
std::string shown(double si, const ValidationCase& c, bool difference) {
  const Dimension dim = c.quantity->dim;
  const double v = si_to_unit(si, c.unit, dim) - (difference ? si_to_unit(0.0, c.unit, dim) : 0.0);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", std::fabs(v) < 1e-12 ? 0.0 : v);
  return std::string(buf) + (c.unit.empty() ? "" : " " + c.unit);
}

std::string pad(const std::string& s, std::size_t w) { return s.size() >= w ? s : s + std::string(w - s.size(), ' '); }

std::string tally_text(const ValidationTally& t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%d/%d (%.1f %%)", t.passed, t.total(), t.percent());
  return buf;
}

}  // namespace

ValidationTotals validation_totals(const std::vector<ValidationOutcome>& outcomes) {
  ValidationTotals t;
  std::set<std::string> sources;
  for (const auto& o : outcomes) {
    (o.passed ? t.all.passed : t.all.failed)++;
    if (!o.c->fitted) (o.passed ? t.not_fitted.passed : t.not_fitted.failed)++;
    sources.insert(o.c->source);
  }
  t.sources = static_cast<int>(sources.size());
  return t;
}

std::string validation_scorecard(const std::vector<ValidationOutcome>& outcomes, std::size_t worst) {
  const ValidationTotals totals = validation_totals(outcomes);
  std::string out = "validate: " + std::to_string(outcomes.size()) + " published references from " +
                    std::to_string(totals.sources) + " sources (" +
                    std::to_string(totals.all.total() - totals.not_fitted.total()) + " used in a fit)\n\n";
  // By tag, in the order the tags are defined, sport rows first.
  std::map<std::string, std::pair<ValidationTally, ValidationTally>> by_tag;
  for (const auto& o : outcomes)
    for (const auto& tag : o.c->tags) {
      auto& [all, nf] = by_tag[tag];
      (o.passed ? all.passed : all.failed)++;
      if (!o.c->fitted) (o.passed ? nf.passed : nf.failed)++;
    }
  out += pad("tag", 12) + pad("all", 20) + "not fitted\n";
  for (const auto tag : validation_tags()) {
    const auto it = by_tag.find(std::string(tag));
    if (it == by_tag.end()) continue;
    out += pad(std::string(tag), 12) + pad(tally_text(it->second.first), 20) + tally_text(it->second.second) + "\n";
  }
  out += pad("every case", 12) + pad(tally_text(totals.all), 20) + tally_text(totals.not_fitted) + "\n\n";

  // Failing cases first (worst first), then the passing ones nearest their edge.
  std::vector<const ValidationOutcome*> order;
  for (const auto& o : outcomes) order.push_back(&o);
  std::stable_sort(order.begin(), order.end(), [](const ValidationOutcome* a, const ValidationOutcome* b) {
    return std::fabs(a->error_in_tolerances()) > std::fabs(b->error_in_tolerances());
  });
  const std::size_t failing = static_cast<std::size_t>(totals.all.failed);
  const std::size_t n = std::min(order.size(), std::max(worst, failing));
  if (n > 0) {
    std::vector<std::vector<std::string>> rows{{"case", "quantity", "published", "got", "tol", "err/tol", ""}};
    for (std::size_t i = 0; i < n; ++i) {
      const ValidationOutcome& o = *order[i];
      const ValidationCase& c = *o.c;
      const bool diff = !c.baseline.empty();
      char err[32];
      const double e = o.error_in_tolerances();
      std::snprintf(err, sizeof err, std::fabs(e) < 1e4 ? "%+.2f" : "%+.3g", e);  // 1e308 yd is no 309-digit row
      rows.push_back({c.id + (c.fitted ? " (fitted)" : ""), std::string(c.quantity->name) + (diff ? " change" : ""),
                      shown(c.published, c, diff), shown(o.got, c, diff), shown(c.tolerance, c, true), err,
                      o.passed ? "pass" : "FAIL"});
    }
    std::vector<std::size_t> w(rows[0].size(), 0);
    for (const auto& r : rows)
      for (std::size_t i = 0; i < r.size(); ++i) w[i] = std::max(w[i], r[i].size());
    out += failing == 0 ? "every case passes; those nearest their edge:\n"
           : n > failing ? "failing cases, then the passing ones nearest their edge:\n"
                         : "failing cases, worst first:\n";
    for (const auto& r : rows) {
      std::string line = " ";
      for (std::size_t i = 0; i < r.size(); ++i) line += " " + (i + 1 < r.size() ? pad(r[i], w[i]) : r[i]);
      out += line + "\n";
    }
    out += "\n";
  }
  out += "validate: " + std::to_string(totals.all.passed) + " passed, " + std::to_string(totals.all.failed) + " failed\n";
  return out;
}

nlohmann::json validation_json(const ValidationLibrary& lib, const std::vector<ValidationOutcome>& outcomes) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& o : outcomes) {
    const ValidationCase& c = *o.c;
    const ValidationSource* s = lib.source(c.source);
    cases.push_back({{"id", c.id},
                     {"source", c.source},
                     {"source_title", s ? s->authors + ", " + s->title + " (" + std::to_string(s->year) + ")" : ""},
                     {"tags", c.tags},
                     {"fitted", c.fitted},
                     {"quantity", std::string(c.quantity->name)},
                     {"change_from_baseline", !c.baseline.empty()},
                     {"published", c.published},
                     {"got", o.got},
                     {"tolerance", c.tolerance},
                     {"si_unit", std::string(si_unit_name(c.quantity->dim))},
                     {"error_in_tolerances", o.error_in_tolerances()},
                     {"passed", o.passed},
                     {"why", c.why},
                     {"origin", c.origin}});
  }
  const ValidationTotals t = validation_totals(outcomes);
  return {{"cases", cases},
          {"passed", t.all.passed},
          {"failed", t.all.failed},
          {"sources", t.sources},
          {"not_fitted", {{"passed", t.not_fitted.passed}, {"failed", t.not_fitted.failed}}}};
}

std::string validation_junit(const ValidationLibrary& lib, const std::vector<ValidationOutcome>& outcomes) {
  const ValidationTotals t = validation_totals(outcomes);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites name=\"sweetspot validate\" tests=\"" + std::to_string(t.all.total()) + "\" failures=\"" +
         std::to_string(t.all.failed) + "\" errors=\"0\">\n";
  for (const std::string sport : {"golf", "baseball"}) {
    std::string body;
    int tests = 0, failures = 0;
    for (const auto& o : outcomes) {
      const ValidationCase& c = *o.c;
      if (c.tags.front() != sport) continue;
      ++tests;
      body += "    <testcase classname=\"validate." + sport + "\" name=\"" + xml_escape(c.id) + "\"";
      if (o.passed) {
        body += "/>\n";
        continue;
      }
      ++failures;
      const bool diff = !c.baseline.empty();
      const ValidationSource* s = lib.source(c.source);
      const std::string message = std::string(c.quantity->name) + ": published " + shown(c.published, c, diff) + ", got " +
                                  shown(o.got, c, diff) + " (tolerance " + shown(c.tolerance, c, true) + ")";
      body += ">\n      <failure type=\"out of band\" message=\"" + xml_escape(message) + "\">";
      body += xml_escape(message + "\nsource: " + (s ? s->authors + ", " + s->title + ", " + s->where : c.source) +
                         "\ntolerance: " + c.why + "\ncase: " + c.origin);
      body += "</failure>\n    </testcase>\n";
    }
    if (tests == 0) continue;
    out += "  <testsuite name=\"" + sport + "\" tests=\"" + std::to_string(tests) + "\" failures=\"" +
           std::to_string(failures) + "\" errors=\"0\">\n" + body + "  </testsuite>\n";
  }
  return out + "</testsuites>\n";
}

}  // namespace sweetspot
