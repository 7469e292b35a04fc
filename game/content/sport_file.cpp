#include "game/content/sport_file.hpp"

#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {

SportCatalog load_sports(const std::filesystem::path& path) {
  const TomlFile f = TomlFile::read(path, "sports");
  f.only_keys(f.root(), "", {"sport"});
  SportCatalog out;
  for (const toml::table* t : f.tables(f.root(), "sport", true)) {
    f.only_keys(*t, "sport", {"name", "ball", "impactor", "default_impactor", "default_world", "default_aero",
                              "default_scenario", "rules", "contact_height", "distance_unit", "report", "csv"});
    SportProfile p;
    p.name = f.text(f.required(*t, "name", "the sport's name"), "name");
    p.ball = f.text(f.required(*t, "ball", "a ball in equipment/balls.toml"), "ball");
    const toml::node& imp = f.required(*t, "impactor", "club or bat");
    const std::string kind = f.text(imp, "impactor");
    if (kind == "club") p.impactor = ImpactorKind::Club;
    else if (kind == "bat") p.impactor = ImpactorKind::Bat;
    else f.fail(imp, "impactor", "unknown kind '" + kind + "' (allowed: club, bat)");
    p.default_impactor = f.text(f.required(*t, "default_impactor", "a club or bat name"), "default_impactor");
    p.default_world = f.text(f.required(*t, "default_world", "a world name or none"), "default_world");
    p.default_aero = f.text(f.required(*t, "default_aero", "an aero model name"), "default_aero");
    p.default_scenario = f.text(f.required(*t, "default_scenario", "a built-in scenario"), "default_scenario");
    const toml::node& rules = f.required(*t, "rules", "golf or baseball");
    p.rules = f.text(rules, "rules");
    if (p.rules != "golf" && p.rules != "baseball") f.fail(rules, "rules", "unknown rule set (allowed: golf, baseball)");
    if (t->get("contact_height")) {
      static constexpr Range kHeight{0.0, 3.0};
      p.contact_height = f.quantity(*t->get("contact_height"), "contact_height", Dimension::Length, &kHeight);
    }
    const toml::node& unit = f.required(*t, "distance_unit", "yd or ft");
    p.distance_unit = f.text(unit, "distance_unit");
    if (p.distance_unit != "yd" && p.distance_unit != "ft") f.fail(unit, "distance_unit", "allowed: yd, ft");
    for (const char* key : {"report", "csv"}) {
      const toml::node& n = f.required(*t, key, "metric ids");
      const toml::array* a = n.as_array();
      if (a == nullptr || a->empty()) f.fail(n, key, "expected an array of metric ids");
      auto& list = std::string_view(key) == "report" ? p.report : p.csv;
      for (const auto& e : *a) list.push_back(f.text(e, key));
    }
    // The rules play the game the impactor makes: golf strokes with a club, at-bats with a
    // bat. A mismatch would run a round whose ball can never be holed.
    if ((p.rules == "golf") != (p.impactor == ImpactorKind::Club))
      f.fail(rules, "rules", "'" + p.rules + "' does not go with impactor '" + kind + "' (allowed: golf with club, baseball with bat)");
    for (const char* key : {"name", "ball", "impactor", "default_impactor", "default_world", "default_aero",
                            "default_scenario", "rules", "report", "csv"})
      p.source[key] = f.where(*t->get(key));
    for (const SportProfile& o : out.sports)
      if (o.name == p.name) throw InputError(f.where(*t) + ": sport '" + p.name + "' is defined twice");
    out.sports.push_back(std::move(p));
  }
  return out;
}

}  // namespace sweetspot
