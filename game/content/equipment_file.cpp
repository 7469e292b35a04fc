// Equipment files through the one TOML reader. See equipment_file.hpp.
#include "game/content/equipment_file.hpp"

#include <algorithm>

#include "game/content/toml_file.hpp"
#include "physics/delivery.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

/// A mesh of assets/meshes by its plain name ("driver_head"): a path ("../../etc/passwd")
/// would reach outside the assets, so it is refused here, at the file's line, and so is a
/// name with no `meshes`/NAME.obj (the window would draw nothing for it).
std::string mesh_name(const TomlFile& f, const toml::node& n, const std::filesystem::path& meshes) {
  const std::string name = f.text(n, "mesh");
  const bool plain = name.find_first_of("/\\") == std::string::npos && name != "." && name != ".." &&
                     name.find('\0') == std::string::npos;
  if (!plain) f.fail(n, "mesh", "'" + name + "' is not a mesh name of assets/meshes (a plain name such as driver_head)");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(meshes / (name + ".obj"), ec))
    f.fail(n, "mesh", "no mesh '" + name + "' in " + meshes.string() + " (a NAME.obj there, such as driver_head)");
  return name;
}

// Runs a physics validator and re-throws its message with the file and line: the line of
// the key it names ("club 'driver': head_mass = ..." -> head_mass), else the table's. The
// validator's own "club 'driver': " is dropped, since the caller puts the entry in context.
template <class F>
void validated(const TomlFile& f, const toml::table& t, const std::string& who, F&& check) {
  try {
    check();
  } catch (const InputError& e) {
    std::string message = e.what();
    if (message.rfind(who + ": ", 0) == 0) message.erase(0, who.size() + 2);
    // The physics name may be a member path ("compliance.stiffness"); the file's key is its last part.
    const std::string named = message.substr(0, message.find_first_of(" :(="));
    const toml::node* key = t.get(named.substr(named.rfind('.') + 1));
    throw InputError(f.where(key != nullptr ? *key : t) + ": " + message);
  }
}

CorCurve curve(const TomlFile& f, const toml::node& n, std::string_view key) {
  const auto pts = f.pairs(n, key, Dimension::Speed, Dimension::Dimensionless);
  if (pts.size() > static_cast<size_t>(CorCurve::kMaxPoints)) f.fail(n, key, "at most 8 points");
  CorCurve k;
  k.count = static_cast<int>(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    k.speed[i] = pts[i].first;
    k.cor[i] = pts[i].second;
  }
  return k;
}

FrictionModel friction(const TomlFile& f, const toml::table& t) {
  const toml::node* n = t.get("friction");
  if (n == nullptr) return FrictionModel::Coulomb;
  FrictionModel m;
  if (!friction_model_from_string(f.text(*n, "friction"), &m))
    f.fail(*n, "friction", "unknown model (allowed: " + friction_model_names() + ")");
  return m;
}

BallSpec read_ball(const TomlFile& f, const toml::table& t) {
  f.only_keys(t, "ball", {"name", "mass", "radius", "inertia", "stiffness", "poisson", "shear_stiffness_ratio",
                          "tangential_damping"});
  BallSpec b;
  b.name = f.text(f.required(t, "name", "the ball's name"), "name");
  b.mass = f.quantity(f.required(t, "mass", "kg"), "mass", Dimension::Mass, &BallSpec::kMass);
  b.radius = f.quantity(f.required(t, "radius", "m"), "radius", Dimension::Length, &BallSpec::kRadius);
  b.inertia = f.quantity_or(t, "inertia", Dimension::Inertia, 0.4 * b.mass * b.radius * b.radius);
  // Stiffness is in N/m^1.5, a unit the parser does not spell: written as a plain number
  // with its unit in the key's documentation (balls.toml).
  b.compliance.stiffness = f.quantity_or(t, "stiffness", Dimension::Dimensionless, 0.0, &BallCompliance::kStiffness);
  b.compliance.poisson = f.quantity_or(t, "poisson", Dimension::Dimensionless, b.compliance.poisson, &BallCompliance::kPoisson);
  b.compliance.shear_stiffness_ratio = f.quantity_or(t, "shear_stiffness_ratio", Dimension::Dimensionless, 0.0,
                                                    &BallCompliance::kShearStiffnessRatio);
  b.compliance.tangential_damping = f.quantity_or(t, "tangential_damping", Dimension::Dimensionless,
                                                 b.compliance.tangential_damping, &BallCompliance::kTangentialDamping);
  validated(f, t, "ball '" + b.name + "'", [&] { validate_ball(b); });
  return b;
}

