// toml++ reader for the equipment files. See equipment_file.hpp.
#include "game/equipment/equipment_file.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include <toml++/toml.h>

#include "game/assets/assets.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

// Where we are in which file, for messages: "clubs.toml:42: club 'driver' key 'loft': ...".
struct Context {
  std::string file;
  std::string who;  // "club 'driver'"

  [[noreturn]] void fail(const toml::node* node, const std::string& key, const std::string& msg) const {
    std::ostringstream os;
    os << file;
    if (node) os << ':' << node->source().begin.line;
    os << ": " << who << " key '" << key << "': " << msg;
    throw InputError(os.str());
  }
};

std::string text_of(const toml::node& n) {
  if (auto s = n.value_exact<std::string>()) return *s;
  if (auto i = n.value_exact<std::int64_t>()) return std::to_string(*i);
  if (auto d = n.value_exact<double>()) {
    std::ostringstream os;
    os.precision(17);
    os << *d;
    return os.str();
  }
  return {};
}

double quantity(const Context& c, const toml::node& n, const std::string& key, Dimension dim) {
  if (!n.is_string() && !n.is_number()) c.fail(&n, key, "expected a quantity such as \"10mm\" or a number");
  try {
    return parse_quantity(text_of(n), dim);
  } catch (const InputError& e) {
    c.fail(&n, key, e.what());
  }
}

const toml::node& required(const Context& c, const toml::table& t, const std::string& key) {
  const toml::node* n = t.get(key);
  if (!n) c.fail(&t, key, "missing (required)");
  return *n;
}

double get(const Context& c, const toml::table& t, const std::string& key, Dimension dim) {
  return quantity(c, required(c, t, key), key, dim);
}

double get_or(const Context& c, const toml::table& t, const std::string& key, Dimension dim, double fallback) {
  const toml::node* n = t.get(key);
  return n ? quantity(c, *n, key, dim) : fallback;
}

std::string get_name(const Context& c, const toml::table& t) {
  const toml::node& n = required(c, t, "name");
  auto s = n.value_exact<std::string>();
  if (!s || s->empty()) c.fail(&n, "name", "expected a non-empty string");
  return *s;
}

std::vector<double> list(const Context& c, const toml::table& t, const std::string& key, Dimension dim,
                         size_t count) {
  const toml::node& n = required(c, t, key);
  const toml::array* a = n.as_array();
  if (!a || a->size() != count) {
    c.fail(&n, key, "expected an array of " + std::to_string(count) + " quantities");
  }
  std::vector<double> out;
  for (const auto& e : *a) out.push_back(quantity(c, e, key, dim));
  return out;
}

// [[x, y], ...] pairs of (dim_x, dim_y) quantities.
std::vector<std::pair<double, double>> pairs(const Context& c, const toml::node& n, const std::string& key,
                                             Dimension dx, Dimension dy) {
  const toml::array* a = n.as_array();
  if (!a || a->empty()) c.fail(&n, key, "expected an array of [x, y] pairs");
  std::vector<std::pair<double, double>> out;
  for (const auto& e : *a) {
    const toml::array* p = e.as_array();
    if (!p || p->size() != 2) c.fail(&e, key, "each entry must be a pair [x, y]");
    out.emplace_back(quantity(c, (*p)[0], key, dx), quantity(c, (*p)[1], key, dy));
  }
  return out;
}

CorCurve curve(const Context& c, const toml::node& n, const std::string& key) {
  const auto pts = pairs(c, n, key, Dimension::Speed, Dimension::Dimensionless);
  if (pts.size() > static_cast<size_t>(CorCurve::kMaxPoints)) c.fail(&n, key, "at most 8 points");
  CorCurve k;
  k.count = static_cast<int>(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    k.speed[i] = pts[i].first;
    k.cor[i] = pts[i].second;
  }
  return k;
}

FrictionModel friction(const Context& c, const toml::table& t) {
  const toml::node* n = t.get("friction");
  if (!n) return FrictionModel::Coulomb;
  const auto s = n->value_exact<std::string>();
  if (s && *s == "none") return FrictionModel::None;
  if (s && *s == "textbook") return FrictionModel::Textbook;
  if (s && *s == "coulomb") return FrictionModel::Coulomb;
  c.fail(n, "friction", "must be one of none, textbook, coulomb");
}

// Runs a physics validator and re-throws its message with the file and line.
template <class F>
void validated(const Context& c, const toml::node& where, F&& check) {
  try {
    check();
  } catch (const InputError& e) {
    std::ostringstream os;
    os << c.file << ':' << where.source().begin.line << ": " << e.what();
    throw InputError(os.str());
  }
}

