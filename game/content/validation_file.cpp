#include "game/content/validation_file.hpp"

#include <algorithm>

#include "game/content/quantity_text.hpp"
#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

// Whole-library limits: a library is a few hundred cases; these refuse a runaway file.
constexpr std::size_t kMaxSetEntries = 32;
constexpr std::size_t kMaxCases = 5000;
constexpr Range kYear{1600.0, 2100.0};

std::vector<std::string> text_list(const TomlFile& f, const toml::node& n, std::string_view key, bool allow_empty) {
  const toml::array* a = n.as_array();
  if (a == nullptr) f.fail(n, key, "expected an array of strings");
  if (!allow_empty && a->empty()) f.fail(n, key, "expected at least one entry");
  if (a->size() > kMaxSetEntries) f.fail(n, key, "more than " + std::to_string(kMaxSetEntries) + " entries");
  std::vector<std::string> out;
  for (const auto& e : *a) out.push_back(f.text(e, key));
  return out;
}

std::vector<std::string> assignments(const TomlFile& f, const toml::node& n, std::string_view key) {
  std::vector<std::string> out = text_list(f, n, key, true);
  for (const std::string& s : out) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
      f.fail(n, key, "'" + s + "' is not key=value (a scenario key as --set takes it, e.g. swing.speed=94mph)");
  }
  return out;
}

// The unit `published` was written in ("275yd" -> "yd"); "" for a bare number.
std::string unit_text(const toml::node& n) {
  const auto s = n.value_exact<std::string>();
  return s ? std::string(unit_part(*s)) : std::string();
}

void read_sources(const TomlFile& f, ValidationLibrary& lib) {
  const toml::node* n = f.root().get("sources");
  if (n == nullptr) return;
  for (const auto& [k, v] : f.table(*n, "sources")) {
    const std::string key(k.str());
    const toml::table& t = f.table(v, "sources." + key);
    f.only_keys(t, "sources." + key, {"authors", "title", "year", "where"});
    ValidationSource s;
    s.key = key;
    s.authors = f.text(f.required(t, "authors", "who published it"), "authors");
    s.title = f.text(f.required(t, "title", "the publication's title"), "title");
    s.year = f.whole_number(f.required(t, "year", "year of publication"), "year", kYear);
    s.where = f.text(f.required(t, "where", "URL, journal and pages, or book and chapter"), "where");
    s.origin = f.where(v);
    if (const ValidationSource* old = lib.source(key))
      f.fail(v, "sources." + key, "defined twice (first at " + old->origin + ")");
    lib.sources.push_back(std::move(s));
  }
}

void read_cases(const TomlFile& f, ValidationLibrary& lib) {
  for (const toml::table* t : f.tables(f.root(), "case", true)) {
    f.only_keys(*t, "case", {"id", "source", "tags", "fitted", "scenario", "set", "quantity", "published", "tolerance",
                             "why", "baseline"});
    ValidationCase c;
    c.origin = f.where(*t);
    c.id = f.text(f.required(*t, "id", "a unique name"), "id");
    c.source = f.text(f.required(*t, "source", "a [sources.KEY] key"), "source");
    const toml::node& tags = f.required(*t, "tags", "sport first, then what it checks");
    c.tags = text_list(f, tags, "tags", false);
    for (std::size_t i = 0; i < c.tags.size(); ++i) {
      const auto& known = validation_tags();
      if (std::find(known.begin(), known.end(), c.tags[i]) == known.end()) {
        std::string names;
        for (const auto k : known) names += (names.empty() ? "" : ", ") + std::string(k);
        f.fail(tags, "tags", "unknown tag '" + c.tags[i] + "' (allowed: " + names + ")");
      }
      const bool sport = c.tags[i] == "golf" || c.tags[i] == "baseball";
      if (sport != (i == 0)) f.fail(tags, "tags", "the sport (golf or baseball) comes first, and only once");
    }
    if (const toml::node* n = t->get("fitted")) c.fitted = f.boolean(*n, "fitted");
    if (const toml::node* n = t->get("scenario")) c.scenario = f.text(*n, "scenario");
    if (const toml::node* n = t->get("set")) c.set = assignments(f, *n, "set");
    if (const toml::node* n = t->get("baseline")) {
      c.baseline = assignments(f, *n, "baseline");
      if (c.baseline.empty()) f.fail(*n, "baseline", "empty: leave it out, or name what the baseline shot changes");
    }
    const toml::node& q = f.required(*t, "quantity", "what is compared");
    const std::string qname = f.text(q, "quantity");
    for (const auto& known : validation_quantities())
      if (known.name == qname) c.quantity = &known;
    if (c.quantity == nullptr) {
      std::string names;
      for (const auto& k : validation_quantities()) names += (names.empty() ? "" : ", ") + std::string(k.name);
      f.fail(q, "quantity", "unknown quantity '" + qname + "' (allowed: " + names + ")");
    }
    const bool pitch_scenario = c.scenario.rfind("pitch:", 0) == 0;
    if (pitch_scenario != c.quantity->pitch) {
      f.fail(q, "quantity", c.quantity->pitch ? "'" + qname + "' is a pitch's: set scenario = \"pitch:TYPE\""
                                              : "'" + qname + "' is a shot's, but the scenario is a pitch");
    }
    if (pitch_scenario && c.tags[0] != "baseball") f.fail(tags, "tags", "a pitch is baseball's");
    const toml::node& pub = f.required(*t, "published", "the published value, with its unit");
    c.published = f.quantity(pub, "published", c.quantity->dim);
    c.unit = unit_text(pub);
    static constexpr Range kPositive{0.0, 1e9, true, false};
    c.tolerance = f.quantity(f.required(*t, "tolerance", "the source's own spread or rounding"), "tolerance",
                             c.quantity->dim, &kPositive);
    c.why = f.text(f.required(*t, "why", "where the tolerance comes from"), "why");
    for (const ValidationCase& o : lib.cases)
      if (o.id == c.id) f.fail(*t->get("id"), "id", "'" + c.id + "' is used twice (first at " + o.origin + ")");
    if (lib.cases.size() >= kMaxCases) f.fail(*t, "case", "more than " + std::to_string(kMaxCases) + " cases");
    lib.cases.push_back(std::move(c));
  }
}

}  // namespace