struct FaceLaw {
  double reference_speed = 48.8, slope = 0.0;
  double shaft_tip_mass = 0.0;  // kg, from [shaft]
  ImpactMaterial material;
  MeasuredRange measured;
};

/// A [*.measured] table: e, mu, e_t as [low, high] (each optional) and the pair and source
/// text the warnings quote.
MeasuredRange read_measured(const TomlFile& f, const toml::node& n, const std::string& key) {
  const toml::table& t = f.table(n, key);
  f.only_keys(t, key, {"e", "mu", "e_t", "pair", "source"});
  MeasuredRange m;
  const auto range = [&](const char* name, const Range& allowed, Range* out) {
    const toml::node* v = t.get(name);
    if (v == nullptr) return;
    const std::vector<double> lh = f.quantities(*v, key + "." + name, Dimension::Dimensionless, 2, &allowed);
    if (!(lh[0] <= lh[1])) f.fail(*v, key + "." + name, "expected [low, high] with low <= high");
    *out = Range{lh[0], lh[1]};
  };
  range("e", ImpactMaterial::kE, &m.e);
  range("mu", ImpactMaterial::kMu, &m.mu);
  range("e_t", ImpactMaterial::kEt, &m.e_t);
  m.pair = f.text(f.required(t, "pair", "what strikes what, for the warnings"), "pair");
  m.source = f.text(f.required(t, "source", "where the ranges were measured"), "source");
  return m;
}

FaceLaw read_face(const TomlFile& f, const toml::table& root) {
  FaceLaw law;
  const toml::node* n = root.get("face");
  if (n == nullptr) return law;
  const toml::table& t = f.table(*n, "face");
  f.only_keys(t, "face", {"cor_reference_speed", "cor_slope", "mu", "e_t", "friction", "model", "measured"});
  if (const toml::node* m = t.get("measured")) law.measured = read_measured(f, *m, "face.measured");
  // The speed the face's COR is quoted at (the USGA test's 48.8 m/s); the curve of e over
  // speed is built about it, so it must be a speed a ball meets a face at.
  static constexpr Range kReferenceSpeed{1.0, 100.0};
  law.reference_speed = f.quantity_or(t, "cor_reference_speed", Dimension::Speed, law.reference_speed, &kReferenceSpeed);
  static constexpr Range kSlope{0.0, 0.05};
  law.slope = f.quantity_or(t, "cor_slope", Dimension::Dimensionless, 0.0, &kSlope);
  law.material.mu = f.quantity_or(t, "mu", Dimension::Dimensionless, law.material.mu, &ImpactMaterial::kMu);
  law.material.e_t = f.quantity_or(t, "e_t", Dimension::Dimensionless, law.material.e_t, &ImpactMaterial::kEt);
  law.material.friction = friction(f, t);
  if (const toml::node* m = t.get("model")) {
    if (!impact_model_from_string(f.text(*m, "model"), &law.material.model))
      f.fail(*m, "model", "unknown impact model (allowed: compliant, rigid)");
  }
  return law;
}

