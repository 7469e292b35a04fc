#include "game/tuning/validation.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>

#include "game/content/quantity_text.hpp"
#include "game/content/scenario.hpp"
#include "game/modes/baseball/pitching.hpp"
#include "game/rules/run_shot.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

double shot_quantity(const ShotResult& r, std::string_view q) {
  const auto& L = r.launch;
  const auto& F = r.trajectory.summary;
  if (q == "ball_speed") return L.ball_speed;
  if (q == "vertical_angle") return L.vertical_angle;
  if (q == "horizontal_angle") return L.horizontal_angle;
  if (q == "spin") return L.spin.total;
  if (q == "backspin") return L.spin.backspin;
  if (q == "sidespin") return L.spin.sidespin_right;
  if (q == "spin_axis") return L.spin.axis_rad;
  if (q == "smash_factor") {
    if (!r.impact.present) throw InputError("quantity smash_factor: this shot has launch numbers only, no club or bat, so no smash factor");
    return r.smash_factor;
  }
  if (q == "carry") return F.carry_m;
  if (q == "total") return F.total_m;
  if (q == "roll") return F.total_m - F.carry_m;
  if (q == "apex") return F.apex_m;
  if (q == "landing_angle") return F.landing_angle_deg * kPi / 180.0;
  if (q == "hang_time") return F.hang_time_s;
  if (q == "lateral") return F.lateral_m;
  if (q == "distance") return F.carry_m;
  throw std::logic_error("validation: unhandled shot quantity");
}

double pitch_quantity(const Assets& assets, const PitchFlight& f, std::string_view q) {
  if (q == "induced_vertical_break") return statcast_movement(assets, f).induced_vertical_break;
  if (q == "horizontal_break") return statcast_movement(assets, f).horizontal_break;
  if (q == "flight_time") return f.flight_time;
  if (q == "plate_speed") return f.plate_velocity.norm();
  throw std::logic_error("validation: unhandled pitch quantity");
}

// The case's `set` with the baseline's assignments in place of those of the same key.
std::vector<std::pair<std::string, std::string>> conditions(const ValidationCase& c, const std::vector<std::string>& extra) {
  std::vector<std::pair<std::string, std::string>> out;  // assignment, where it is written
  for (const std::string& s : c.set) {
    const bool replaced = std::any_of(extra.begin(), extra.end(), [&](const std::string& e) { return set_key(e) == set_key(s); });
    if (!replaced) out.emplace_back(s, c.origin + ": set " + s);
  }
  for (const std::string& s : extra) out.emplace_back(s, c.origin + ": baseline " + s);
  return out;
}

double measure_shot(const Assets& assets, const ValidationCase& c, const std::vector<std::string>& extra) {
  ScenarioDoc doc = c.scenario.empty() ? parse_toml_doc("sport = \"" + c.tags.front() + "\"\n", c.origin)
                                       : read_toml_doc(resolve_scenario(assets, c.scenario));
  for (const auto& [s, origin] : conditions(c, extra)) apply_set(doc, s, origin);
  const Scenario sc = scenario_from_doc(assets, doc, c.id);
  if (sc.spec.sport != c.tags.front())
    throw InputError("tags: the case is " + c.tags.front() + "'s (its first tag) but its shot is a " + sc.spec.sport + " shot");
  return shot_quantity(run_scenario(sc, RunOptions{c.quantity->flight, false}), c.quantity->name);
}

double measure_pitch(const Assets& assets, const ValidationCase& c, const std::vector<std::string>& extra) {
  PitchCall call;
  call.type = pitch_type(load_pitch_types(assets), c.pitch_type());
  for (const auto& [s, origin] : conditions(c, extra)) {
    const std::string key = set_key(s);
    const std::string value = s.substr(s.find('=') + 1);
    static constexpr Range kFraction{0.0, 1.0};
    if (key == "pitch.speed")
      call.type.speed = flag_quantity(origin, value, Dimension::Speed, &PitchType::kSpeed);
    else if (key == "pitch.spin")
      call.type.spin = flag_quantity(origin, value, Dimension::AngularVelocity, &PitchType::kSpin);
    else if (key == "pitch.active_spin")
      call.type.active_spin = flag_quantity(origin, value, Dimension::Fraction, &kFraction);
    else
      throw InputError(origin + ": a pitch takes pitch.speed, pitch.spin and pitch.active_spin");
  }
  return pitch_quantity(assets, throw_pitch(assets, call), c.quantity->name);
}

double measure(const Assets& assets, const ValidationCase& c, const std::vector<std::string>& extra) {
  return c.is_pitch() ? measure_pitch(assets, c, extra) : measure_shot(assets, c, extra);
}

}  // namespace

double ValidationOutcome::error_in_tolerances() const { return (got - c->published) / c->tolerance; }

std::filesystem::path validation_dir(const Assets& assets) { return assets.root() / "validation"; }

ValidationOutcome run_validation_case(const Assets& assets, const ValidationCase& c) {
  ValidationOutcome out;
  out.c = &c;
  try {
    out.got = measure(assets, c, {});
    if (!c.baseline.empty()) out.got -= measure(assets, c, c.baseline);
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.rfind(c.origin, 0) == 0) throw;
    throw InputError(c.origin + ": case '" + c.id + "': " + what);
  }
  out.passed = std::isfinite(out.got) && std::fabs(out.got - c.published) <= c.tolerance;
  return out;
}

std::vector<ValidationOutcome> run_validation(const Assets& assets, const ValidationLibrary& lib,
                                              const std::string& filter) {
  std::vector<const ValidationCase*> todo;
  for (const ValidationCase& c : lib.cases)
    if (filter.empty() || std::find(c.tags.begin(), c.tags.end(), filter) != c.tags.end()) todo.push_back(&c);
  std::vector<ValidationOutcome> out(todo.size());
  std::vector<std::exception_ptr> errors(todo.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < todo.size(); i = next++) {
      try {
        out[i] = run_validation_case(assets, *todo[i]);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  const std::size_t threads =
      std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, std::max<std::size_t>(1, todo.size()));
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);  // the first bad case in library order
  return out;
}

}  // namespace sweetspot
