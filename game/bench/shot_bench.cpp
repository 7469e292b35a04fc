#include "game/bench/shot_bench.hpp"

#include "game/content/course_file.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

#include "game/content/assets.hpp"
#include "game/bench/bullet_baseline.hpp"
#include "physics/flight.hpp"
#include "physics/units.hpp"
#include "physics/world.hpp"

namespace sweetspot::bench {
namespace {

using Clock = std::chrono::steady_clock;

template <class Shot>
ShotBenchResult time_shots(double min_seconds, const Shot& shot) {
  ShotBenchResult r;
  double total = shot();  // warm-up (caches, lazy statics), not timed
  total = 0.0;
  const auto t0 = Clock::now();
  double elapsed = 0.0;
  do {
    for (int i = 0; i < 16; ++i) total += shot();
    r.shots += 16;
    elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  } while (elapsed < min_seconds);
  r.seconds = elapsed;
  r.us_per_shot = elapsed * 1e6 / r.shots;
  r.shots_per_second = r.shots / elapsed;
  r.mean_total_m = total / r.shots;
  return r;
}

BaselineGround golf_ground(const WorldDescription& d) {
  BaselineGround g;
  for (const WorldMesh& m : d.meshes) {
    if (d.materials[static_cast<size_t>(m.material)].kind == SurfaceKind::Decoration) continue;
    const int base = static_cast<int>(g.positions.size());
    g.positions.insert(g.positions.end(), m.vertices.begin(), m.vertices.end());
    for (std::uint32_t i : m.indices) g.indices.push_back(base + static_cast<int>(i));
  }
  // Bullet's combined restitution/friction: fairway-like values for a typical game.
  g.restitution = 0.3;
  g.friction = 0.4;
  return g;
}

AeroFn baseline_aero(const ShotModel& m) {
  const AeroModel* model = m.aero;
  const double rho = m.air_density;
  const double radius = m.ball.radius;
  return [model, rho, radius](const Vec3&, const Vec3& v, const Vec3& w) {
    const sweetspot::AeroEffect fx = aero_effect(*model, rho, radius, v, w);
    return bench::AeroEffect{fx.force, fx.spin_rate};
  };
}

BaselineBall baseline_ball(const ShotModel& m) { return BaselineBall{m.ball.mass, m.ball.radius, m.ball.inertia}; }

ShotModel golf_model(const Assets& assets, const Terrain* terrain, FlightSettings settings = {}) {
  return make_shot_model(golf_ball_properties(), assets.aero(assets.sport("golf").default_aero), Environment{}, terrain, settings);
}

}  // namespace

std::vector<BenchLaunch> bench_tour_launches() {
  // TrackMan PGA Tour averages (DESIGN §4): ball speed, launch angle, spin.
  const Vec3 tee(0.0, golf_ball_properties().radius, 0.0);
  return {
      {"driver", launch_from_metrics(mph_to_mps(167.0), deg_to_rad(10.9), 0.0, rpm_to_radps(2686.0), 0.0, tee)},
      {"7-iron", launch_from_metrics(mph_to_mps(120.0), deg_to_rad(16.3), 0.0, rpm_to_radps(7097.0), 0.0, tee)},
      {"pw", launch_from_metrics(mph_to_mps(102.0), deg_to_rad(24.2), 0.0, rpm_to_radps(9304.0), 0.0, tee)},
  };
}

ShotBenchResult bench_golf_shots(const Assets& assets, double min_seconds, SweepMethod method) {
  const World world(assets.world("golf_hole")->description(), method);
  const ShotModel model = golf_model(assets, &world);
  const std::vector<BenchLaunch> launches = bench_tour_launches();
  std::size_t next = 0;
  return time_shots(min_seconds, [&] {
    return simulate_shot(model, launches[next++ % launches.size()].launch, false).summary.total_m;
  });
}

ShotBenchResult bench_course_shots(const Assets& assets, double min_seconds) {
  const Course course = load_course(assets, "national");
  const CourseHole& first = course.holes.front();
  const World world(first.world->description(), SweepMethod::BvhExact);
  const ShotModel model = golf_model(assets, &world);
  std::vector<BenchLaunch> launches = bench_tour_launches();
  for (BenchLaunch& l : launches) l.launch.position += first.tee;  // hole 1 runs east, along +x
  std::size_t next = 0;
  return time_shots(min_seconds, [&] {
    return simulate_shot(model, launches[next++ % launches.size()].launch, false).summary.total_m;
  });
}

namespace {

FlightSettings reference_tolerances() {
  FlightSettings tight;
  tight.rel_tol = 1e-13;
  tight.abs_tol = 1e-14;
  tight.bounce_rel_tol = 1e-13;
  return tight;
}

ShotBenchResult time_tour_launches(const ShotModel& model, double min_seconds) {
  const std::vector<BenchLaunch> launches = bench_tour_launches();
  std::size_t next = 0;
  return time_shots(min_seconds, [&] {
    return simulate_shot(model, launches[next++ % launches.size()].launch, false).summary.total_m;
  });
}

}  // namespace

ShotBenchResult bench_golf_shots_flat(const Assets& assets, double min_seconds) {
  return time_tour_launches(golf_model(assets, nullptr), min_seconds);
}

ShotBenchResult bench_golf_shots_tight(const Assets& assets, double min_seconds) {
  return time_tour_launches(golf_model(assets, assets.world("golf_hole")->world.get(), reference_tolerances()), min_seconds);
}

ShotBenchResult bench_baseball_shots(const Assets& assets, double min_seconds) {
  const ShotModel model = make_shot_model(baseball_properties(), assets.aero("nathan"), Environment{},
                                          assets.world("ballpark")->world.get());
  const LaunchState launch = launch_from_metrics(mph_to_mps(103.0), deg_to_rad(28.0), 0.0, rpm_to_radps(2000.0), 0.0,
                                                 Vec3(0.0, 0.9, 0.0));
  return time_shots(min_seconds, [&] { return simulate_shot(model, launch, false).summary.total_m; });
}

ShotBenchResult bench_baseline_golf_shots(const Assets& assets, double min_seconds) {
  const BaselineGround ground = golf_ground(assets.world("golf_hole")->description());
  const BaselineGroundShape shape(ground);  // built once, as a game builds its level
  const ShotModel model = golf_model(assets, nullptr);
  const AeroFn aero = baseline_aero(model);
  const BaselineBall ball = baseline_ball(model);
  const std::vector<BenchLaunch> launches = bench_tour_launches();
  std::size_t next = 0;
  return time_shots(min_seconds, [&] {
    return run_bullet_baseline(launches[next++ % launches.size()].launch, ball, aero, shape).total_m;
  });
}

CarryErrors golf_carry_errors(const Assets& assets) {
  const WorldAsset& w = *assets.world("golf_hole");
  const BaselineGround ground = golf_ground(w.description());
  const ShotModel model = golf_model(assets, w.world.get());
  const ShotModel reference = golf_model(assets, w.world.get(), reference_tolerances());
  CarryErrors e;
  for (const BenchLaunch& l : bench_tour_launches()) {
    CarryError c;
    c.name = l.name;
    c.ours_m = simulate_shot(model, l.launch, false).summary.carry_m;
    c.reference_m = simulate_shot(reference, l.launch, false).summary.carry_m;
    BaselineOptions opt;
    opt.carry_only = true;
    c.baseline_m = run_bullet_baseline(l.launch, baseline_ball(model), baseline_aero(model), ground, opt).carry_m;
    c.ours_error_m = std::abs(c.ours_m - c.reference_m);
    c.baseline_error_m = std::abs(c.baseline_m - c.reference_m);
    e.ours_error_m = std::max(e.ours_error_m, c.ours_error_m);
    e.baseline_error_m = std::max(e.baseline_error_m, c.baseline_error_m);
    e.shots.push_back(c);
  }
  return e;
}

}  // namespace sweetspot::bench
