// The key tables. Ranges are SI; `unit` only decides how a message quotes them.
#include "game/scenario/scenario_schema.hpp"

#include <cmath>
#include <cstdio>
#include <deque>
#include <set>

#include "physics/math.hpp"

namespace sweetspot {
namespace {

constexpr double kDeg = kPi / 180.0;

KeySpec quantity(std::string_view key, Dimension dim, double lo, double hi, std::string_view unit,
                 std::string_view def, std::string_view doc, std::uint8_t sports = kAnySport,
                 bool lo_exclusive = false) {
  KeySpec k;
  k.key = key;
  k.type = ValueType::Quantity;
  k.dim = dim;
  k.min = lo;
  k.max = hi;
  k.min_exclusive = lo_exclusive;
  k.unit = unit;
  k.sports = sports;
  k.default_text = def;
  k.doc = doc;
  return k;
}

KeySpec list(std::string_view key, Dimension dim, int n, double lo, double hi, std::string_view unit,
             std::string_view def, std::string_view doc, std::uint8_t sports = kAnySport) {
  KeySpec k = quantity(key, dim, lo, hi, unit, def, doc, sports);
  k.type = ValueType::QuantityList;
  k.list_size = n;
  return k;
}

KeySpec choice(std::string_view key, std::string_view choices, std::string_view def,
               std::string_view doc, std::uint8_t sports = kAnySport) {
  KeySpec k;
  k.key = key;
  k.type = ValueType::Choice;
  k.choices = choices;
  k.default_text = def;
  k.doc = doc;
  k.sports = sports;
  return k;
}

KeySpec name(std::string_view key, std::string_view def, std::string_view doc,
             std::uint8_t sports = kAnySport, ValueType type = ValueType::Name) {
  KeySpec k;
  k.key = key;
  k.type = type;
  k.default_text = def;
  k.doc = doc;
  k.sports = sports;
  return k;
}

// Expectation keys: expect.NAME (value, any finite) and expect.NAME_tol (>= 0).
void add_expectations(std::vector<KeySpec>& keys, const std::vector<ExpectSpec>& specs,
                      std::deque<std::string>& storage) {
  for (const auto& e : specs) {
    storage.push_back("expect." + std::string(e.name));
    const std::string_view value_key = storage.back();
    storage.push_back("expect." + std::string(e.name) + "_tol");
    const std::string_view tol_key = storage.back();
    if (e.list_size > 0) {
      keys.push_back(list(value_key, e.dim, e.list_size, -kInf, kInf, e.unit, "",
                          "expected value (regression)"));
    } else {
      keys.push_back(quantity(value_key, e.dim, -kInf, kInf, e.unit, "", "expected value (regression)"));
    }
    keys.push_back(quantity(tol_key, e.dim, 0.0, kInf, e.unit, "", "allowed |got - expected|"));
  }
}

// Key strings built at run time must outlive the string_views in the schema; a deque never
// moves its elements on push_back, so the views stay valid.
std::deque<std::string>& key_storage() {
  static std::deque<std::string> s;
  return s;
}

Schema build_scenario_schema() {
  Schema s;
  s.name = "scenario";
  auto& k = s.keys;
  const auto G = kGolfOnly;
  const auto B = kBaseballOnly;
  const auto Speed = Dimension::Speed;
  const auto Angle = Dimension::Angle;
  const auto Spin = Dimension::AngularVelocity;
  const auto Length = Dimension::Length;
  const auto Mass = Dimension::Mass;

  k.push_back(choice("sport", "golf|baseball", "", "which game (required)"));
  k.push_back(name("description", "", "one line shown by `sweetspot list`", kAnySport, ValueType::Text));
  k.push_back(name("update", "true", "regression: false keeps `regress --update` from rewriting external reference values",
                   kAnySport, ValueType::Bool));

  k.push_back(name("ball.name", "tour", "ball from assets/equipment/balls.toml", G));
  k.push_back(name("ball.name", "mlb", "ball from assets/equipment/balls.toml", B));
  k.push_back(quantity("ball.mass", Mass, 0.0, 1.0, "g", "", "override the ball's mass (inertia scales with it)", kAnySport, true));
  k.push_back(quantity("ball.radius", Length, 0.0, 0.1, "mm", "", "override the ball's radius (inertia scales with r^2)", kAnySport, true));

  k.push_back(name("club.name", "driver", "club from assets/equipment/clubs.toml", G));
  k.push_back(quantity("club.head_mass", Mass, 0.0, 1.0, "g", "", "override the head mass (inertia tensor scales with it)", G, true));
  k.push_back(name("bat.name", "maple", "bat from assets/equipment/bats.toml", B));
  k.push_back(quantity("bat.mass", Mass, 0.0, 2.0, "oz", "", "override the bat mass (inertia scales with it)", B, true));

  k.push_back(quantity("swing.speed", Speed, 0.0, kMaxSpeed, "mph", "113mph", "club head speed at the face centre", G, true));
  k.push_back(quantity("swing.attack_angle", Angle, -30 * kDeg, 30 * kDeg, "deg", "0deg", "attack angle, + up", G));
  k.push_back(quantity("swing.path", Angle, -30 * kDeg, 30 * kDeg, "deg", "0deg", "club path, + in-to-out (right)", G));
  k.push_back(quantity("swing.dynamic_loft", Angle, 0.0, 70 * kDeg, "deg", "", "delivered loft (default: the club's)", G));
  k.push_back(quantity("swing.face_angle", Angle, -30 * kDeg, 30 * kDeg, "deg", "0deg", "face angle to target, + open (right)", G));
  k.push_back(list("swing.impact_offset", Length, 2, -0.05, 0.05, "mm", "[0mm, 0mm]", "impact point [toe +, up +] from the face centre", G));
  k.push_back(quantity("swing.closure_rate", Spin, -6000 * kDeg, 6000 * kDeg, "deg/s", "0deg/s", "face closure rate, + closing", G));

  k.push_back(quantity("swing.speed", Speed, 0.0, kMaxSpeed, "mph", "31.3m/s", "bat speed at the sweet spot", B, true));
  k.push_back(quantity("swing.attack_angle", Angle, -45 * kDeg, 45 * kDeg, "deg", "0.15rad", "swing plane angle, + up", B));
  k.push_back(quantity("swing.direction", Angle, -90 * kDeg, 90 * kDeg, "deg", "0deg", "horizontal swing direction, + toward right field", B));
  k.push_back(quantity("swing.impact_from_tip", Length, 0.0, 0.5, "in", "6in", "impact point along the barrel from the tip", B));
  k.push_back(quantity("swing.undercut", Length, -0.06, 0.06, "mm", "0mm", "ball centre above the bat axis, + gives backspin", B));

  k.push_back(quantity("pitch.speed", Speed, 0.0, kMaxSpeed, "mph", "90mph", "pitch speed at the plate (0 = off a tee)", B));
  k.push_back(quantity("pitch.approach_angle", Angle, -20 * kDeg, 45 * kDeg, "deg", "0.1rad", "vertical approach angle, + descending", B));
  k.push_back(quantity("pitch.spin", Spin, 0.0, kMaxSpin, "rpm", "240rad/s", "pitch spin rate", B));
  k.push_back(quantity("pitch.spin_axis", Angle, -kPi, kPi, "deg", "0deg", "pitch spin axis, 0 = pure backspin", B));

  k.push_back(quantity("impact.e", Dimension::Dimensionless, 0.0, 1.0, "", "", "normal restitution (default: the equipment's speed-dependent curve)"));
  k.push_back(quantity("impact.e_t", Dimension::Dimensionless, 0.0, 1.0, "", "", "tangential restitution (default: the equipment's)"));
  k.push_back(quantity("impact.mu", Dimension::Dimensionless, 0.0, 2.0, "", "", "friction coefficient (default: the equipment's)"));
  k.push_back(choice("impact.friction", "none|textbook|coulomb", "", "friction model (default: the equipment's, coulomb)"));

  k.push_back(quantity("environment.temperature", Dimension::Temperature, celsius_to_kelvin(-50), celsius_to_kelvin(60), "C", "21C", "air temperature"));
  k.push_back(quantity("environment.pressure", Dimension::Pressure, 30000.0, 110000.0, "hPa", "", "station pressure (default: from altitude)"));
  k.push_back(quantity("environment.altitude", Length, -500.0, 6000.0, "m", "0m", "altitude above sea level"));
  k.push_back(quantity("environment.humidity", Dimension::Fraction, 0.0, 1.0, "%", "50%", "relative humidity"));
  k.push_back(quantity("environment.wind_speed", Speed, 0.0, 60.0, "mph", "0mph", "wind speed at the reference height (10 m)"));
  k.push_back(quantity("environment.wind_direction", Angle, -2 * kPi, 2 * kPi, "deg", "0deg", "direction the wind blows toward: 0 = tailwind, 90deg = toward the right"));

  k.push_back(choice("environment.wind_profile", "log|power|uniform", "log", "how wind grows with height"));
  k.push_back(name("world.name", "", "world asset: golf_hole (golf default), ballpark (baseball default), none = flat ground"));
  k.push_back(quantity("world.aim", Angle, -90 * kDeg, 90 * kDeg, "deg", "0deg", "target line turned right (+) of the hole's +x axis", G));
  k.push_back(list("world.ball_position", Length, 2, -2000.0, 2000.0, "m", "[0m, 0m]", "ball position [downrange x, right z]; height from the terrain", G));
  k.push_back(choice("world.lie", "tee|fairway|rough|sand|green", "", "required surface under the ball (checked against the world)", G));

  k.push_back(name("aero.model", "", "aerodynamic model (default: ferguson2022 / nathan)"));

  k.push_back(quantity("launch.ball_speed", Speed, 0.0, kMaxSpeed, "mph", "", "launch-only scenario: ball speed (skips the impact)", kAnySport, true));
  k.push_back(quantity("launch.vertical_angle", Angle, -90 * kDeg, 90 * kDeg, "deg", "0deg", "launch-only: vertical launch angle, + up"));
  k.push_back(quantity("launch.horizontal_angle", Angle, -90 * kDeg, 90 * kDeg, "deg", "0deg", "launch-only: horizontal launch angle, + right"));
  k.push_back(quantity("launch.spin", Spin, 0.0, kMaxSpin, "rpm", "0rpm", "launch-only: total spin"));
  k.push_back(quantity("launch.spin_axis", Angle, -kPi, kPi, "deg", "0deg", "launch-only: spin axis, + curves right"));

  add_expectations(k, scenario_expectations(), key_storage());
  return s;
}

Schema build_impact_case_schema() {
  Schema s;
  s.name = "impact case";
  auto& k = s.keys;
  k.push_back(choice("case", "impact", "", "regression case kind (required)"));
  k.push_back(name("description", "", "what the case checks", kAnySport, ValueType::Text));
  k.push_back(name("update", "true", "false keeps `regress --update` from rewriting external reference values",
                   kAnySport, ValueType::Bool));
  for (const std::string_view body : {std::string_view("impactor"), std::string_view("ball")}) {
    auto& st = key_storage();
    auto key = [&](std::string_view leaf) {
      st.push_back(std::string(body) + "." + std::string(leaf));
      return std::string_view(st.back());
    };
    k.push_back(quantity(key("mass"), Dimension::Mass, 0.0, 1000.0, "kg", "", "body mass (required unless fixed)", kAnySport, true));
    k.push_back(quantity(key("inertia"), Dimension::Inertia, 0.0, 1000.0, "kg*m^2", "", "scalar moment of inertia about the CG (required unless fixed)", kAnySport, true));
    k.push_back(list(key("velocity"), Dimension::Speed, 3, -kMaxSpeed, kMaxSpeed, "m/s", "[0m/s, 0m/s, 0m/s]", "CG velocity"));
    k.push_back(list(key("angular_velocity"), Dimension::AngularVelocity, 3, -kMaxSpin, kMaxSpin, "rad/s", "[0rad/s, 0rad/s, 0rad/s]", "angular velocity"));
    k.push_back(list(key("r"), Dimension::Length, 3, -10.0, 10.0, "m", "[0m, 0m, 0m]", "CG -> contact point"));
  }
  k.push_back(name("impactor.fixed", "false", "immovable impactor (the ground)", kAnySport, ValueType::Bool));
  k.push_back(list("normal", Dimension::Dimensionless, 3, -1e3, 1e3, "", "", "contact normal from impactor into ball (normalised; required)"));
  k.push_back(quantity("impact.e", Dimension::Dimensionless, 0.0, 1.0, "", "", "normal restitution (required)"));
  k.push_back(quantity("impact.e_t", Dimension::Dimensionless, 0.0, 1.0, "", "0", "tangential restitution"));
  k.push_back(quantity("impact.mu", Dimension::Dimensionless, 0.0, 2.0, "", "0", "friction coefficient"));
  k.push_back(choice("impact.friction", "none|textbook|coulomb", "coulomb", "friction model"));
  k.push_back(choice("expect.contact", "grip|slip|none", "", "expected contact kind"));
  add_expectations(k, impact_case_expectations(), key_storage());
  return s;
}

void append_unique(std::string& out, std::set<std::string_view>& seen, std::string_view item) {
  if (!seen.insert(item).second) return;
  if (!out.empty()) out += ", ";
  out += item;
}

std::string_view section_of(std::string_view key) {
  const auto dot = key.find('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}

}  // namespace

const char* to_string(Sport s) { return s == Sport::Golf ? "golf" : "baseball"; }

const KeySpec* Schema::find(std::string_view key, std::uint8_t sport) const {
  for (const auto& k : keys) {
    if (k.key == key && (sport == 0 || (k.sports & sport) != 0)) return &k;
  }
  return nullptr;
}

bool Schema::has_section(std::string_view section) const {
  for (const auto& k : keys) {
    if (section_of(k.key) == section) return true;
  }
  return false;
}

std::string Schema::keys_in_section(std::string_view section, std::uint8_t sport) const {
  std::string out;
  std::set<std::string_view> seen;
  for (const auto& k : keys) {
    if (sport != 0 && (k.sports & sport) == 0) continue;
    if (section_of(k.key) != section) continue;
    append_unique(out, seen, k.key);
  }
  return out;
}

std::string Schema::section_names() const {
  std::string out;
  std::set<std::string_view> seen;
  for (const auto& k : keys) {
    const auto sec = section_of(k.key);
    append_unique(out, seen, sec.empty() ? k.key : sec);
  }
  return out;
}

const Schema& scenario_schema() {
  static const Schema s = build_scenario_schema();
  return s;
}

const Schema& impact_case_schema() {
  static const Schema s = build_impact_case_schema();
  return s;
}

const std::vector<ExpectSpec>& scenario_expectations() {
  static const std::vector<ExpectSpec> v{
      {"ball_speed", Dimension::Speed, "mph", 0},
      {"vertical_angle", Dimension::Angle, "deg", 0},
      {"horizontal_angle", Dimension::Angle, "deg", 0},
      {"spin", Dimension::AngularVelocity, "rpm", 0},
      {"backspin", Dimension::AngularVelocity, "rpm", 0},
      {"sidespin", Dimension::AngularVelocity, "rpm", 0},
      {"spin_axis", Dimension::Angle, "deg", 0},
      {"smash_factor", Dimension::Dimensionless, "", 0},
      {"carry", Dimension::Length, "yd", 0},
      {"total", Dimension::Length, "yd", 0},
      {"apex", Dimension::Length, "yd", 0},
      {"landing_angle", Dimension::Angle, "deg", 0},
      {"hang_time", Dimension::Time, "s", 0},
      {"lateral", Dimension::Length, "yd", 0},
  };
  return v;
}

const std::vector<ExpectSpec>& impact_case_expectations() {
  static const std::vector<ExpectSpec> v{
      {"ball_velocity", Dimension::Speed, "m/s", 3},
      {"impactor_velocity", Dimension::Speed, "m/s", 3},
      {"ball_spin", Dimension::AngularVelocity, "rad/s", 3},
      {"ball_speed", Dimension::Speed, "m/s", 0},
      {"ball_direction", Dimension::Angle, "deg", 0},
      {"ball_tangential_velocity", Dimension::Speed, "m/s", 0},
      {"contact_tangential_velocity", Dimension::Speed, "m/s", 0},
      {"energy_ratio", Dimension::Dimensionless, "", 0},
  };
  return v;
}

double si_to_unit(double si, std::string_view unit, Dimension dim) {
  if (unit.empty()) return si;
  // The units table is affine (SI = x*scale + offset); invert it from two probes.
  std::string probe = "0 ";
  probe.append(unit.data(), unit.size());
  const double offset = parse_quantity(probe, dim);
  probe[0] = '1';
  const double scale = parse_quantity(probe, dim) - offset;
  return (si - offset) / scale;
}

std::string format_quantity(double si, std::string_view unit, Dimension dim, int digits) {
  char buf[64];
  double v = si_to_unit(si, unit, dim);
  if (std::fabs(v) < 1e-12) v = 0.0;  // no "-0"
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  std::string out = buf;
  if (!unit.empty()) {
    out += ' ';
    out += unit;
  }
  return out;
}

std::string range_text(const KeySpec& spec) {
  if (spec.type == ValueType::Choice) {
    std::string out = "one of ";
    std::string_view c = spec.choices;
    bool first = true;
    while (!c.empty()) {
      const auto bar = c.find('|');
      if (!first) out += ", ";
      out += c.substr(0, bar);
      first = false;
      c = bar == std::string_view::npos ? std::string_view() : c.substr(bar + 1);
    }
    return out;
  }
  if (spec.type == ValueType::Bool) return "true or false";
  if (spec.type != ValueType::Quantity && spec.type != ValueType::QuantityList) return "any text";
  const std::string who = spec.type == ValueType::QuantityList ? "each element" : std::string(spec.key);
  const bool lo = std::isfinite(spec.min);
  const bool hi = std::isfinite(spec.max);
  const std::string_view si_unit = [&]() -> std::string_view {
    switch (spec.dim) {
      case Dimension::Speed: return "m/s";
      case Dimension::Angle: return "rad";
      case Dimension::AngularVelocity: return "rad/s";
      case Dimension::Temperature: return "K";
      case Dimension::Mass: return "kg";
      case Dimension::Length: return "m";
      case Dimension::Pressure: return "Pa";
      case Dimension::Time: return "s";
      case Dimension::Inertia: return "kg*m^2";
      default: return "";
    }
  }();
  std::string out;
  if (lo) out += format_quantity(spec.min, spec.unit, spec.dim) + (spec.min_exclusive ? " < " : " <= ");
  out += who;
  if (hi) out += " <= " + format_quantity(spec.max, spec.unit, spec.dim);
  if (!lo && !hi) out += " finite";
  if (spec.unit != si_unit && !si_unit.empty() && (lo || hi)) {
    out += " (";
    if (lo) out += format_quantity(spec.min, si_unit, spec.dim) + (hi ? " .. " : " minimum");
    if (hi) out += format_quantity(spec.max, si_unit, spec.dim);
    out += ")";
  }
  if (spec.type == ValueType::QuantityList) {
    out = std::to_string(spec.list_size) + " values, " + out;
  }
  return out;
}

}  // namespace sweetspot
