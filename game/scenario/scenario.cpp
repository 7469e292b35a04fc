// load_scenario: document -> checked values -> physics inputs. run_scenario: the one data
// path of DESIGN §1 (delivery -> impact -> launch -> flight/world -> result).
#include "game/scenario/scenario.hpp"

#include <map>
#include <mutex>
#include <memory>

#include "game/assets/assets.hpp"
#include "game/equipment/equipment_file.hpp"
#include "game/report/report.hpp"
#include "game/scenario/scenario_air.hpp"
#include "game/scenario/scenario_catalog.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

// Equipment look-ups name the key and its origin when the name is unknown.
template <typename Fn>
auto lookup(const CheckedDoc& doc, const char* key, Fn&& fn) -> decltype(fn(std::string())) {
  const std::string name = doc.text(key);
  try {
    return fn(name);
  } catch (const InputError& e) {
    throw InputError(doc.origin(key) + ": " + key + ": " + e.what());
  }
}

FrictionModel friction_from(const std::string& s) {
  if (s == "none") return FrictionModel::None;
  if (s == "textbook") return FrictionModel::Textbook;
  return FrictionModel::Coulomb;
}

void apply_material_overrides(const CheckedDoc& doc, ImpactMaterial& m) {
  if (auto e = doc.quantity_if_set("impact.e")) m.e = CorCurve::constant(*e);
  if (auto et = doc.quantity_if_set("impact.e_t")) {
    // A stated e_t is the value used: drop the equipment's speed fade, as impact.e drops
    // the speed-dependent COR curve.
    m.e_t = *et;
    m.e_t_scale = CorCurve::constant(1.0);
  }
  if (auto mu = doc.quantity_if_set("impact.mu")) m.mu = *mu;
  if (auto f = doc.text_if_set("impact.friction")) m.friction = friction_from(*f);
}

void apply_ball_overrides(const CheckedDoc& doc, BallSpec& b) {
  // A heavier or larger ball of the same construction: inertia ∝ m r².
  if (auto m = doc.quantity_if_set("ball.mass")) {
    b.inertia *= *m / b.mass;
    b.mass = *m;
  }
  if (auto r = doc.quantity_if_set("ball.radius")) {
    b.inertia *= (*r / b.radius) * (*r / b.radius);
    b.radius = *r;
  }
}

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

BallProperties ball_properties(const BallSpec& b) { return {b.mass, b.radius, b.inertia}; }

}  // namespace

// One World per name serves the process: reading the OBJ with assimp (~100 ms for the golf
// hole) and building Bullet's trees (~30 ms) happen once, and with the default sweep method
// its queries only read, so sweep threads share it.
const World* shared_world(const std::string& name) {
  if (name == kFlatWorld) return nullptr;
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<const World>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[name];
  if (!slot) slot = std::make_unique<const World>(load_world(name));
  return slot.get();
}

namespace {

// Rotation about +y that turns the target line (+x) by `aim` toward +z (right).
Mat3 aim_rotation(double aim) { return Eigen::AngleAxisd(-aim, Vec3::UnitY()).toRotationMatrix(); }

void fill_club_numbers(const Scenario& s, const Delivery& d, ClubNumbers& c) {
  const auto& w = s.golf_swing;
  c.club = s.club.name;
  c.speed = w.club_speed;
  c.speed_at_impact = d.impactor_speed;
  c.attack_angle = w.attack_angle;
  c.path = w.club_path;
  c.face_to_target = w.face_angle;
  c.dynamic_loft = std::isnan(w.dynamic_loft) ? s.club.dynamic_loft : w.dynamic_loft;
  c.lie = s.club.lie;
  c.impact_toe = w.impact_toe;
  c.impact_up = w.impact_up;
  c.closure_rate = w.closure_rate;
}

void fill_bat_numbers(const Scenario& s, const Delivery& d, BatNumbers& b) {
  const auto& w = s.bat_swing;
  b.bat = s.bat.name;
  b.speed = w.bat_speed;
  b.speed_at_impact = d.impactor_speed;
  b.attack_angle = w.attack_angle;
  b.direction = w.direction;
  b.impact_from_tip = w.impact_from_tip;
  b.undercut = w.undercut;
  b.pitch_speed = s.pitch.speed;
  b.pitch_spin = s.pitch.spin;
}

// The ball's resting height on the world at world.ball_position, and the lie check.
void place_golf_ball(const CheckedDoc& doc, const World* world, Scenario& s) {
  s.aim = doc.quantity("world.aim");
  if (world == nullptr) {
    if (!s.lie.empty() && s.lie != "fairway") {
      throw InputError(doc.origin("world.lie") + ": world.lie: the flat ground (world none) is fairway, not " + s.lie);
    }
    return;
  }
  SurfaceContact hit;
  const Vec3 probe(s.ball_offset.x(), world->description().bounds_max.y(), s.ball_offset.z());
  const double reach = world->description().bounds_max.y() - world->description().bounds_min.y();
  if (!world->support(probe, s.ball.radius, reach, &hit)) {
    throw InputError(doc.origin("world.ball_position") + ": world.ball_position: no ground under [" +
                     std::to_string(s.ball_offset.x()) + " m, " + std::to_string(s.ball_offset.z()) + " m] in world " +
                     s.world);
  }
  s.ball_offset.y() = hit.point.y();
  const std::string surface = to_string(world->material(hit.material).kind);
  s.start_surface = surface;
  if (!s.lie.empty() && surface != s.lie) {
    throw InputError(doc.origin("world.lie") + ": world.lie: the ball at world.ball_position lies on " + surface +
                     ", not " + s.lie);
  }
}

}  // namespace

