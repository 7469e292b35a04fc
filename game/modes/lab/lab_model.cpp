#include "game/modes/lab/lab_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <variant>

#include "game/content/scenario_doc.hpp"
#include "game/content/scenario_schema.hpp"
#include "game/content/scenario_toml.hpp"
#include "game/modes/lab/grip.hpp"
#include "game/rules/run_shot.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

constexpr LabParamInfo kParams[] = {
    {LabParam::ClubSpeed, "swing.speed", kClubKeys, 0},
    {LabParam::AttackAngle, "swing.attack_angle", kClubKeys, 0},
    {LabParam::ClubPath, "swing.path", kClubKeys, 0},
    {LabParam::DynamicLoft, "swing.dynamic_loft", kClubKeys, 0},
    {LabParam::FaceAngle, "swing.face_angle", kClubKeys, 0},
    {LabParam::ClosureRate, "swing.closure_rate", kClubKeys, 0},
    {LabParam::ImpactToe, "swing.impact_offset", kClubKeys, 0},
    {LabParam::ImpactUp, "swing.impact_offset", kClubKeys, 1},
    {LabParam::BatSpeed, "swing.speed", kBatKeys, 0},
    {LabParam::BatAttack, "swing.attack_angle", kBatKeys, 0},
    {LabParam::BatDirection, "swing.direction", kBatKeys, 0},
    {LabParam::PitchSpeed, "pitch.speed", kBatKeys, 0},
    {LabParam::PitchSpin, "pitch.spin", kBatKeys, 0},
    {LabParam::ImpactFromTip, "swing.impact_from_tip", kBatKeys, 0},
    {LabParam::Undercut, "swing.undercut", kBatKeys, 0},
    {LabParam::E, "impact.e", kAnyStrike, 0},
    {LabParam::Et, "impact.e_t", kAnyStrike, 0},
    {LabParam::Mu, "impact.mu", kAnyStrike, 0},
    {LabParam::Temperature, "environment.temperature", kAnyStrike, 0},
    {LabParam::Altitude, "environment.altitude", kAnyStrike, 0},
    {LabParam::Humidity, "environment.humidity", kAnyStrike, 0},
    {LabParam::WindSpeed, "environment.wind_speed", kAnyStrike, 0},
    {LabParam::WindDirection, "environment.wind_direction", kAnyStrike, 0},
};

constexpr bool params_in_enum_order() {
  for (int i = 0; i < static_cast<int>(std::size(kParams)); ++i)
    if (static_cast<int>(kParams[i].param) != i) return false;
  return std::size(kParams) == static_cast<std::size_t>(LabParam::WindDirection) + 1;
}
static_assert(params_in_enum_order(), "kParams is indexed by LabParam");

// The scenario key each LabChoice is saved under, indexed by it (Scenario and Sport load anew).
constexpr std::string_view kChoiceKeys[] = {"", "", "club.name", "bat.name", "impact.model", "impact.friction", "aero.model"};

