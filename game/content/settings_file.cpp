#include "game/content/settings_file.hpp"

#include <cstdlib>

#include "game/content/scenario_toml.hpp"
#include "game/content/toml_file.hpp"

namespace sweetspot {

std::filesystem::path settings_path() {
  if (const char* s = std::getenv("SWEETSPOT_SETTINGS"); s != nullptr && *s != '\0') return s;
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x != nullptr && *x != '\0')
    return std::filesystem::path(x) / "sweetspot" / "settings.toml";
  if (const char* h = std::getenv("HOME"); h != nullptr && *h != '\0')
    return std::filesystem::path(h) / ".config" / "sweetspot" / "settings.toml";
  return "sweetspot_settings.toml";
}

Settings load_settings(const std::filesystem::path& path) {
  Settings s;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return s;
  const TomlFile f = TomlFile::read(path, "settings");
  f.only_keys(f.root(), "", {"input_latency"});
  s.input_latency = f.quantity_or(f.root(), "input_latency", Dimension::Time, 0.0, &Settings::kInputLatency);
  return s;
}

std::string settings_toml(const Settings& s) {
  return "# Sweetspot settings: the input latency the meter subtracts from each click (tap calibration).\n"
         "input_latency = \"" + quantity_text(s.input_latency * 1000.0, "ms") + "\"\n";
}

}  // namespace sweetspot