Scenario scenario_from_doc(const ScenarioDoc& raw, std::string name) {
  const CheckedDoc doc(raw, scenario_schema());
  Scenario s;
  s.name = std::move(name);
  s.doc = raw;
  s.sport = doc.sport();
  s.description = doc.text_if_set("description").value_or("");
  const EquipmentCatalog& eq = default_equipment();
  s.ball = lookup(doc, "ball.name", [&](const std::string& n) { return eq.ball(n); });
  apply_ball_overrides(doc, s.ball);

  if (s.sport == Sport::Golf) {
    s.club = lookup(doc, "club.name", [&](const std::string& n) { return eq.club(n); });
    if (auto m = doc.quantity_if_set("club.head_mass")) {
      s.club.inertia *= *m / s.club.head_mass;
      s.club.head_mass = *m;
    }
    s.material = s.club.face;
    auto& w = s.golf_swing;
    w.club_speed = doc.quantity("swing.speed");
    w.attack_angle = doc.quantity("swing.attack_angle");
    w.club_path = doc.quantity("swing.path");
    w.dynamic_loft = doc.quantity_if_set("swing.dynamic_loft").value_or(s.club.dynamic_loft);
    w.face_angle = doc.quantity("swing.face_angle");
    const auto offset = doc.list("swing.impact_offset");
    w.impact_toe = offset[0];
    w.impact_up = offset[1];
    w.closure_rate = doc.quantity("swing.closure_rate");
    const auto pos = doc.list("world.ball_position");
    s.ball_offset = Vec3(pos[0], 0.0, pos[1]);
    s.lie = doc.text_if_set("world.lie").value_or("");
  } else {
    s.bat = lookup(doc, "bat.name", [&](const std::string& n) { return eq.bat(n); });
    if (auto m = doc.quantity_if_set("bat.mass")) {
      s.bat.inertia_cg *= *m / s.bat.mass;
      s.bat.inertia_axial *= *m / s.bat.mass;
      s.bat.mass = *m;
    }
    s.material = s.bat.material;
    auto& w = s.bat_swing;
    w.bat_speed = doc.quantity("swing.speed");
    w.attack_angle = doc.quantity("swing.attack_angle");
    w.direction = doc.quantity("swing.direction");
    w.impact_from_tip = doc.quantity("swing.impact_from_tip");
    w.undercut = doc.quantity("swing.undercut");
    auto& p = s.pitch;
    p.speed = doc.quantity("pitch.speed");
    p.approach_angle = doc.quantity("pitch.approach_angle");
    p.spin = doc.quantity("pitch.spin");
    p.spin_axis = doc.quantity("pitch.spin_axis");
  }
  apply_material_overrides(doc, s.material);

  if (auto speed = doc.quantity_if_set("launch.ball_speed")) {
    LaunchOnly l;
    l.ball_speed = *speed;
    l.vertical_angle = doc.quantity("launch.vertical_angle");
    l.horizontal_angle = doc.quantity("launch.horizontal_angle");
    l.spin = doc.quantity("launch.spin");
    l.spin_axis = doc.quantity("launch.spin_axis");
    s.launch = l;
  } else {
    for (const char* k : {"launch.vertical_angle", "launch.horizontal_angle", "launch.spin", "launch.spin_axis"}) {
      if (doc.has(k)) {
        throw InputError(doc.origin(k) + ": " + k + ": a launch-only scenario needs launch.ball_speed too");
      }
    }
  }

  s.environment = environment_from(doc);
  s.aero = &aero_from(doc);
  s.world = doc.text_if_set("world.name").value_or(default_world_name(to_string(s.sport)));
  const World* world = nullptr;
  try {
    world = shared_world(s.world);
  } catch (const InputError& e) {
    throw InputError(doc.origin("world.name") + ": world.name: " + e.what() + " (or none for the flat ground)");
  }
  if (s.sport == Sport::Golf) place_golf_ball(doc, world, s);
  s.expectations = expectations_from(doc);
  return s;
}