// The field an edit sets; nullptr when the shot has no such field (a bat key on a club shot).
// Spec is ShotSpec or const ShotSpec.
template <class Spec>
auto field(Spec& s, LabParam p) -> decltype(&s.environment.temperature) {
  auto* club = std::get_if<ClubStrike>(&s.strike);
  auto* bat = std::get_if<BatStrike>(&s.strike);
  switch (p) {
    case LabParam::ClubSpeed: return club ? &club->swing.club_speed : nullptr;
    case LabParam::AttackAngle: return club ? &club->swing.attack_angle : nullptr;
    case LabParam::ClubPath: return club ? &club->swing.club_path : nullptr;
    case LabParam::DynamicLoft: return club ? &club->swing.dynamic_loft : nullptr;
    case LabParam::FaceAngle: return club ? &club->swing.face_angle : nullptr;
    case LabParam::ClosureRate: return club ? &club->swing.closure_rate : nullptr;
    case LabParam::ImpactToe: return club ? &club->swing.impact_toe : nullptr;
    case LabParam::ImpactUp: return club ? &club->swing.impact_up : nullptr;
    case LabParam::BatSpeed: return bat ? &bat->swing.bat_speed : nullptr;
    case LabParam::BatAttack: return bat ? &bat->swing.attack_angle : nullptr;
    case LabParam::BatDirection: return bat ? &bat->swing.direction : nullptr;
    case LabParam::PitchSpeed: return bat ? &bat->pitch.speed : nullptr;
    case LabParam::PitchSpin: return bat ? &bat->pitch.spin : nullptr;
    case LabParam::ImpactFromTip: return bat ? &bat->swing.impact_from_tip : nullptr;
    case LabParam::Undercut: return bat ? &bat->swing.undercut : nullptr;
    case LabParam::Temperature: return &s.environment.temperature;
    case LabParam::Altitude: return &s.environment.altitude;
    case LabParam::Humidity: return &s.environment.humidity;
    case LabParam::WindSpeed: return &s.environment.wind_speed;
    case LabParam::WindDirection: return &s.environment.wind_direction;
    case LabParam::E:
    case LabParam::Et:
    case LabParam::Mu: return nullptr;  // optionals: set in apply()
  }
  return nullptr;
}

// A value as scenario text in its key's display unit; 12 significant digits, so a slider's
// 105 mph is written "105mph" and not the last bit of its conversion to m/s and back.
std::string save_text(double si, const KeySpec& k) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", si_to_unit(si, k.unit, k.dim));
  return std::string(buf) + std::string(k.unit);
}

}  // namespace

const LabParamInfo& lab_param_info(LabParam p) { return kParams[static_cast<int>(p)]; }

LabModel::LabModel(const Assets& assets, const std::string& scenario, std::vector<std::string> overrides)
    : assets_(assets) {
  load(scenario, overrides);
}

void LabModel::load(const std::string& scenario, const std::vector<std::string>& overrides) {
  Scenario s = load_scenario(assets_, scenario, overrides);
  ResolvedShot r = s.resolved;
  ShotResult res = run_shot(r, s.name);
  if (res.impact.present) res.impact.mu_grip = mu_grip(r);
  scenario_ = std::move(s);
  start_overrides_ = overrides;
  resolved_ = std::move(r);
  result_ = std::move(res);
  edited_.clear();
  chosen_.clear();
  e_replaces_law_ = e_over_law(scenario_.spec);
  ++serial_;
}

bool LabModel::e_over_law(const ShotSpec& spec) const {
  if (!spec.impact.e) return false;
  ShotSpec own = spec;
  own.impact.e.reset();
  return resolve(own, assets_).material.e.count > 1;
}

bool LabModel::run(const ShotSpec& spec) {
  try {
    ResolvedShot r = resolve(spec, assets_);
    ShotResult res = run_shot(r, scenario_.name);
    // The Tuning panel says whether moving µ can change this launch (~1 ms of launches).
    if (res.impact.present) res.impact.mu_grip = mu_grip(r);
    const bool law = e_over_law(spec);
    resolved_ = std::move(r);
    result_ = std::move(res);
    e_replaces_law_ = law;
    status_.clear();
    ++serial_;
    return true;
  } catch (const InputError& e) {
    status_ = e.what();  // the last good shot stays
    return false;
  }
}

void LabModel::update(const Intents& intents, double now) {
  // The Lab has no clock of its own: nothing happens between intents.
  apply_in_time_order(intents, now, [](double) {}, [this](const Intent& in) { apply(in); });
}

double LabModel::value(LabParam p) const {
  const ShotSpec& s = resolved_.spec;
  switch (p) {
    case LabParam::E: return result_.impact.present ? result_.impact.e : resolved_.material.e.at(0.0);
    case LabParam::Et: return resolved_.material.e_t;
    case LabParam::Mu: return resolved_.material.mu;
    case LabParam::DynamicLoft: {
      const GolfSwing& w = std::get<ClubStrike>(s.strike).swing;
      return resolved_.club ? face_centre_loft(w, *resolved_.club) : w.dynamic_loft;
    }
    case LabParam::FaceAngle: {
      const GolfSwing& w = std::get<ClubStrike>(s.strike).swing;
      return resolved_.club ? face_centre_face_angle(w, *resolved_.club) : w.face_angle;
    }
    case LabParam::ImpactUp: {
      const double v = std::get<ClubStrike>(s.strike).swing.impact_up;
      return std::isnan(v) && resolved_.club ? resolved_.club->strike_height : v;
    }
    default: {
      const double* f = field(s, p);
      return f ? *f : 0.0;
    }
  }
}

