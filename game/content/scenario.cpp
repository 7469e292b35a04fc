// Scenario document -> checked values -> ShotSpec -> resolve. See scenario.hpp.
#include "game/content/scenario.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

std::vector<Expectation> expectations_from(const CheckedDoc& doc) {
  std::vector<Expectation> out;
  for (const auto& spec : scenario_expectations()) {
    const std::string key = "expect." + std::string(spec.name);
    if (!doc.has(key)) continue;
    Expectation e;
    e.name = spec.name;
    e.value = spec.list_size > 0 ? doc.list(key) : std::vector<double>{doc.quantity(key)};
    e.tolerance = doc.quantity(key + "_tol");
    out.push_back(std::move(e));
  }
  return out;
}

Environment environment_from(const CheckedDoc& doc) {
  Environment env;
  env.temperature = doc.quantity("environment.temperature");
  if (auto p = doc.quantity_if_set("environment.pressure")) env.pressure = *p;
  env.altitude = doc.quantity("environment.altitude");
  env.humidity = doc.quantity("environment.humidity");
  env.wind_speed = doc.quantity("environment.wind_speed");
  env.wind_direction = doc.quantity("environment.wind_direction");
  const std::string profile = doc.text("environment.wind_profile");
  env.wind_profile = profile == "power"     ? WindProfile::PowerLaw
                     : profile == "uniform" ? WindProfile::Uniform
                                            : WindProfile::Logarithmic;
  if (auto h = doc.quantity_if_set("environment.wind_reference_height")) env.wind_reference_height = *h;
  if (auto z = doc.quantity_if_set("environment.wind_roughness_length")) env.wind_roughness_length = *z;
  if (auto a = doc.quantity_if_set("environment.wind_power_exponent")) env.wind_power_exponent = *a;
  return env;
}