Scenario load_scenario(std::string_view name_or_path, const std::vector<std::string>& overrides) {
  const auto path = resolve_scenario(name_or_path);
  ScenarioDoc doc = read_toml_doc(path);
  for (const auto& o : overrides) apply_set(doc, o);
  return scenario_from_doc(doc, std::string(name_or_path));
}

ShotResult run_scenario(const Scenario& s, const RunOptions& options) {
  ShotResult r;
  r.scenario = s.name;
  r.sport = s.sport;
  if (s.launch) {
    const auto& l = *s.launch;
    const Vec3 start(0.0, s.sport == Sport::Golf ? s.ball.radius : kBaseballContactHeight, 0.0);
    r.launch_state = launch_from_metrics(l.ball_speed, l.vertical_angle, l.horizontal_angle, l.spin, l.spin_axis, start);
  } else {
    const Delivery d = s.sport == Sport::Golf ? deliver_golf(s.ball, s.club, s.golf_swing, s.material)
                                              : deliver_baseball(s.ball, s.bat, s.bat_swing, s.pitch, s.material);
    r.launch_state = d.launch;
    r.impactor_at_impact = d.impactor_at_impact;
    r.has_impactor = true;
    r.smash_factor = d.smash_factor;
    auto& i = r.impact;
    i.present = true;
    i.e = d.impact.e_used;
    i.e_t = s.material.e_t;
    i.mu = s.material.mu;
    i.friction = s.material.friction;
    i.contact = d.impact.contact;
    i.normal_impulse = d.impact.normal_impulse;
    i.tangential_impulse = d.impact.tangential_impulse;
    i.energy_loss = d.impact.energy_loss;
    if (s.sport == Sport::Golf) {
      fill_club_numbers(s, d, r.club);
    } else {
      fill_bat_numbers(s, d, r.bat);
    }
  }
  // Delivery works at the origin along +x; move the shot to the ball's spot on the world
  // and turn it to the aim line. Launch numbers are measured relative to the aim line.
  r.launch = measure_launch(r.launch_state);
  if (s.aim != 0.0 || !s.ball_offset.isZero(0.0)) {
    const Mat3 R = aim_rotation(s.aim);
    const Vec3 ball0(0.0, s.sport == Sport::Golf ? s.ball.radius : kBaseballContactHeight, 0.0);
    auto& L = r.launch_state;
    L.position = s.ball_offset + ball0 + R * (L.position - ball0);
    L.velocity = R * L.velocity;
    L.spin = R * L.spin;
    if (r.has_impactor) {
      auto& P = r.impactor_at_impact;
      P.position = s.ball_offset + ball0 + R * (P.position - ball0);
      P.orientation = Quat(R) * P.orientation;
      P.velocity = R * P.velocity;
      P.angular_velocity = R * P.angular_velocity;
    }
  }
  r.world = s.world;
  if (!options.fly) return r;

  FlightInput in;
  in.launch = r.launch_state;
  in.ball = ball_properties(s.ball);
  in.environment = s.environment;
  in.aero = s.aero;
  in.settings.record_samples = options.record_samples;
  const World* world = shared_world(s.world);
  try {
    r.trajectory = simulate_shot(in, world);
  } catch (const InputError& e) {
    // Valid inputs can still launch an unflyable ball (the textbook friction model creates
    // energy); say which scenario and why rather than a bare flight message.
    throw InputError(s.name + ": the impact launched a ball the flight model refuses (" + e.what() +
                     "); check impact.friction / impact.mu / swing inputs");
  }
  return r;
}

nlohmann::json shot_json(const ShotResult& r, const Scenario& /*s*/) { return shot_json(r); }

}  // namespace sweetspot