void read_club(const TomlFile& f, const toml::table& t, const FaceLaw& face, const std::filesystem::path& meshes,
               ClubSpec& k, ClubInfo& info) {
  f.only_keys(t, "club", {"name", "kind", "mesh", "tee_height", "tour_speed", "tour_attack", "loft", "lie", "dynamic_loft", "strike_height", "head_mass", "cg",
                          "inertia", "inertia_products", "bulge_radius", "roll_radius", "cor", "length", "face_size",
                          "cor_edge_drop"});
  k.name = f.text(f.required(t, "name", "the club's name"), "name");
  info.name = k.name;
  info.kind = f.text(f.required(t, "kind", "wood, hybrid, iron, wedge or putter"), "kind");
  if (info.kind != "wood" && info.kind != "hybrid" && info.kind != "iron" && info.kind != "wedge" &&
      info.kind != "putter")
    f.fail(*t.get("kind"), "kind", "unknown kind '" + info.kind + "' (allowed: wood, hybrid, iron, wedge, putter)");
  info.mesh = mesh_name(f, f.required(t, "mesh", "the head mesh in assets/meshes"), meshes);
  info.tee_height = f.quantity_or(t, "tee_height", Dimension::Length, 0.0, &ClubInfo::kTeeHeight);
  info.tour_speed = f.quantity(f.required(t, "tour_speed", "a tour player's full-swing club speed"), "tour_speed",
                               Dimension::Speed, &GolfSwing::kClubSpeed);
  info.tour_attack = f.quantity(f.required(t, "tour_attack", "a tour player's attack angle"), "tour_attack",
                                Dimension::Angle, &GolfSwing::kAttackAngle);
  info.measured = face.measured;
  k.loft = f.quantity(f.required(t, "loft", "static loft"), "loft", Dimension::Angle, &ClubSpec::kLoft);
  k.lie = f.quantity(f.required(t, "lie", "static lie"), "lie", Dimension::Angle, &ClubSpec::kLie);
  k.dynamic_loft = f.quantity(f.required(t, "dynamic_loft", "typical delivered loft"), "dynamic_loft",
                              Dimension::Angle, &GolfSwing::kDynamicLoft);
  k.strike_height = f.quantity_or(t, "strike_height", Dimension::Length, 0.0, &GolfSwing::kImpactUp);
  k.head_mass = f.quantity(f.required(t, "head_mass", "kg"), "head_mass", Dimension::Mass, &ClubSpec::kHeadMass);
  k.shaft_tip_mass = face.shaft_tip_mass;
  const auto cg = f.quantities(f.required(t, "cg", "[x, y, z] in the head frame"), "cg", Dimension::Length, 3);
  k.cg = Vec3(cg[0], cg[1], cg[2]);
  const auto d = f.quantities(f.required(t, "inertia", "[Ixx, Iyy, Izz]"), "inertia", Dimension::Inertia, 3);
  std::vector<double> p{0.0, 0.0, 0.0};
  if (const toml::node* n = t.get("inertia_products")) p = f.quantities(*n, "inertia_products", Dimension::Inertia, 3);
  k.inertia << d[0], p[0], p[1],
               p[0], d[1], p[2],
               p[1], p[2], d[2];
  k.bulge_radius = f.quantity(f.required(t, "bulge_radius", "m"), "bulge_radius", Dimension::Length,
                              &ClubSpec::kFaceRadius);
  k.roll_radius = f.quantity(f.required(t, "roll_radius", "m"), "roll_radius", Dimension::Length,
                             &ClubSpec::kFaceRadius);
  k.length = f.quantity(f.required(t, "length", "shaft length"), "length", Dimension::Length, &ClubSpec::kLength);
  if (const toml::node* n = t.get("face_size")) {
    const auto size = f.quantities(*n, "face_size", Dimension::Length, 2);
    // Checked as written (width and height), at face_size's own line.
    static constexpr Range kFaceSize{2.0 * ClubSpec::kFaceHalfSize.min, 2.0 * ClubSpec::kFaceHalfSize.max};
    for (int i = 0; i < 2; ++i)
      if (const std::string why = range_refusal(i == 0 ? "face_size[0] (width)" : "face_size[1] (height)", size[i], kFaceSize, "m");
          !why.empty())
        f.fail(*n, "face_size", why);
    k.face_half_width = 0.5 * size[0];
    k.face_half_height = 0.5 * size[1];
  }
  k.cor_edge_drop = f.quantity_or(t, "cor_edge_drop", Dimension::Dimensionless, 0.0, &ClubSpec::kCorEdgeDrop);
  // The face: the shared ball–face law with this club's COR at the reference speed.
  k.face = face.material;
  static constexpr Range kCor{0.0, 1.0, true};
  const double cor = f.quantity(f.required(t, "cor", "face COR at the reference speed"), "cor",
                                Dimension::Dimensionless, &kCor);
  if (face.slope > 0.0) {
    // Linear in normal speed through (reference speed, cor) between 10 and 90 m/s, held
    // constant outside and within [0, 1].
    const double speeds[] = {10.0, face.reference_speed, 90.0};
    k.face.e.count = 3;
    for (size_t i = 0; i < 3; ++i) {
      k.face.e.speed[i] = speeds[i];
      k.face.e.cor[i] = std::clamp(cor + face.slope * (face.reference_speed - speeds[i]), 0.0, 1.0);
    }
  } else {
    k.face.e = CorCurve::constant(cor);
  }
  validated(f, t, "club '" + k.name + "'", [&] { validate_club(k); });
}