const toml::table& root_file(const std::filesystem::path& path, toml::table& storage) {
  try {
    storage = toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << path.filename().string() << ':' << e.source().begin.line << ": TOML syntax error: " << e.description();
    throw InputError(os.str());
  } catch (const std::exception& e) {
    throw InputError(path.string() + ": cannot read equipment file (" + e.what() + ")");
  }
  return storage;
}

const toml::array& entries(const Context& c, const toml::table& root, const char* key) {
  const toml::node* n = root.get(key);
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->empty()) {
    throw InputError(c.file + ": needs at least one [[" + key + "]] table");
  }
  return *a;
}

BallSpec read_ball(const Context& file, const toml::table& t) {
  Context c = file;
  c.who = "ball";
  BallSpec b;
  b.name = get_name(c, t);
  c.who = "ball '" + b.name + "'";
  b.mass = get(c, t, "mass", Dimension::Mass);
  b.radius = get(c, t, "radius", Dimension::Length);
  b.inertia = get_or(c, t, "inertia", Dimension::Inertia, 0.4 * b.mass * b.radius * b.radius);
  b.contact_offset = get_or(c, t, "contact_offset", Dimension::Length, 0.0);
  if (!(b.contact_offset >= 0.0 && b.contact_offset <= 0.2 * b.radius)) {
    c.fail(t.get("contact_offset"), "contact_offset", "must be in [0, 0.2·radius]");
  }
  validated(c, t, [&] { validate_ball(b); });
  return b;
}

struct FaceLaw {
  double reference_speed = 48.8, slope = 0.0;
  ImpactMaterial material;
};

FaceLaw read_face(const Context& file, const toml::table& root) {
  Context c = file;
  c.who = "[face]";
  FaceLaw f;
  const toml::node* n = root.get("face");
  if (!n) return f;
  const toml::table* t = n->as_table();
  if (!t) c.fail(n, "face", "must be a table");
  f.reference_speed = get_or(c, *t, "cor_reference_speed", Dimension::Speed, f.reference_speed);
  f.slope = get_or(c, *t, "cor_slope", Dimension::Dimensionless, 0.0);
  if (!(f.slope >= 0.0 && f.slope <= 0.05)) c.fail(t->get("cor_slope"), "cor_slope", "must be in [0, 0.05] per m/s");
  f.material.mu = get_or(c, *t, "mu", Dimension::Dimensionless, f.material.mu);
  f.material.e_t = get_or(c, *t, "e_t", Dimension::Dimensionless, f.material.e_t);
  if (const toml::node* s = t->get("e_t_scale")) f.material.e_t_scale = curve(c, *s, "e_t_scale");
  f.material.friction = friction(c, *t);
  return f;
}

ClubSpec read_club(const Context& file, const toml::table& t, const FaceLaw& face) {
  Context c = file;
  c.who = "club";
  ClubSpec k;
  k.name = get_name(c, t);
  c.who = "club '" + k.name + "'";
  k.loft = get(c, t, "loft", Dimension::Angle);
  k.lie = get(c, t, "lie", Dimension::Angle);
  k.dynamic_loft = get(c, t, "dynamic_loft", Dimension::Angle);
  k.head_mass = get(c, t, "head_mass", Dimension::Mass);
  const auto cg = list(c, t, "cg", Dimension::Length, 3);
  k.cg = Vec3(cg[0], cg[1], cg[2]);
  const auto d = list(c, t, "inertia", Dimension::Inertia, 3);
  std::vector<double> p{0.0, 0.0, 0.0};
  if (t.get("inertia_products")) p = list(c, t, "inertia_products", Dimension::Inertia, 3);
  k.inertia << d[0], p[0], p[1],
               p[0], d[1], p[2],
               p[1], p[2], d[2];
  k.bulge_radius = get(c, t, "bulge_radius", Dimension::Length);
  k.roll_radius = get(c, t, "roll_radius", Dimension::Length);
  k.length = get(c, t, "length", Dimension::Length);
  // The face: the shared ball–face law with this club's COR at the reference speed.
  k.face = face.material;
  const toml::node& cor_node = required(c, t, "cor");
  const double cor = quantity(c, cor_node, "cor", Dimension::Dimensionless);
  if (!(cor > 0.0 && cor <= 1.0)) c.fail(&cor_node, "cor", "must be in (0, 1]");
  if (face.slope > 0.0) {
    // Linear in normal speed through (reference speed, cor), clamped to [0, 1].
    const double speeds[] = {10.0, face.reference_speed, 90.0};
    k.face.e.count = 3;
    for (size_t i = 0; i < 3; ++i) {
      k.face.e.speed[i] = speeds[i];
      k.face.e.cor[i] = std::clamp(cor + face.slope * (face.reference_speed - speeds[i]), 0.0, 1.0);
    }
  } else {
    k.face.e = CorCurve::constant(cor);
  }
  validated(c, t, [&] { validate_club(k); });
  return k;
}

