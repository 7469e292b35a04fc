#include "game/content/aero_file.hpp"

#include <algorithm>

#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {

std::vector<AeroModel> load_aero_models(const std::filesystem::path& path, const SportCatalog& sports) {
  const TomlFile f = TomlFile::read(path, "aero models");
  f.only_keys(f.root(), "", {"model"});
  std::vector<AeroModel> out;
  for (const toml::table* t : f.tables(f.root(), "model", true)) {
    f.only_keys(*t, "model", {"name", "sport", "source", "drag", "drag_per_krpm", "lift_law", "lift", "s_max",
                              "decay_length", "decay_tau", "lift_onset", "drag_crisis", "drag_re_slope"});
    AeroModel m;
    m.name = f.text(f.required(*t, "name", "the model's name"), "name");
    const toml::node& sport = f.required(*t, "sport", "the sport whose ball it flies: " + sports.names());
    m.sport = f.text(sport, "sport");
    if (std::none_of(sports.sports.begin(), sports.sports.end(), [&](const SportProfile& p) { return p.name == m.sport; }))
      f.fail(sport, "sport", "unknown sport '" + m.sport + "' (allowed: " + sports.names() + ")");
    m.source = f.text(f.required(*t, "source", "the citation"), "source");
    const auto drag = f.quantities(f.required(*t, "drag", "[d0, d1, d2]"), "drag", Dimension::Dimensionless, 3);
    m.d0 = drag[0];
    m.d1 = drag[1];
    m.d2 = drag[2];
    m.d_krpm = f.quantity_or(*t, "drag_per_krpm", Dimension::Dimensionless, 0.0);
    const toml::node& law = f.required(*t, "lift_law", "quadratic, power or saturating");
    if (!lift_law_from_string(f.text(law, "lift_law"), &m.lift))
      f.fail(law, "lift_law", "unknown law (allowed: quadratic, power, saturating)");
    const auto lift = f.quantities(f.required(*t, "lift", "[l0, l1, l2]"), "lift", Dimension::Dimensionless, 3);
    m.l0 = lift[0];
    m.l1 = lift[1];
    m.l2 = lift[2];
    m.s_max = f.quantity_or(*t, "s_max", Dimension::Dimensionless, m.s_max);
    static constexpr Range kPositive{0.0, 1e12, true};
    const double length = f.quantity_or(*t, "decay_length", Dimension::Length, 0.0, &kPositive);
    m.decay_per_metre = length > 0.0 ? 1.0 / length : 0.0;
    m.decay_tau = f.quantity_or(*t, "decay_tau", Dimension::Time, 0.0, &kPositive);
    m.lift_onset = f.quantity_or(*t, "lift_onset", Dimension::Dimensionless, 0.0);
    if (const toml::node* n = t->get("drag_crisis")) {
      // [Re_critical, Cd rise, width in Re]: plain numbers.
      const auto c = f.quantities(*n, "drag_crisis", Dimension::Dimensionless, 3);
      m.crisis_re = c[0];
      m.crisis_rise = c[1];
      m.crisis_width = c[2];
    }
    // Cd per 1e5 of Reynolds number past the crisis: a plain number.
    m.drag_re_slope = f.quantity_or(*t, "drag_re_slope", Dimension::Dimensionless, 0.0);
    if (const std::string why = validate_aero_model(m); !why.empty()) throw InputError(f.where(*t) + ": " + why);
    for (const AeroModel& o : out)
      if (o.name == m.name) throw InputError(f.where(*t) + ": aero model '" + m.name + "' is defined twice");
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace sweetspot