ShotSpec spec_from(const CheckedDoc& doc) {
  ShotSpec s;
  s.sport = doc.sport()->name;
  if (auto b = doc.text_if_set("ball.name")) s.ball = *b;
  s.ball_mass = doc.quantity_if_set("ball.mass");
  s.ball_radius = doc.quantity_if_set("ball.radius");
  if (auto speed = doc.quantity_if_set("launch.ball_speed")) {
    // A launch is three measured numbers; a default angle or spin of 0 would fly a shot
    // nobody asked for. Direction and spin axis default to 0 (straight), as on a monitor.
    for (const char* k : {"launch.vertical_angle", "launch.spin"})
      if (!doc.has(k))
        throw InputError(doc.origin("launch.ball_speed") + ": " + k +
                         " is missing: a launch needs ball_speed, vertical_angle and spin");
    // The launch replaces the strike, so a club, bat, swing, pitch or impact key would be
    // ignored without a word.
    for (const std::string& k : doc.keys())
      for (const char* family : {"club.", "bat.", "swing.", "pitch.", "impact."})
        if (k.rfind(family, 0) == 0)
          throw InputError(doc.origin(k) + ": " + k + ": a launch-only scenario has no strike; leave out " + family +
                           "* or the [launch] table");
    LaunchStrike l;
    l.numbers.ball_speed = *speed;
    l.numbers.vertical_angle = doc.quantity("launch.vertical_angle");
    l.numbers.horizontal_angle = doc.quantity("launch.horizontal_angle");
    l.numbers.spin = doc.quantity("launch.spin");
    l.numbers.spin_axis = doc.quantity("launch.spin_axis");
    s.strike = l;
  } else {
    for (const char* k : {"launch.vertical_angle", "launch.horizontal_angle", "launch.spin", "launch.spin_axis"}) {
      if (doc.has(k)) throw InputError(doc.origin(k) + ": " + k + ": a launch-only scenario needs launch.ball_speed too");
    }
    if (doc.sport()->impactor == ImpactorKind::Club) {
      ClubStrike c;
      if (auto n = doc.text_if_set("club.name")) c.club = *n;
      c.head_mass = doc.quantity_if_set("club.head_mass");
      auto& w = c.swing;
      w.club_speed = doc.quantity("swing.speed");
      w.attack_angle = doc.quantity("swing.attack_angle");
      w.club_path = doc.quantity("swing.path");
      w.dynamic_loft = doc.quantity_if_set("swing.dynamic_loft").value_or(std::nan(""));
      w.strike_loft = doc.quantity_if_set("swing.strike_loft").value_or(std::nan(""));
      if (!std::isnan(w.dynamic_loft) && !std::isnan(w.strike_loft))
        throw InputError(doc.origin("swing.strike_loft") + ": swing.strike_loft: " + kLoftGivenTwice);
      w.face_angle = doc.quantity("swing.face_angle");
      w.strike_face_angle = doc.quantity_if_set("swing.strike_face_angle").value_or(std::nan(""));
      // A face angle of 0 (the scenarios' "square") is the absence of one: an override of
      // the strike's face angle may stand on a square scenario.
      if (!std::isnan(w.strike_face_angle) && w.face_angle != 0.0)
        throw InputError(doc.origin("swing.strike_face_angle") + ": swing.strike_face_angle: " + kFaceAngleGivenTwice);
      if (doc.has("swing.impact_offset")) {
        const auto offset = doc.list("swing.impact_offset");
        w.impact_toe = offset[0];
        w.impact_up = offset[1];
      }
      w.closure_rate = doc.quantity("swing.closure_rate");
      w.sand_entry = doc.quantity("swing.sand_entry");
      s.strike = c;
    } else {
      BatStrike b;
      if (auto n = doc.text_if_set("bat.name")) b.bat = *n;
      b.mass = doc.quantity_if_set("bat.mass");
      auto& w = b.swing;
      w.bat_speed = doc.quantity("swing.speed");
      w.attack_angle = doc.quantity("swing.attack_angle");
      w.direction = doc.quantity("swing.direction");
      w.impact_from_tip = doc.quantity("swing.impact_from_tip");
      w.undercut = doc.quantity("swing.undercut");
      auto& p = b.pitch;
      p.speed = doc.quantity("pitch.speed");
      p.approach_angle = doc.quantity("pitch.approach_angle");
      p.spin = doc.quantity("pitch.spin");
      p.spin_axis = doc.quantity("pitch.spin_axis");
      s.strike = b;
    }
  }
  s.impact.e = doc.quantity_if_set("impact.e");
  s.impact.e_t = doc.quantity_if_set("impact.e_t");
  s.impact.mu = doc.quantity_if_set("impact.mu");
  if (auto f = doc.text_if_set("impact.friction")) {
    FrictionModel m;
    friction_model_from_string(*f, &m);  // the schema's choices are these names
    s.impact.friction = m;
  }
  if (auto f = doc.text_if_set("impact.model")) {
    ImpactModel m;
    impact_model_from_string(*f, &m);  // the schema's choices are these names
    s.impact.model = m;
  }
  s.environment = environment_from(doc);
  if (auto a = doc.text_if_set("aero.model")) s.aero = *a;
  if (auto w = doc.text_if_set("world.name")) s.world = *w;
  s.flight.ground_firmness = doc.quantity("world.firmness");
  if (doc.sport()->impactor == ImpactorKind::Club || doc.has("world.flagstick")) s.flagstick = doc.flag("world.flagstick");
  s.flight.green_stimp = doc.quantity_if_set("world.stimp").value_or(0.0);
  if (doc.strikes() & kClubKeys) {
    const auto pos = doc.list("world.ball_position");
    s.placement.x = pos[0];
    s.placement.z = pos[1];
    s.placement.aim = doc.quantity("world.aim");
    s.placement.lie = doc.text_if_set("world.lie").value_or("");
  }
  return s;
}

