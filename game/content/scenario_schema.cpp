// The key tables. Ranges are SI; `unit` only decides how a message quotes them.
#include "game/content/scenario_schema.hpp"

#include <cmath>
#include <cstdio>
#include <deque>
#include <set>

#include "physics/atmosphere.hpp"
#include "physics/delivery.hpp"
#include "physics/impact.hpp"
#include "physics/launch.hpp"
#include "physics/math.hpp"
#include "game/core/shot_spec.hpp"

namespace sweetspot {
namespace {

KeySpec quantity(std::string_view key, Dimension dim, const Range* range, std::string_view unit,
                 std::string_view def, std::string_view doc, std::uint8_t strikes = kAnyStrike) {
  KeySpec k;
  k.key = key;
  k.type = ValueType::Quantity;
  k.dim = dim;
  k.range = {range, range, range};
  k.unit = unit;
  k.strikes = strikes;
  k.default_text = def;
  k.doc = doc;
  return k;
}

KeySpec list(std::string_view key, Dimension dim, int n, std::array<const Range*, 3> ranges, std::string_view unit,
             std::string_view def, std::string_view doc, std::uint8_t strikes = kAnyStrike) {
  KeySpec k = quantity(key, dim, nullptr, unit, def, doc, strikes);
  k.type = ValueType::QuantityList;
  k.list_size = n;
  k.range = ranges;
  return k;
}

KeySpec choice(std::string_view key, std::string_view choices, std::string_view def,
               std::string_view doc, std::uint8_t strikes = kAnyStrike) {
  KeySpec k;
  k.key = key;
  k.type = ValueType::Choice;
  k.choices = choices;
  k.default_text = def;
  k.doc = doc;
  k.strikes = strikes;
  return k;
}

KeySpec name(std::string_view key, std::string_view def, std::string_view doc,
             std::uint8_t strikes = kAnyStrike, ValueType type = ValueType::Name) {
  KeySpec k;
  k.key = key;
  k.type = type;
  k.default_text = def;
  k.doc = doc;
  k.strikes = strikes;
  return k;
}

// Expectation keys: expect.NAME (value, any finite) and expect.NAME_tol (>= 0).
void add_expectations(std::vector<KeySpec>& keys, const std::vector<ExpectSpec>& specs,
                      std::deque<std::string>& storage) {
  static constexpr Range kTolerance{0.0, kInf};
  for (const auto& e : specs) {
    storage.push_back("expect." + std::string(e.name));
    const std::string_view value_key = storage.back();
    storage.push_back("expect." + std::string(e.name) + "_tol");
    const std::string_view tol_key = storage.back();
    if (e.list_size > 0) {
      keys.push_back(list(value_key, e.dim, e.list_size, {&kAnyFinite, &kAnyFinite, &kAnyFinite}, e.unit, "",
                          "expected value (regression)"));
    } else {
      keys.push_back(quantity(value_key, e.dim, e.range != nullptr ? e.range : &kAnyFinite, e.unit, "",
                              "expected value (regression)"));
    }
    keys.push_back(quantity(tol_key, e.dim, &kTolerance, e.unit, "", "allowed |got - expected|"));
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
  const auto C = kClubKeys;
  const auto B = kBatKeys;
  const auto Speed = Dimension::Speed;
  const auto Angle = Dimension::Angle;
  const auto Spin = Dimension::AngularVelocity;
  const auto Length = Dimension::Length;
  const auto Mass = Dimension::Mass;
  const auto None = Dimension::Dimensionless;

  k.push_back(name("sport", "", "which game (required): a sport of assets/sports.toml"));
  k.push_back(name("description", "", "one line shown by `sweetspot list`", kAnyStrike, ValueType::Text));
  k.push_back(name("update", "true", "regression: false keeps `regress --update` from rewriting external reference values",
                   kAnyStrike, ValueType::Bool));

  k.push_back(name("ball.name", "", "ball from assets/equipment/balls.toml (default: the sport's)"));
  k.push_back(quantity("ball.mass", Mass, &BallSpec::kMass, "g", "", "override the ball's mass (inertia scales with it)"));
  k.push_back(quantity("ball.radius", Length, &BallSpec::kRadius, "mm", "", "override the ball's radius (inertia scales with r^2)"));

  k.push_back(name("club.name", "", "club from assets/equipment/clubs.toml (default: the sport's)", C));
  k.push_back(quantity("club.head_mass", Mass, &ClubSpec::kHeadMass, "g", "", "override the head mass (inertia tensor scales with it)", C));
  k.push_back(name("bat.name", "", "bat from assets/equipment/bats.toml (default: the sport's)", B));
  k.push_back(quantity("bat.mass", Mass, &BatSpec::kMass, "oz", "", "override the bat mass (inertia scales with it)", B));

  k.push_back(quantity("swing.speed", Speed, &GolfSwing::kClubSpeed, "mph", "113mph", "club head speed at the face centre", C));
  k.push_back(quantity("swing.attack_angle", Angle, &GolfSwing::kAttackAngle, "deg", "0deg", "attack angle, + up", C));
  k.push_back(quantity("swing.path", Angle, &GolfSwing::kClubPath, "deg", "0deg", "club path, + in-to-out (right)", C));
  k.push_back(quantity("swing.dynamic_loft", Angle, &GolfSwing::kDynamicLoft, "deg", "", "delivered loft at the face centre (default: the club's)", C));
  k.push_back(quantity("swing.strike_loft", Angle, &GolfSwing::kDynamicLoft, "deg", "",
                       "delivered loft where the face meets the ball, TrackMan's dynamic loft (instead of swing.dynamic_loft)", C));
  k.push_back(quantity("swing.face_angle", Angle, &GolfSwing::kFaceAngle, "deg", "0deg", "face angle to target at the face centre, + open (right)", C));
  k.push_back(quantity("swing.strike_face_angle", Angle, &GolfSwing::kFaceAngle, "deg", "",
                       "face angle to target where the face meets the ball, TrackMan's face angle (instead of swing.face_angle, which stays 0)", C));
  k.push_back(list("swing.impact_offset", Length, 2, {&GolfSwing::kImpactToe, &GolfSwing::kImpactUp, nullptr}, "mm",
                   "", "impact point [toe +, up +] from the face centre (default: the club's usual strike)", C));
  k.push_back(quantity("swing.closure_rate", Spin, &GolfSwing::kClosureRate, "deg/s", "0deg/s", "face closure rate, + closing", C));
  k.push_back(quantity("swing.sand_entry", Length, &kSandEntry, "in", "0in",
                       "from a bunker: where the club enters the sand behind the ball (a splash; 1in as taught), 0 = the ball first", C));

  k.push_back(quantity("swing.speed", Speed, &BatSwing::kBatSpeed, "mph", "31.3m/s", "bat speed at the sweet spot", B));
  k.push_back(quantity("swing.attack_angle", Angle, &BatSwing::kAttackAngle, "deg", "0.15rad", "swing plane angle, + up", B));
  k.push_back(quantity("swing.direction", Angle, &BatSwing::kDirection, "deg", "0deg", "horizontal swing direction, + toward right field", B));
  k.push_back(quantity("swing.impact_from_tip", Length, &BatSwing::kImpactFromTip, "in", "6in", "impact point along the barrel from the tip (below 0: the ball's centre past the end, its edge on the end cap)", B));
  k.push_back(quantity("swing.undercut", Length, &BatSwing::kUndercut, "mm", "0mm", "ball centre above the bat axis, + gives backspin", B));

  k.push_back(quantity("pitch.speed", Speed, &Pitch::kSpeed, "mph", "90mph", "pitch speed at the plate (0 = off a tee)", B));
  k.push_back(quantity("pitch.approach_angle", Angle, &Pitch::kApproachAngle, "deg", "0.1rad", "vertical approach angle, + descending", B));
  k.push_back(quantity("pitch.spin", Spin, &Pitch::kSpin, "rpm", "240rad/s", "pitch spin rate", B));
  k.push_back(quantity("pitch.spin_axis", Angle, &Pitch::kSpinAxis, "deg", "0deg", "pitch spin axis, 0 = pure backspin", B));

  k.push_back(quantity("impact.e", None, &ImpactMaterial::kE, "", "", "normal restitution (default: the equipment's speed-dependent curve)"));
  k.push_back(quantity("impact.e_t", None, &ImpactMaterial::kEt, "", "", "the rigid model's tangential restitution (default: the equipment's)"));
  k.push_back(quantity("impact.mu", None, &ImpactMaterial::kMu, "", "", "friction coefficient (default: the equipment's)"));
  k.push_back(choice("impact.friction", "none|textbook|coulomb", "", "friction model (default: the equipment's, coulomb)"));
  k.push_back(choice("impact.model", "compliant|rigid", "",
                     "impact with duration (compliant) or instantaneous impulse (rigid); default: the equipment's"));

  k.push_back(quantity("environment.temperature", Dimension::Temperature, &Environment::kTemperature, "C", "21C", "air temperature"));
  k.push_back(quantity("environment.pressure", Dimension::Pressure, &Environment::kPressure, "hPa", "", "station pressure (default: from altitude)"));
  k.push_back(quantity("environment.altitude", Length, &Environment::kAltitude, "m", "0m", "altitude above sea level"));
  k.push_back(quantity("environment.humidity", Dimension::Fraction, &Environment::kHumidity, "%", "50%", "relative humidity"));
  k.push_back(quantity("environment.wind_speed", Speed, &Environment::kWindSpeed, "mph", "0mph", "wind speed at the reference height (10 m)"));
  k.push_back(quantity("environment.wind_direction", Angle, &Environment::kWindDirection, "deg", "0deg",
                       "direction the wind blows toward: 0 = tailwind, 90deg = toward the right"));
  k.push_back(choice("environment.wind_profile", "log|power|uniform", "log", "how wind grows with height"));
  k.push_back(quantity("environment.wind_reference_height", Length, &Environment::kWindReferenceHeight, "m", "",
                       "height the wind speed is measured at (default 10 m)"));
  k.push_back(quantity("environment.wind_roughness_length", Length, &Environment::kWindRoughnessLength, "m", "",
                       "z0 of the log profile (default 0.03 m; mown grass 0.01..0.05 m)"));
  k.push_back(quantity("environment.wind_power_exponent", None, &Environment::kWindPowerExponent, "", "",
                       "alpha of the power-law profile (default 1/7, open terrain)"));

  k.push_back(name("world.name", "", "world asset (default: the sport's), none = flat ground"));
  k.push_back(name("world.flagstick", "false", "golf: leave the flagstick in the hole (true/false)", C, ValueType::Bool));
  k.push_back(quantity("world.firmness", None, &kFirmness, "", "1", "turf stiffness relative to the world's materials: 0.25 soaked ... 4 baked"));
  k.push_back(quantity("world.stimp", Length, &SurfaceMaterial::kStimp, "ft", "", "green speed, a Stimpmeter reading (default: the world's greens)"));
  k.push_back(quantity("world.aim", Angle, &BallPlacement::kAim, "deg", "0deg", "target line turned right (+) of the world's +x axis", C));
  k.push_back(list("world.ball_position", Length, 2, {&BallPlacement::kHorizontal, &BallPlacement::kHorizontal, nullptr},
                   "m", "[0m, 0m]", "ball position [downrange x, right z]; height from the terrain", C));
  k.push_back(choice("world.lie", "tee|fairway|rough|sand|green", "", "required surface under the ball (checked against the world)", C));

  k.push_back(name("aero.model", "", "aerodynamic model of assets/aero_models.toml (default: the sport's)"));

  k.push_back(quantity("launch.ball_speed", Speed, &LaunchNumbers::kBallSpeed, "mph", "", "launch-only scenario: ball speed (skips the impact)"));
  k.push_back(quantity("launch.vertical_angle", Angle, &LaunchNumbers::kVerticalAngle, "deg", "0deg", "launch-only: vertical launch angle, + up"));
  k.push_back(quantity("launch.horizontal_angle", Angle, &LaunchNumbers::kHorizontalAngle, "deg", "0deg", "launch-only: horizontal launch angle, + right"));
  k.push_back(quantity("launch.spin", Spin, &LaunchNumbers::kSpin, "rpm", "0rpm", "launch-only: total spin"));
  k.push_back(quantity("launch.spin_axis", Angle, &LaunchNumbers::kSpinAxis, "deg", "0deg", "launch-only: spin axis, + curves right, 180deg = topspin"));

  add_expectations(k, scenario_expectations(), key_storage());
  return s;
}

Schema build_impact_case_schema() {
  Schema s;
  s.name = "impact case";
  auto& k = s.keys;
  static constexpr Range kBodyMass{0.0, 1000.0, true};
  static constexpr Range kBodyInertia{0.0, 1000.0, true};
  static constexpr Range kVelocity{-150.0, 150.0};
  static constexpr Range kSpinRate{-2094.3951023931954, 2094.3951023931954};
  static constexpr Range kArm{-10.0, 10.0};
  static constexpr Range kNormal{-1e3, 1e3};
  k.push_back(choice("case", "impact", "", "regression case kind (required)"));
  k.push_back(name("description", "", "what the case checks", kAnyStrike, ValueType::Text));
  k.push_back(name("update", "true", "false keeps `regress --update` from rewriting external reference values",
                   kAnyStrike, ValueType::Bool));
  for (const std::string_view body : {std::string_view("impactor"), std::string_view("ball")}) {
    auto& st = key_storage();
    auto key = [&](std::string_view leaf) {
      st.push_back(std::string(body) + "." + std::string(leaf));
      return std::string_view(st.back());
    };
    k.push_back(quantity(key("mass"), Dimension::Mass, &kBodyMass, "kg", "", "body mass (required unless fixed)"));
    k.push_back(quantity(key("inertia"), Dimension::Inertia, &kBodyInertia, "kg*m^2", "", "scalar moment of inertia about the CG (required unless fixed)"));
    k.push_back(list(key("velocity"), Dimension::Speed, 3, {&kVelocity, &kVelocity, &kVelocity}, "m/s", "[0m/s, 0m/s, 0m/s]", "CG velocity"));
    k.push_back(list(key("angular_velocity"), Dimension::AngularVelocity, 3, {&kSpinRate, &kSpinRate, &kSpinRate}, "rad/s", "[0rad/s, 0rad/s, 0rad/s]", "angular velocity"));
    k.push_back(list(key("r"), Dimension::Length, 3, {&kArm, &kArm, &kArm}, "m", "[0m, 0m, 0m]", "CG -> contact point"));
  }
  k.push_back(name("impactor.fixed", "false", "immovable impactor (the ground)", kAnyStrike, ValueType::Bool));
  k.push_back(list("normal", Dimension::Dimensionless, 3, {&kNormal, &kNormal, &kNormal}, "", "", "contact normal from impactor into ball (normalised; required)"));
  k.push_back(quantity("impact.e", Dimension::Dimensionless, &ImpactMaterial::kE, "", "", "normal restitution (required)"));
  k.push_back(quantity("impact.e_t", Dimension::Dimensionless, &ImpactMaterial::kEt, "", "0", "tangential restitution"));
  k.push_back(quantity("impact.mu", Dimension::Dimensionless, &ImpactMaterial::kMu, "", "0", "friction coefficient"));
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

std::string_view top_section_of(std::string_view key) {
  const auto dot = key.find('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}

}  // namespace

const KeySpec* Schema::find(std::string_view key, std::uint8_t strikes) const {
  for (const auto& k : keys) {
    if (k.key == key && (k.strikes & strikes) != 0) return &k;
  }
  return nullptr;
}

bool Schema::has_section(std::string_view section) const {
  for (const auto& k : keys) {
    if (top_section_of(k.key) == section) return true;
  }
  return false;
}

std::string Schema::keys_in_section(std::string_view section, std::uint8_t strikes) const {
  std::string out;
  std::set<std::string_view> seen;
  for (const auto& k : keys) {
    if ((k.strikes & strikes) == 0) continue;
    if (top_section_of(k.key) != section) continue;
    append_unique(out, seen, k.key);
  }
  return out;
}

std::string Schema::section_names() const {
  std::string out;
  std::set<std::string_view> seen;
  for (const auto& k : keys) {
    const auto sec = top_section_of(k.key);
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

namespace {
// What a measured quantity can be: a speed, a distance, a time or a total spin is never
// negative; an angle lies in its half or whole turn. An expectation outside can never pass.
constexpr Range kNonNegative{0.0, kInf};
constexpr Range kElevation{-kPi / 2.0, kPi / 2.0};
constexpr Range kHeading{-kPi, kPi};
}  // namespace

const std::vector<ExpectSpec>& scenario_expectations() {
  static const std::vector<ExpectSpec> v{
      {"ball_speed", Dimension::Speed, "mph", 0, &kNonNegative},
      {"vertical_angle", Dimension::Angle, "deg", 0, &kElevation},
      {"horizontal_angle", Dimension::Angle, "deg", 0, &kHeading},
      {"spin", Dimension::AngularVelocity, "rpm", 0, &kNonNegative},
      {"backspin", Dimension::AngularVelocity, "rpm", 0},
      {"sidespin", Dimension::AngularVelocity, "rpm", 0},
      {"spin_axis", Dimension::Angle, "deg", 0, &kHeading},
      {"smash_factor", Dimension::Dimensionless, "", 0, &kNonNegative},
      {"carry", Dimension::Length, "yd", 0, &kNonNegative},
      {"total", Dimension::Length, "yd", 0, &kNonNegative},
      {"apex", Dimension::Length, "yd", 0, &kNonNegative},
      {"landing_angle", Dimension::Angle, "deg", 0, &kElevation},
      {"hang_time", Dimension::Time, "s", 0, &kNonNegative},
      {"lateral", Dimension::Length, "yd", 0},
  };
  return v;
}

const std::vector<ExpectSpec>& impact_case_expectations() {
  static const std::vector<ExpectSpec> v{
      {"ball_velocity", Dimension::Speed, "m/s", 3},
      {"impactor_velocity", Dimension::Speed, "m/s", 3},
      {"ball_spin", Dimension::AngularVelocity, "rad/s", 3},
      {"ball_speed", Dimension::Speed, "m/s", 0, &kNonNegative},
      {"ball_direction", Dimension::Angle, "deg", 0, &kHeading},
      {"ball_tangential_velocity", Dimension::Speed, "m/s", 0},
      {"contact_tangential_velocity", Dimension::Speed, "m/s", 0},
      {"energy_ratio", Dimension::Dimensionless, "", 0, &kNonNegative},
  };
  return v;
}

namespace {
// The units table is affine (SI = x·scale + offset); read both from two probes of the parser.
struct UnitAffine {
  double scale = 1.0, offset = 0.0;
};
UnitAffine unit_affine(std::string_view unit, Dimension dim) {
  std::string probe = "0 ";
  probe.append(unit.data(), unit.size());
  const double offset = parse_quantity(probe, dim);
  probe[0] = '1';
  return {parse_quantity(probe, dim) - offset, offset};
}
}  // namespace

double si_to_unit(double si, std::string_view unit, Dimension dim) {
  if (unit.empty()) return si;
  const UnitAffine a = unit_affine(unit, dim);
  return (si - a.offset) / a.scale;
}

double unit_to_si(double value, std::string_view unit, Dimension dim) {
  if (unit.empty()) return value;
  const UnitAffine a = unit_affine(unit, dim);
  return value * a.scale + a.offset;
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
  const std::string_view si_unit = si_unit_name(spec.dim);
  const auto one = [&](const Range* r, const std::string& who) {
    if (r == nullptr) r = &kAnyFinite;
    const bool lo = std::isfinite(r->min);
    const bool hi = std::isfinite(r->max);
    std::string out;
    if (lo) out += format_quantity(r->min, spec.unit, spec.dim) + (r->min_open ? " < " : " <= ");
    out += who;
    if (hi) out += std::string(r->max_open ? " < " : " <= ") + format_quantity(r->max, spec.unit, spec.dim);
    if (!lo && !hi) out += " finite";
    if (spec.unit != si_unit && !si_unit.empty() && (lo || hi)) out += " (" + range_text(*r, si_unit) + ")";
    return out;
  };
  if (spec.type == ValueType::Quantity) return one(spec.range[0], std::string(spec.key));
  std::string out = std::to_string(spec.list_size) + " values";
  for (int i = 0; i < spec.list_size && i < 3; ++i) {
    out += i == 0 ? ": " : "; ";
    std::string who = "[";
    who += std::to_string(i);
    who += ']';
    out += one(spec.range[static_cast<size_t>(i)], who);
  }
  return out;
}

}  // namespace sweetspot