const std::vector<ValidationQuantity>& validation_quantities() {
  static const std::vector<ValidationQuantity> q{
      {"ball_speed", Dimension::Speed, false, false},
      {"vertical_angle", Dimension::Angle, false, false},
      {"horizontal_angle", Dimension::Angle, false, false},
      {"spin", Dimension::AngularVelocity, false, false},
      {"backspin", Dimension::AngularVelocity, false, false},
      {"sidespin", Dimension::AngularVelocity, false, false},
      {"spin_axis", Dimension::Angle, false, false},
      {"smash_factor", Dimension::Dimensionless, false, false},
      {"carry", Dimension::Length, false, true},
      {"total", Dimension::Length, false, true},
      {"roll", Dimension::Length, false, true},
      {"apex", Dimension::Length, false, true},
      {"landing_angle", Dimension::Angle, false, true},
      {"hang_time", Dimension::Time, false, true},
      {"lateral", Dimension::Length, false, true},
      {"distance", Dimension::Length, false, true},
      {"induced_vertical_break", Dimension::Length, true, true},
      {"horizontal_break", Dimension::Length, true, true},
      {"flight_time", Dimension::Time, true, true},
      {"plate_speed", Dimension::Speed, true, true},
  };
  return q;
}

const std::vector<std::string_view>& validation_tags() {
  static const std::vector<std::string_view> t{"golf", "baseball", "launch", "carry", "roll", "wind", "atmosphere",
                                               "gear", "lie", "putting", "pitch", "batted", "distance"};
  return t;
}

std::string ValidationCase::pitch_type() const {
  return scenario.rfind("pitch:", 0) == 0 ? scenario.substr(6) : std::string();
}

const ValidationSource* ValidationLibrary::source(std::string_view key) const {
  for (const ValidationSource& s : sources)
    if (s.key == key) return &s;
  return nullptr;
}

ValidationLibrary load_validation_library(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec)) {
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".toml") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) throw InputError("validation library '" + dir.string() + "' holds no .toml files");
  } else {
    files.push_back(dir);  // read_data_file names a missing or odd path
  }
  ValidationLibrary lib;
  for (const auto& p : files) {
    const TomlFile f = TomlFile::read(p, "validation references");
    f.only_keys(f.root(), "", {"sources", "case"});
    read_sources(f, lib);
    read_cases(f, lib);
  }
  for (const ValidationCase& c : lib.cases)
    if (lib.source(c.source) == nullptr)
      throw InputError(c.origin + ": source: '" + c.source + "' is not defined by any [sources.KEY] table");
  return lib;
}

}  // namespace sweetspot