void LabModel::apply(const Intent& in) {
  switch (in.kind) {
    case IntentKind::Swing:
    case IntentKind::Restart:
      run(resolved_.spec);  // the same shot again (deterministic): the view replays it
      break;
    case IntentKind::Edit: {
      const auto p = static_cast<LabParam>(in.param);
      if (in.param < 0 || in.param > static_cast<int>(LabParam::WindDirection)) break;
      ShotSpec spec = resolved_.spec;
      // A loft or face angle given where the face meets the ball becomes the face centre's
      // first, so an edit of the strike moves the contact over the face instead of turning it.
      if (auto* club = std::get_if<ClubStrike>(&spec.strike); club && resolved_.club) {
        if (!std::isnan(club->swing.strike_face_angle)) {
          club->swing.face_angle = face_centre_face_angle(club->swing, *resolved_.club);
          club->swing.strike_face_angle = std::nan("");
        }
        if (!std::isnan(club->swing.strike_loft)) {
          club->swing.dynamic_loft = face_centre_loft(club->swing, *resolved_.club);
          club->swing.strike_loft = std::nan("");
        }
      }
      if (p == LabParam::E) spec.impact.e = in.value;
      else if (p == LabParam::Et) spec.impact.e_t = in.value;
      else if (p == LabParam::Mu) spec.impact.mu = in.value;
      else if (double* f = field(spec, p)) *f = in.value;
      else break;
      // A range the physics refuses is named by its scenario key, as a file's would be.
      const LabParamInfo& info = lab_param_info(p);
      if (const KeySpec* k = scenario_schema().find(info.key, info.strikes)) {
        const Range* r = k->range[static_cast<std::size_t>(info.element)];
        if (r != nullptr && !r->contains(in.value)) {
          status_ = std::string(info.key) + ": " + save_text(in.value, *k) + " is outside " + range_text(*k);
          break;
        }
      }
      if (run(spec) && std::find(edited_.begin(), edited_.end(), p) == edited_.end()) edited_.push_back(p);
      break;
    }
    case IntentKind::Choose: {
      const auto c = static_cast<LabChoice>(in.param);
      if (c == LabChoice::Scenario || c == LabChoice::Sport) {
        try {
          load(c == LabChoice::Sport ? assets_.sport(in.text).default_scenario : in.text, {});
          status_.clear();
        } catch (const InputError& e) {
          status_ = e.what();
        }
        break;
      }
      ShotSpec spec = resolved_.spec;
      if (c == LabChoice::Club) {
        auto* club = std::get_if<ClubStrike>(&spec.strike);
        const auto* base = std::get_if<ClubStrike>(&scenario_.spec.strike);
        if (!club || !base) break;
        club->club = in.text;
        // The new club's own delivered loft and strike, as the scenario gave them.
        club->swing.dynamic_loft = base->swing.dynamic_loft;
        club->swing.strike_loft = base->swing.strike_loft;
        club->swing.impact_toe = base->swing.impact_toe;
        club->swing.impact_up = base->swing.impact_up;
        std::erase_if(edited_, [](LabParam p) {
          return p == LabParam::DynamicLoft || p == LabParam::ImpactToe || p == LabParam::ImpactUp;
        });
      } else if (c == LabChoice::Bat) {
        auto* bat = std::get_if<BatStrike>(&spec.strike);
        if (!bat) break;
        bat->bat = in.text;
      } else if (c == LabChoice::ImpactModel) {
        ImpactModel m;
        if (!impact_model_from_string(in.text, &m)) {
          status_ = "impact.model: unknown model " + in.text;
          break;
        }
        spec.impact.model = m;
      } else if (c == LabChoice::Friction) {
        FrictionModel m;
        if (!friction_model_from_string(in.text, &m)) {
          status_ = "impact.friction: unknown model " + in.text;
          break;
        }
        spec.impact.friction = m;
      } else if (c == LabChoice::Aero) {
        spec.aero = in.text;
      } else {
        break;
      }
      if (run(spec)) {
        std::erase_if(chosen_, [c](const auto& x) { return x.first == c; });
        chosen_.emplace_back(c, in.text);
      }
      break;
    }
    case IntentKind::Save:
      try {
        write_file_atomic(in.text, scenario_text(), OverInput::Allow);  // saving over the loaded scenario is the point
        status_ = "saved " + in.text;
      } catch (const std::exception& e) {
        status_ = e.what();
      }
      break;
    default: break;
  }
}