BatSpec read_bat(const Context& file, const toml::table& t) {
  Context c = file;
  c.who = "bat";
  BatSpec b;
  b.name = get_name(c, t);
  c.who = "bat '" + b.name + "'";
  b.length = get(c, t, "length", Dimension::Length);
  b.mass = get(c, t, "mass", Dimension::Mass);
  b.cg_from_knob = get(c, t, "cg_from_knob", Dimension::Length);
  b.inertia_cg = get(c, t, "inertia_cg", Dimension::Inertia);
  b.inertia_axial = get(c, t, "inertia_axial", Dimension::Inertia);
  b.barrel_profile = pairs(c, required(c, t, "barrel_profile"), "barrel_profile", Dimension::Length, Dimension::Length);
  b.sweet_spot_from_tip = get(c, t, "sweet_spot_from_tip", Dimension::Length);
  b.pivot_from_knob = get(c, t, "pivot_from_knob", Dimension::Length);
  const toml::node& mn = required(c, t, "material");
  const toml::table* m = mn.as_table();
  if (!m) c.fail(&mn, "material", "must be a table");
  b.material.e = curve(c, required(c, *m, "cor"), "material.cor");
  b.material.e_t = get_or(c, *m, "e_t", Dimension::Dimensionless, 0.0);
  b.material.mu = get_or(c, *m, "mu", Dimension::Dimensionless, 0.5);
  b.material.friction = friction(c, *m);
  if (const toml::node* cp = m->get("cor_profile")) {
    b.cor_profile = pairs(c, *cp, "material.cor_profile", Dimension::Length, Dimension::Dimensionless);
  }
  validated(c, t, [&] { validate_bat(b); });
  return b;
}

template <class T>
void check_unique(const std::vector<T>& v, const std::string& file, const char* what) {
  for (size_t i = 0; i < v.size(); ++i) {
    for (size_t j = i + 1; j < v.size(); ++j) {
      if (v[i].name == v[j].name) throw InputError(file + ": " + what + " '" + v[i].name + "' is defined twice");
    }
  }
}

template <class T>
const T& find(const std::vector<T>& v, std::string_view name, const char* what) {
  for (const auto& x : v) {
    if (x.name == name) return x;
  }
  std::string names;
  for (const auto& x : v) names += (names.empty() ? "" : ", ") + x.name;
  throw InputError(std::string("unknown ") + what + " '" + std::string(name) + "' (allowed: " + names + ")");
}

}  // namespace

const BallSpec& EquipmentCatalog::ball(std::string_view name) const { return find(balls, name, "ball"); }
const ClubSpec& EquipmentCatalog::club(std::string_view name) const { return find(clubs, name, "club"); }
const BatSpec& EquipmentCatalog::bat(std::string_view name) const { return find(bats, name, "bat"); }

EquipmentCatalog load_equipment(const std::filesystem::path& dir) {
  EquipmentCatalog cat;
  toml::table storage;
  {
    const Context c{"balls.toml", ""};
    const toml::table& root = root_file(dir / "balls.toml", storage);
    for (const auto& e : entries(c, root, "ball")) {
      if (!e.is_table()) throw InputError(c.file + ": [[ball]] entries must be tables");
      cat.balls.push_back(read_ball(c, *e.as_table()));
    }
    check_unique(cat.balls, c.file, "ball");
  }
  {
    const Context c{"clubs.toml", ""};
    const toml::table& root = root_file(dir / "clubs.toml", storage);
    const FaceLaw face = read_face(c, root);
    for (const auto& e : entries(c, root, "club")) {
      if (!e.is_table()) throw InputError(c.file + ": [[club]] entries must be tables");
      cat.clubs.push_back(read_club(c, *e.as_table(), face));
    }
    check_unique(cat.clubs, c.file, "club");
  }
  {
    const Context c{"bats.toml", ""};
    const toml::table& root = root_file(dir / "bats.toml", storage);
    for (const auto& e : entries(c, root, "bat")) {
      if (!e.is_table()) throw InputError(c.file + ": [[bat]] entries must be tables");
      cat.bats.push_back(read_bat(c, *e.as_table()));
    }
    check_unique(cat.bats, c.file, "bat");
  }
  return cat;
}

const EquipmentCatalog& default_equipment() {
  static const EquipmentCatalog catalog = load_equipment(asset_root() / "equipment");
  return catalog;
}

}  // namespace sweetspot