void read_bat(const TomlFile& f, const toml::table& t, const std::filesystem::path& meshes, BatSpec& b, BatInfo& info) {
  f.only_keys(t, "bat", {"name", "mesh", "length", "mass", "cg_from_knob", "inertia_cg", "inertia_axial",
                         "barrel_profile", "sweet_spot_from_tip", "pivot_from_knob", "material"});
  b.name = f.text(f.required(t, "name", "the bat's name"), "name");
  info.name = b.name;
  info.mesh = t.get("mesh") != nullptr ? mesh_name(f, *t.get("mesh"), meshes) : std::string("bat");
  b.length = f.quantity(f.required(t, "length", "m"), "length", Dimension::Length, &BatSpec::kLength);
  b.mass = f.quantity(f.required(t, "mass", "kg"), "mass", Dimension::Mass, &BatSpec::kMass);
  b.cg_from_knob = f.quantity(f.required(t, "cg_from_knob", "m"), "cg_from_knob", Dimension::Length);
  b.inertia_cg = f.quantity(f.required(t, "inertia_cg", "kg*m^2"), "inertia_cg", Dimension::Inertia,
                            &BatSpec::kInertiaCg);
  b.inertia_axial = f.quantity(f.required(t, "inertia_axial", "kg*m^2"), "inertia_axial", Dimension::Inertia);
  b.barrel_profile = f.pairs(f.required(t, "barrel_profile", "[[from_knob, radius], ...]"), "barrel_profile",
                             Dimension::Length, Dimension::Length);
  b.sweet_spot_from_tip = f.quantity(f.required(t, "sweet_spot_from_tip", "m"), "sweet_spot_from_tip", Dimension::Length);
  b.pivot_from_knob = f.quantity(f.required(t, "pivot_from_knob", "m"), "pivot_from_knob", Dimension::Length);
  const toml::table& m = f.table(f.required(t, "material", "[bat.material]"), "material");
  f.only_keys(m, "material", {"cor", "e_t", "mu", "friction", "cor_profile", "measured"});
  if (const toml::node* r = m.get("measured")) info.measured = read_measured(f, *r, "material.measured");
  b.material.e = curve(f, f.required(m, "cor", "[[normal speed, e], ...]"), "material.cor");
  b.material.e_t = f.quantity_or(m, "e_t", Dimension::Dimensionless, 0.0, &ImpactMaterial::kEt);
  b.material.mu = f.quantity_or(m, "mu", Dimension::Dimensionless, 0.5, &ImpactMaterial::kMu);
  b.material.friction = friction(f, m);
  if (const toml::node* cp = m.get("cor_profile"))
    b.cor_profile = f.pairs(*cp, "material.cor_profile", Dimension::Length, Dimension::Dimensionless);
  validated(f, t, "bat '" + b.name + "'", [&] { validate_bat(b); });
}

