// Regression cases. Values are compared in SI; the table and `--update` speak the unit the
// case file used, so a human-written "167mph" stays "167.3mph" after an update.
#include "game/tuning/regression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "game/tuning/impact_case.hpp"
#include "game/content/quantity_text.hpp"
#include "game/content/scenario.hpp"
#include "game/content/toml_file.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
namespace {

struct Measured {
  std::map<std::string, std::vector<double>> values;  // SI
  std::string contact;
};

Measured measure_shot(const ShotResult& r) {
  Measured m;
  const auto& L = r.launch;
  const auto& F = r.trajectory.summary;
  m.values["ball_speed"] = {L.ball_speed};
  m.values["vertical_angle"] = {L.vertical_angle};
  m.values["horizontal_angle"] = {L.horizontal_angle};
  m.values["spin"] = {L.spin.total};
  m.values["backspin"] = {L.spin.backspin};
  m.values["sidespin"] = {L.spin.sidespin_right};
  m.values["spin_axis"] = {L.spin.axis_rad};
  if (r.impact.present) m.values["smash_factor"] = {r.smash_factor};
  m.values["carry"] = {F.carry_m};
  m.values["total"] = {F.total_m};
  m.values["apex"] = {F.apex_m};
  m.values["landing_angle"] = {F.landing_angle_deg * kPi / 180.0};
  m.values["hang_time"] = {F.hang_time_s};
  m.values["lateral"] = {F.lateral_m};
  if (r.impact.present) m.contact = to_string(r.impact.contact);
  return m;
}

// The unit a value text was written in: whatever follows the number ("167mph" -> "mph"); of
// a list, its first element's.
std::string unit_of(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '[' || text.front() == '"')) text.remove_prefix(1);
  const auto comma = text.find(',');
  if (comma != std::string_view::npos) text = text.substr(0, comma);
  while (!text.empty() && (text.back() == ' ' || text.back() == ']' || text.back() == '"')) text.remove_suffix(1);
  return std::string(unit_part(text));
}

std::string number(double v, int digits) {
  if (std::fabs(v) < 1e-15) v = 0.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string shown(double si, const std::string& unit, Dimension dim) {
  return number(si_to_unit(si, unit, dim), 6) + (unit.empty() ? "" : " " + unit);
}

// The new value text for `--update`: measured values in the case's unit, 7 significant
// digits, quoted when they carry a unit.
std::string value_text(const std::vector<double>& si, const std::string& unit, Dimension dim, bool list) {
  auto one = [&](double v) {
    const std::string n = number(si_to_unit(v, unit, dim), 7);
    return unit.empty() ? n : "\"" + n + unit + "\"";
  };
  if (!list) return one(si[0]);
  std::string out = "[";
  for (std::size_t i = 0; i < si.size(); ++i) out += (i ? ", " : "") + one(si[i]);
  return out + "]";
}

// Replaces the value of key `leaf` on `line` (1-based), keeping everything else on the line:
// the key as written (bare, dotted or quoted), other keys of an inline table
// (`expect = { ball_speed = "167mph", spin = ... }`), the comment.
void replace_value(std::vector<std::string>& lines, int line, const std::string& leaf, const std::string& value,
                   const std::string& where) {
  std::string& l = lines.at(static_cast<std::size_t>(line - 1));
  const auto is_key_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
  // The key: `leaf` (optionally quoted) not inside a string, followed by spaces and '='.
  std::size_t value_start = std::string::npos;
  bool in_string = false;
  for (std::size_t i = 0; i < l.size() && value_start == std::string::npos; ++i) {
    const char c = l[i];
    if (c == '#' && !in_string) break;
    const bool quoted_key = c == '"' && l.compare(i + 1, leaf.size(), leaf) == 0 && i + 1 + leaf.size() < l.size() &&
                            l[i + 1 + leaf.size()] == '"';
    if (!quoted_key && c == '"') {
      in_string = !in_string;
      continue;
    }
    if (in_string) continue;
    const std::size_t name_at = quoted_key ? i + 1 : i;
    if (l.compare(name_at, leaf.size(), leaf) != 0) continue;
    if (!quoted_key && i > 0 && is_key_char(l[i - 1])) continue;
    std::size_t j = name_at + leaf.size() + (quoted_key ? 1 : 0);
    if (!quoted_key && j < l.size() && is_key_char(l[j])) continue;  // "spin" must not match "spin_tol"
    while (j < l.size() && (l[j] == ' ' || l[j] == '\t')) ++j;
    if (j < l.size() && l[j] == '=') value_start = j + 1;
  }
  if (value_start == std::string::npos) throw InputError(where + ": cannot update: '" + leaf + " =' not found on this line");
  // The value ends at a ',' or '}' outside strings and brackets, a comment, or the line's end.
  std::size_t end = value_start;
  int depth = 0;
  in_string = false;
  for (; end < l.size(); ++end) {
    const char c = l[end];
    if (c == '"') in_string = !in_string;
    if (in_string) continue;
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (c == '#' || (depth == 0 && (c == ',' || c == '}'))) break;
  }
  if (depth != 0 || in_string) throw InputError(where + ": cannot update a value that spans several lines; write it on one line");
  std::string tail;
  if (end < l.size()) tail = (l[end] == '#' ? "  " : "") + l.substr(end);  // ", next = ..." / "}" / "# comment"
  l = l.substr(0, value_start) + " " + value + tail;
}

struct ExpectName {
  std::string name;
  Dimension dim;
  std::string default_unit;
  int list_size;
};

}  // namespace

