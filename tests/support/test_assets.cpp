#include "support/test_assets.hpp"

#include "physics/units.hpp"

namespace sweetspot::test {

const Assets& assets() {
  static const Assets a(std::filesystem::path(SWEETSPOT_SOURCE_DIR) / "assets");
  return a;
}

const Course& links() {
  static const Course c = load_course(assets(), "links");
  return c;
}

ShotModel golf_model(const Terrain* terrain, const Environment& env, const FlightSettings& settings) {
  return make_shot_model(golf_ball_properties(), assets().aero(assets().sport("golf").default_aero), env, terrain, settings);
}

ShotModel baseball_model(const Terrain* terrain, const Environment& env, const FlightSettings& settings) {
  return make_shot_model(baseball_properties(), assets().aero("nathan"), env, terrain, settings);
}

ShotTrajectory fly(const FlightCase& c, const Terrain* terrain) {
  const AeroModel& aero = c.aero ? *c.aero : assets().aero(assets().sport("golf").default_aero);
  return simulate_shot(make_shot_model(c.ball, aero, c.environment, terrain, c.settings), c.launch, c.record_samples);
}

ShotSpec launch_spec(const char* sport, double mph, double launch_deg, double rpm, double direction_deg) {
  ShotSpec spec;
  spec.sport = sport;
  LaunchStrike l;
  l.numbers.ball_speed = mph_to_mps(mph);
  l.numbers.vertical_angle = deg_to_rad(launch_deg);
  l.numbers.horizontal_angle = deg_to_rad(direction_deg);
  l.numbers.spin = rpm_to_radps(rpm);
  spec.strike = l;
  return spec;
}

FlightCase golf_launch(double mph, double launch_deg, double rpm, const char* model) {
  FlightCase c;
  c.aero = &assets().aero(model);
  c.launch = launch_from_metrics(mph_to_mps(mph), deg_to_rad(launch_deg), 0.0, rpm_to_radps(rpm), 0.0,
                                 Vec3(0.0, c.ball.radius, 0.0));
  return c;
}

}  // namespace sweetspot::test