// A refusal from resolve() starts with the key it is about ("club.name: unknown club ...",
// "swing.speed = ..."); prefix the file:line or flag that key came from.
[[noreturn]] void rethrow_with_origin(const CheckedDoc& doc, const InputError& e) {
  const std::string msg = e.what();
  std::string best;
  for (const std::string& key : doc.keys()) {
    if (msg.rfind(key, 0) == 0 && key.size() > best.size()) best = key;
  }
  if (best.empty()) {
    for (const KeySpec& spec : scenario_schema().keys) {
      const std::string key(spec.key);
      if (msg.rfind(key, 0) == 0 && key.size() > best.size()) best = key;
    }
  }
  // A message that names its own file (a broken materials.toml read for world.name) is
  // about that file, not the scenario's line.
  const std::string rest = !best.empty() && msg.compare(best.size(), 2, ": ") == 0 ? msg.substr(best.size() + 2) : msg;
  const std::string first = rest.substr(0, rest.find(':'));
  std::error_code ec;
  if (first.find('.') != std::string::npos && std::filesystem::is_regular_file(first, ec))
    throw InputError(rest + (best.empty() ? std::string() : " (read for " + best + ")"));
  throw InputError((best.empty() ? doc.source() : doc.origin(best)) + ": " + msg);
}

}  // namespace

std::filesystem::path resolve_scenario(const Assets& assets, std::string_view name_or_path) {
  const std::filesystem::path as_path{std::string(name_or_path)};
  std::error_code ec;
  if (as_path.extension() == ".toml" || std::filesystem::exists(as_path, ec)) return as_path;
  const auto& all = assets.scenarios();
  for (const auto& s : all)
    if (s.name == name_or_path) return s.path;
  std::string names;
  for (const auto& s : all) names += (names.empty() ? "" : ", ") + s.name;
  throw InputError("unknown scenario '" + std::string(name_or_path) + "'; built-in scenarios: " + names +
                   "; or give a path to a .toml file");
}

Scenario scenario_from_doc(const Assets& assets, const ScenarioDoc& raw, std::string name) {
  const CheckedDoc doc(raw, scenario_schema(), &assets.sports());
  Scenario s;
  s.name = std::move(name);
  s.doc = raw;
  s.description = doc.text_if_set("description").value_or("");
  s.spec = spec_from(doc);
  s.expectations = expectations_from(doc);
  try {
    s.resolved = resolve(s.spec, assets);
  } catch (const InputError& e) {
    rethrow_with_origin(doc, e);
  }
  return s;
}

Scenario load_scenario(const Assets& assets, std::string_view name_or_path, const std::vector<std::string>& overrides) {
  ScenarioDoc doc = read_toml_doc(resolve_scenario(assets, name_or_path));
  for (const auto& o : overrides) apply_set(doc, o);
  return scenario_from_doc(assets, doc, std::string(name_or_path));
}


std::string origins_named_in(const ScenarioDoc& doc, const std::string& message) {
  const auto key_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.'; };
  std::string out;
  for (const DocEntry& e : doc.entries) {
    // The key as a whole word ("ball.mass", not "ball.mass_x"), from an origin not said yet.
    bool named = false;
    for (auto at = message.find(e.key); at != std::string::npos && !named; at = message.find(e.key, at + 1)) {
      const std::size_t end = at + e.key.size();
      named = (at == 0 || !key_char(message[at - 1])) && (end == message.size() || !key_char(message[end]) ||
                                                         (message[end] == '.' && (end + 1 == message.size() || message[end + 1] == ' ')));
    }
    if (!named || message.find(e.origin) != std::string::npos) continue;
    out += (out.empty() ? " (" : "; ") + e.key + " from " + e.origin;
  }
  return out.empty() ? out : out + ")";
}

std::string scenario_description(const BuiltinScenario& s) {
  try {
    const ScenarioDoc doc = read_toml_doc(s.path);
    const DocEntry* d = doc.find("description");
    return d ? d->text : std::string();
  } catch (const InputError& e) {
    return std::string("(unreadable: ") + e.what() + ")";
  }
}

}  // namespace sweetspot