bool RegressionCaseResult::passed() const {
  return std::all_of(rows.begin(), rows.end(), [](const RegressionRow& r) { return r.pass; });
}

std::vector<std::filesystem::path> regression_paths(const std::vector<std::string>& args) {
  std::vector<std::filesystem::path> roots;
  if (args.empty()) {
    std::filesystem::path root;
    if (const char* env = std::getenv("SWEETSPOT_ROOT"); env != nullptr && *env != '\0') {
      root = env;
    } else {
#ifdef SWEETSPOT_SOURCE_DIR
      root = SWEETSPOT_SOURCE_DIR;
#else
      root = ".";
#endif
    }
    roots.push_back(root / "tests" / "regression");
  } else {
    for (const auto& a : args) roots.emplace_back(a);
  }
  std::vector<std::filesystem::path> out;
  for (const auto& p : roots) {
    std::error_code ec;
    if (std::filesystem::is_directory(p, ec)) {
      std::vector<std::filesystem::path> files;
      for (const auto& e : std::filesystem::directory_iterator(p)) {
        // Every *.toml is a case: one that is a FIFO, a folder or a dangling link is refused
        // when it is read (exit 2), never skipped so that a run looks clean without it.
        if (e.path().extension() == ".toml") files.push_back(e.path());
      }
      std::sort(files.begin(), files.end());
      if (files.empty()) throw InputError("regression directory '" + p.string() + "' holds no .toml cases");
      out.insert(out.end(), files.begin(), files.end());
    } else if (std::filesystem::exists(p, ec)) {
      for (const auto& q : out)
        if (std::filesystem::equivalent(p, q, ec) && !ec)
          throw InputError("regression case '" + p.string() + "' is given twice (as '" + q.string() + "')");
      out.push_back(p);
    } else {
      throw InputError("cannot read regression case '" + p.string() + "': no such file or directory");
    }
  }
  return out;
}

