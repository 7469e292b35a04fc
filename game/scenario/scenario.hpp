// A scenario: everything that defines one shot (sport, equipment, swing and pitch,
// impact material, air, world, expectations), loaded from a TOML file or a built-in name
// with `--set` overrides, and run through delivery -> impact -> flight to a ShotResult.
//
// Parameters are immutable once loaded; run_scenario() is a pure function of the
// Scenario (deterministic, thread-safe: each thread keeps its own world cache), so the
// CLI, UI, sweeps and tests all share it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/report/shot_result.hpp"
#include "game/scenario/scenario_doc.hpp"
#include "physics/aero.hpp"
#include "physics/atmosphere.hpp"
#include "physics/delivery.hpp"
#include "physics/equipment.hpp"
#include "physics/flight.hpp"
#include "physics/world.hpp"

namespace sweetspot {

/// world.name for the infinite flat fairway (no course or ballpark), as `flight --world none`.
inline constexpr const char* kFlatWorld = "none";

/// A launch-only scenario (`[launch]` section): the ball leaves with these launch-monitor
/// numbers and no club or bat is simulated. SI.
struct LaunchOnly {
  double ball_speed = 0.0;        ///< m/s, tour driver 74.7
  double vertical_angle = 0.0;    ///< rad, + up
  double horizontal_angle = 0.0;  ///< rad, + right
  double spin = 0.0;              ///< rad/s total
  double spin_axis = 0.0;         ///< rad, + curves right
};

/// One `expect.NAME` entry with its tolerance, SI.
struct Expectation {
  std::string name;               ///< "ball_speed", "carry", ...
  std::vector<double> value;      ///< one element for scalars
  double tolerance = 0.0;
};

struct Scenario {
  std::string name;               ///< built-in name ("golf/driver") or the path given
  std::string description;
  Sport sport = Sport::Golf;
  BallSpec ball;                  ///< after ball.mass / ball.radius overrides
  ClubSpec club;                  ///< golf: after club.head_mass override
  BatSpec bat;                    ///< baseball: after bat.mass override
  GolfSwing golf_swing;           ///< golf
  BatSwing bat_swing;             ///< baseball
  Pitch pitch;                    ///< baseball
  ImpactMaterial material;        ///< the club face / bat material after impact.* overrides
  std::optional<LaunchOnly> launch;  ///< set: launch-only, no impact
  Environment environment;
  const AeroModel* aero = nullptr;   ///< never null after load
  std::string world;              ///< world asset name ("golf_hole", "ballpark") or kFlatWorld
  /// Golf: where the ball rests, m: (x, ground height, z) from world.ball_position; the
  /// tee at the origin is (0, 0, 0). Baseball: zero (contact above home plate).
  Vec3 ball_offset = Vec3::Zero();
  double aim = 0.0;               ///< golf: rad, target line turned right of +x (world.aim)
  std::string lie;                ///< golf: required surface under the ball ("" = any)
  std::string start_surface;      ///< golf: surface the ball rests on ("tee", "sand", ...)
  std::vector<Expectation> expectations;
  ScenarioDoc doc;                ///< the document it came from (origins, `regress --update`)
};

/// Loads a built-in name or .toml path, applies `overrides` ("key=value", as `--set`),
/// validates everything and resolves equipment, aero model and world by name. Throws
/// InputError naming file:line / flag / key and the allowed range.
Scenario load_scenario(std::string_view name_or_path, const std::vector<std::string>& overrides);
/// The same from an already-parsed document (UI edits, tests); `name` labels the result.
Scenario scenario_from_doc(const ScenarioDoc& doc, std::string name);

struct RunOptions {
  bool fly = true;             ///< false: delivery and launch only (fit, fast sweeps)
  bool record_samples = true;  ///< false: summary only (sweeps, benchmarks)
};

/// The world by name or path, loaded and built once per process and shared: its queries
/// only read, so any number of threads may use it. nullptr for kFlatWorld. Throws
/// InputError for an unknown name or a bad file.
const World* shared_world(const std::string& name);

/// Delivery -> impact -> launch -> flight on the scenario's world. Deterministic and safe to
/// call from many threads. The world is loaded and built once per process and shared.
ShotResult run_scenario(const Scenario& s, const RunOptions& options = {});

/// DESIGN §6 JSON of a shot of `s` (the report's shot_json; the scenario adds nothing the
/// result does not carry, the overload exists for callers that hold both).
nlohmann::json shot_json(const ShotResult& r, const Scenario& s);

}  // namespace sweetspot