template <class T>
void check_unique(const std::vector<T>& v, const std::string& file, const char* what) {
  for (size_t i = 0; i < v.size(); ++i)
    for (size_t j = i + 1; j < v.size(); ++j)
      if (v[i].name == v[j].name) throw InputError(file + ": " + what + " '" + v[i].name + "' is defined twice");
}

template <class T>
const T& find(const std::vector<T>& v, std::string_view name, const char* what) {
  for (const auto& x : v)
    if (x.name == name) return x;
  std::string names;
  for (const auto& x : v) names += (names.empty() ? "" : ", ") + x.name;
  throw InputError(std::string("unknown ") + what + " '" + std::string(name) + "' (allowed: " + names + ")");
}

}  // namespace

const BallSpec& EquipmentCatalog::ball(std::string_view name) const { return find(balls, name, "ball"); }
const ClubSpec& EquipmentCatalog::club(std::string_view name) const { return find(clubs, name, "club"); }
const ClubInfo& EquipmentCatalog::club_info_of(std::string_view name) const { return find(club_info, name, "club"); }
const BatSpec& EquipmentCatalog::bat(std::string_view name) const { return find(bats, name, "bat"); }
const BatInfo& EquipmentCatalog::bat_info_of(std::string_view name) const { return find(bat_info, name, "bat"); }

EquipmentCatalog load_equipment(const std::filesystem::path& dir) {
  EquipmentCatalog cat;
  const std::filesystem::path meshes = dir.parent_path() / "meshes";
  {
    const TomlFile f = TomlFile::read(dir / "balls.toml", "equipment");
    f.only_keys(f.root(), "", {"ball"});
    for (const toml::table* t : f.tables(f.root(), "ball", true)) {
      try {
        cat.balls.push_back(read_ball(f, *t));
      } catch (const InputError& e) {
        throw InputError(f.in_context(e.what(), "ball '" + f.text_or(*t, "name", "?") + "'"));
      }
    }
    check_unique(cat.balls, f.source(), "ball");
  }
  {
    const TomlFile f = TomlFile::read(dir / "clubs.toml", "equipment");
    f.only_keys(f.root(), "", {"face", "shaft", "club"});
    FaceLaw face = read_face(f, f.root());
    if (const toml::node* n = f.root().get("shaft")) {
      const toml::table& s = f.table(*n, "shaft");
      f.only_keys(s, "shaft", {"tip_mass"});
      face.shaft_tip_mass = f.quantity_or(s, "tip_mass", Dimension::Mass, 0.0, &ClubSpec::kShaftTipMass);
    }
    for (const toml::table* t : f.tables(f.root(), "club", true)) {
      cat.clubs.emplace_back();
      cat.club_info.emplace_back();
      try {
        read_club(f, *t, face, meshes, cat.clubs.back(), cat.club_info.back());
      } catch (const InputError& e) {
        throw InputError(f.in_context(e.what(), "club '" + f.text_or(*t, "name", "?") + "'"));
      }
    }
    check_unique(cat.clubs, f.source(), "club");
  }
  {
    const TomlFile f = TomlFile::read(dir / "bats.toml", "equipment");
    f.only_keys(f.root(), "", {"bat"});
    for (const toml::table* t : f.tables(f.root(), "bat", true)) {
      cat.bats.emplace_back();
      cat.bat_info.emplace_back();
      try {
        read_bat(f, *t, meshes, cat.bats.back(), cat.bat_info.back());
      } catch (const InputError& e) {
        throw InputError(f.in_context(e.what(), "bat '" + f.text_or(*t, "name", "?") + "'"));
      }
    }
    check_unique(cat.bats, f.source(), "bat");
  }
  return cat;
}

}  // namespace sweetspot