RegressionCaseResult run_regression_case(const Assets& assets, const std::filesystem::path& path) {
  RegressionCaseResult res;
  res.path = path;
  res.name = path.stem().string();
  res.original_text = read_data_file(path, "regression case");
  const ScenarioDoc raw = parse_toml_doc(res.original_text, path.string());
  const bool impact_case = raw.find("case") != nullptr;
  const Schema& schema = impact_case ? impact_case_schema() : scenario_schema();
  const CheckedDoc doc(raw, schema, impact_case ? nullptr : &assets.sports());

  Measured m;
  std::vector<ExpectName> names;
  if (impact_case) {
    const ImpactInput in = impact_input_from(doc);
    const ImpactMeasurements im = measure_impact(in, solve_impact(in));
    m.values = im.values;
    m.contact = im.contact;
    for (const auto& e : impact_case_expectations()) names.push_back({std::string(e.name), e.dim, std::string(e.unit), e.list_size});
  } else {
    const Scenario s = scenario_from_doc(assets, raw, path.string());
    m = measure_shot(run_scenario(s, RunOptions{true, false}));
    for (const auto& e : scenario_expectations()) names.push_back({std::string(e.name), e.dim, std::string(e.unit), e.list_size});
  }

  std::vector<std::string> lines;
  {
    std::istringstream ss(res.original_text);
    for (std::string l; std::getline(ss, l);) lines.push_back(l);
  }
  for (const auto& e : names) {
    const std::string key = "expect." + e.name;
    if (!doc.has(key)) continue;
    const auto it = m.values.find(e.name);
    if (it == m.values.end()) {
      throw InputError(doc.origin(key) + ": " + key + ": not measured for this case (a launch-only shot has no smash factor)");
    }
    const std::string raw_text = doc.raw_text(key);
    const std::string unit = raw_text.empty() ? e.default_unit : unit_of(raw_text);
    const std::vector<double> expected = e.list_size > 0 ? doc.list(key) : std::vector<double>{doc.quantity(key)};
    const double tol = doc.quantity(key + "_tol");
    const auto& got = it->second;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      RegressionRow row;
      row.quantity = e.name + (expected.size() > 1 ? std::string(".") + "xyz"[i] : "");
      row.expected = shown(expected[i], unit, e.dim);
      row.got = shown(got[i], unit, e.dim);
      // Deltas and tolerances are differences: no affine offset (temperatures).
      const double scale = si_to_unit(1.0, unit, e.dim) - si_to_unit(0.0, unit, e.dim);
      row.delta = number((got[i] - expected[i]) * scale, 3);
      row.tolerance = number(tol * scale, 3);
      row.pass = std::fabs(got[i] - expected[i]) <= tol;
      row.unit = unit;
      row.expected_si = expected[i];
      row.got_si = got[i];
      row.tolerance_si = tol;
      row.si_unit = std::string(si_unit_name(e.dim));
      row.origin = doc.origin(key);
      res.rows.push_back(row);
    }
    const auto origin = doc.origin(key);
    const auto colon = origin.rfind(':');
    const int line = std::atoi(origin.c_str() + colon + 1);
    replace_value(lines, line, e.name, value_text(got, unit, e.dim, e.list_size > 0), origin);
  }
  if (doc.has("expect.contact")) {
    RegressionRow row;
    row.quantity = "contact";
    row.expected = doc.text("expect.contact");
    row.got = m.contact;
    row.pass = row.expected == row.got;
    row.numeric = false;
    row.origin = doc.origin("expect.contact");
    res.rows.push_back(row);
    const auto origin = doc.origin("expect.contact");
    replace_value(lines, std::atoi(origin.c_str() + origin.rfind(':') + 1), "contact", "\"" + m.contact + "\"", origin);
  }
  if (res.rows.empty()) throw InputError(path.string() + ": no [expect] entries; the case would check nothing");
  if (!doc.flag("update")) {
    res.updated_text = res.original_text;  // external reference values: never rewritten
    res.reference = true;
    return res;
  }
  for (const auto& l : lines) res.updated_text += l + "\n";
  return res;
}

std::string regression_table(const std::vector<RegressionCaseResult>& results) {
  std::vector<std::vector<std::string>> cells{{"case", "quantity", "expected", "got", "delta", "tol", "pass"}};
  for (const auto& c : results) {
    for (const auto& r : c.rows) {
      cells.push_back({c.name, r.quantity, r.expected, r.got, r.delta, r.tolerance, r.pass ? "pass" : "FAIL"});
    }
  }
  std::vector<std::size_t> width(cells[0].size(), 0);
  for (const auto& row : cells) {
    for (std::size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
  }
  std::string out;
  for (const auto& row : cells) {
    std::string line;
    for (std::size_t i = 0; i < row.size(); ++i) {
      line += row[i];
      if (i + 1 < row.size()) line += std::string(width[i] - row[i].size() + 2, ' ');
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace sweetspot