std::vector<std::string> LabModel::edit_overrides() const {
  std::vector<std::string> out;
  for (const auto& [c, text] : chosen_) out.push_back(std::string(kChoiceKeys[static_cast<int>(c)]) + "=" + text);
  bool offset_done = false;
  // A scenario that gives the loft where the face meets the ball keeps it that way: the face
  // an edit froze (apply) is saved as the strike loft at the strike it now has.
  const auto* base = std::get_if<ClubStrike>(&scenario_.spec.strike);
  const auto* now = std::get_if<ClubStrike>(&resolved_.spec.strike);
  const bool keep_strike_loft = base && now && resolved_.club && !std::isnan(base->swing.strike_loft);
  if (keep_strike_loft && std::isnan(now->swing.strike_loft)) {
    const KeySpec* k = scenario_schema().find("swing.strike_loft", kClubKeys);
    const double up = value(LabParam::ImpactUp);
    if (k != nullptr)
      out.push_back("swing.strike_loft=" + save_text(value(LabParam::DynamicLoft) + strike_tilt(*resolved_.club, up), *k));
  }
  // The face angle likewise, turned by the bulge at the strike it now has.
  const bool keep_strike_face = base && now && resolved_.club && !std::isnan(base->swing.strike_face_angle);
  if (keep_strike_face && std::isnan(now->swing.strike_face_angle)) {
    const KeySpec* k = scenario_schema().find("swing.strike_face_angle", kClubKeys);
    const double turn = strike_turn(*resolved_.club, value(LabParam::DynamicLoft), value(LabParam::ImpactToe),
                                    value(LabParam::ImpactUp));
    if (k != nullptr) out.push_back("swing.strike_face_angle=" + save_text(value(LabParam::FaceAngle) + turn, *k));
  }
  for (const LabParam p : edited_) {
    const LabParamInfo& info = lab_param_info(p);
    const KeySpec* k = scenario_schema().find(info.key, info.strikes);
    if (k == nullptr || (keep_strike_loft && p == LabParam::DynamicLoft) || (keep_strike_face && p == LabParam::FaceAngle))
      continue;
    if (p == LabParam::ImpactToe || p == LabParam::ImpactUp) {
      if (offset_done) continue;
      offset_done = true;
      out.push_back(std::string(info.key) + "=[" + save_text(value(LabParam::ImpactToe), *k) + ", " +
                    save_text(value(LabParam::ImpactUp), *k) + "]");
      continue;
    }
    out.push_back(std::string(info.key) + "=" + save_text(value(p), *k));
  }
  return out;
}

std::string LabModel::scenario_text() const {
  // An edit replaces the value the Lab was started with (`--set`) for its key: a key may be
  // given once.
  const std::vector<std::string> edits = edit_overrides();
  std::vector<std::string> overrides;
  for (const std::string& o : start_overrides_)
    if (std::none_of(edits.begin(), edits.end(), [&](const std::string& e) { return set_key(e) == set_key(o); }))
      overrides.push_back(o);
  overrides.insert(overrides.end(), edits.begin(), edits.end());
  return scenario_toml(load_scenario(assets_, scenario_.name, overrides));
}

}  // namespace sweetspot
