#include "game/content/swings_file.hpp"

#include "game/content/toml_file.hpp"

namespace sweetspot {
namespace {
// MeterInput::kAccuracy is in ms; files carry seconds (SI) with a unit ("12ms").
constexpr Range kAccuracySeconds{MeterInput::kAccuracy.min / 1000.0, MeterInput::kAccuracy.max / 1000.0};
}  // namespace

std::vector<ScriptedStroke> load_swings(const std::filesystem::path& path) {
  const TomlFile f = TomlFile::read(path, "swings");
  f.only_keys(f.root(), "", {"stroke"});
  std::vector<ScriptedStroke> out;
  for (const toml::table* t : f.tables(f.root(), "stroke", true)) {
    f.only_keys(*t, "stroke", {"club", "power", "accuracy", "aim"});
    ScriptedStroke s;
    s.where = f.where(*t);
    if (const toml::node* c = t->get("club")) s.club = f.text(*c, "club");
    s.meter.power = f.quantity(f.required(*t, "power", "the swing's power, e.g. \"95%\""), "power",
                               Dimension::Fraction, &MeterInput::kPower);
    s.meter.accuracy_ms = 1000.0 * f.quantity_or(*t, "accuracy", Dimension::Time, 0.0, &kAccuracySeconds);
    s.aim = f.quantity_or(*t, "aim", Dimension::Angle, 0.0, &StrokeInput::kAim);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace sweetspot
