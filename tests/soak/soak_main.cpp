// Soak test: N seeded random golf and baseball deliveries and launch-only shots across the
// physical ranges the physics accepts, plus one field pushed just outside its range for about
// one shot in eight. Every accepted shot must end with finite numbers everywhere (launch,
// impact, summary, every trajectory sample) and within its step and time bound; every
// out-of-range input must be refused with InputError (never NaN, a crash or a silent clamp).
//
//   soak_tests [--count N] [--seed S]     (ctest runs a reduced count; the full soak is
//   build/release/tests/soak_tests --count 1000000)
//
// Shot i draws from its own generator seeded by (seed, i), so a failure report "shot i" is
// reproduced alone with --first i --count 1; SOAK_VERBOSE=1 prints every flight refusal.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "game/content/assets.hpp"
#include "game/content/equipment_file.hpp"
#include "physics/aero.hpp"
#include "physics/delivery.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/launch.hpp"
#include "physics/units.hpp"
#include "physics/world.hpp"
#include "soak/soak_rng.hpp"
#include "support/test_assets.hpp"

namespace {

using namespace sweetspot;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

using SoakRng = soak::Rng;  // not sweetspot::Rng, which it builds on

struct Counts {
  long accepted = 0, refused_ok = 0, flight_refused = 0, world_shots = 0, misses = 0;
};

[[noreturn]] void fail(long i, const std::string& what) {
  std::fprintf(stderr, "soak: shot %ld: %s\n", i, what.c_str());
  std::exit(1);
}

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

void check_launch(long i, const LaunchState& l) {
  if (!finite(l.position) || !finite(l.velocity) || !finite(l.spin)) fail(i, "non-finite launch state");
  const LaunchMetrics m = measure_launch(l);
  if (!std::isfinite(m.ball_speed) || !std::isfinite(m.vertical_angle) || !std::isfinite(m.horizontal_angle) ||
      !std::isfinite(m.spin.total) || !std::isfinite(m.spin.axis_rad))
    fail(i, "non-finite launch metrics");
}

void check_flight(long i, const LaunchState& launch, const FlightSettings& settings, const ShotTrajectory& t) {
  const FlightStats& st = t.stats;
  const FlightSummary& s = t.summary;
  for (double v : {s.carry_m, s.total_m, s.apex_m, s.landing_angle_deg, s.hang_time_s, s.lateral_m, s.total_time_s})
    if (!std::isfinite(v)) fail(i, "non-finite flight summary");
  if (!finite(s.landing_position) || !finite(s.rest_position)) fail(i, "non-finite landing/rest position");
  if (st.flight_steps + st.roll_steps > settings.max_steps) fail(i, "exceeded the step bound");
  if (s.total_time_s > settings.max_time * (1 + 1e-9)) fail(i, "exceeded the time bound");
  if (s.end == EndReason::StepLimit) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "ended on the step/time limit (a hang for sane input): launch v (%.17g, %.17g, %.17g) m/s, "
                  "spin (%.17g, %.17g, %.17g) rad/s, %ld flight + %ld roll steps, %.3f s",
                  launch.velocity.x(), launch.velocity.y(), launch.velocity.z(), launch.spin.x(),
                  launch.spin.y(), launch.spin.z(), static_cast<long>(st.flight_steps),
                  static_cast<long>(st.roll_steps), s.total_time_s);
    fail(i, buf);
  }
  if (t.samples.empty()) fail(i, "no trajectory samples");
  for (const auto& p : t.samples)
    if (!std::isfinite(p.t) || !finite(p.position) || !finite(p.velocity) || !finite(p.spin))
      fail(i, "non-finite trajectory sample at t = " + std::to_string(p.t));
}

Environment random_environment(SoakRng& r) {
  Environment e;
  e.temperature = r.in(263.15, 318.15);  // -10..45 C
  e.altitude = r.in(0.0, 3000.0);
  e.humidity = r.in(0.0, 1.0);
  e.wind_speed = r.in(0.0, 20.0);
  e.wind_direction = r.in(-3.14159, 3.14159);
  return e;
}

struct Worlds {
  const World* golf = nullptr;
  const World* park = nullptr;
};

// One shot; returns normally when it was accepted or correctly refused.
void soak_one(long i, std::uint64_t seed, const EquipmentCatalog& eq, const Worlds& worlds, Counts& c) {
  SoakRng r{seed ^ (static_cast<std::uint64_t>(i) * 0xD1B54A32D192ED03ULL)};
  const int kind = static_cast<int>(i % 4);  // golf delivery, baseball delivery, golf launch, baseball launch
  const bool golf = kind == 0 || kind == 2;
  const bool outside = r.below(8) == 0;
  const int bad = r.below(6);  // which field goes out of range when `outside`
  auto pick = [&](int field, double lo, double hi) { return (outside && bad == field) ? r.outside(lo, hi) : r.in(lo, hi); };
  // In-range draws come from the physics parameters' own ranges (one range per value).
  auto pick_in = [&](int field, const Range& range, double floor = -1e300) {
    if (outside && bad == field) return r.outside(range.min, range.max);
    return r.in(std::max(range.min, floor), range.max);
  };

  LaunchState launch;
  const BallSpec& ball = eq.ball(golf ? "tour" : "mlb");
  try {
    if (kind == 0) {
      const ClubSpec& club = eq.clubs[static_cast<std::size_t>(r.below(static_cast<int>(eq.clubs.size())))];
      GolfSwing s;
      s.club_speed = pick_in(0, GolfSwing::kClubSpeed, 1.0);
      s.attack_angle = pick_in(1, GolfSwing::kAttackAngle);
      s.club_path = r.in(GolfSwing::kClubPath.min, GolfSwing::kClubPath.max);
      s.dynamic_loft = pick_in(2, GolfSwing::kDynamicLoft);
      // NaN is the API's "use the club's own loft", so the non-finite probe here is -inf.
      if (std::isnan(s.dynamic_loft)) s.dynamic_loft = -std::numeric_limits<double>::infinity();
      s.face_angle = pick_in(3, GolfSwing::kFaceAngle);
      // In range: on this club's face as well as within the swing's own bounds.
      const Range toe{std::max(GolfSwing::kImpactToe.min, -club.face_half_width),
                      std::min(GolfSwing::kImpactToe.max, club.face_half_width)};
      s.impact_toe = pick_in(4, toe);
      s.impact_up = r.in(std::max(GolfSwing::kImpactUp.min, -club.face_half_height),
                         std::min(GolfSwing::kImpactUp.max, club.face_half_height));
      s.closure_rate = pick_in(5, GolfSwing::kClosureRate);
      ImpactMaterial m = club.face;
      m.mu = r.in(0.0, 0.8);
      launch = deliver_golf(ball, club, s, m).launch;
    } else if (kind == 1) {
      const BatSpec& bat = eq.bats[static_cast<std::size_t>(r.below(static_cast<int>(eq.bats.size())))];
      BatSwing s;
      s.bat_speed = pick_in(0, BatSwing::kBatSpeed, 1.0);
      s.attack_angle = pick_in(1, BatSwing::kAttackAngle);
      s.direction = pick_in(2, BatSwing::kDirection);
      const double reach = bat.length - bat.pivot_from_knob - 0.05;
      const double past_end = -kEndCapReach * ball.radius;  // the ball's edge on the end cap's rim
      s.impact_from_tip = pick(3, past_end, reach);
      const double reach_r = 0.95 * bat_ball_reach(bat, ball, std::min(std::max(s.impact_from_tip, past_end), reach));
      s.undercut = r.in(-0.999 * reach_r, 0.999 * reach_r);
      Pitch p;
      p.speed = pick_in(4, Pitch::kSpeed);
      p.approach_angle = r.in(Pitch::kApproachAngle.min, Pitch::kApproachAngle.max);
      p.spin = pick_in(5, Pitch::kSpin);
      p.spin_axis = r.in(-3.14159, 3.14159);
      launch = deliver_baseball(ball, bat, s, p, bat.material).launch;
    } else {
      const Vec3 start(0.0, golf ? ball.radius : kBaseballContactHeight, 0.0);
      const double vmax = LaunchNumbers::kBallSpeed.max, wmax = LaunchNumbers::kSpin.max;
      launch = launch_from_metrics(r.in(0.0, vmax), r.in(-10 * kDeg, 89 * kDeg), r.in(-45 * kDeg, 45 * kDeg),
                                   r.in(0.0, wmax), r.in(LaunchNumbers::kSpinAxis.min, LaunchNumbers::kSpinAxis.max),
                                   start);
      if (outside) {
        // The flight refuses a launch beyond its speed or spin range, or a non-finite one.
        if (bad % 3 == 0) launch.velocity = Vec3(r.in(vmax * 1.0001, vmax * 1.2), 0.0, 0.0);
        else if (bad % 3 == 1) launch.spin = Vec3(0.0, 0.0, r.in(wmax * 1.0001, wmax * 1.2));
        else launch.position.x() = std::numeric_limits<double>::quiet_NaN();
      }
    }
  } catch (const InputError& e) {
    // In-range fields can still describe a geometric miss (a glancing, slow swing far off
    // centre); that refusal is an answer, every other one of in-range input is a failure.
    if (!outside && std::string_view(e.what()).find("the strike misses") != std::string_view::npos) {
      ++c.misses;
      return;
    }
    if (!outside) fail(i, std::string("an in-range delivery was refused: ") + e.what());
    ++c.refused_ok;
    return;
  }
  const bool launch_outside = outside && kind >= 2;
  if (outside && !launch_outside) {
    // Every delivery field `bad` names is range-checked, so reaching here is a silent clamp.
    fail(i, "an out-of-range delivery field was accepted (kind " + std::to_string(kind) + ", field " + std::to_string(bad) + ")");
  }
  if (!launch_outside) check_launch(i, launch);

  const BallProperties props{ball.mass, ball.radius, ball.inertia};
  const Environment environment = random_environment(r);
  const AeroModel& aero = sweetspot::test::assets().aero(golf ? "tour_fit" : "nathan");
  const FlightSettings settings;
  const Terrain* terrain = nullptr;
  if (i % 16 < 2) {  // one shot in eight on the asset worlds (slower), the rest on flat ground
    terrain = golf ? worlds.golf : worlds.park;
    ++c.world_shots;
  }
  ShotTrajectory t;
  try {
    t = simulate_shot(make_shot_model(props, aero, environment, terrain, settings), launch);
  } catch (const InputError& e) {
    if (std::getenv("SOAK_VERBOSE")) std::fprintf(stderr, "shot %ld: flight refused: %s\n", i, e.what());
    if (launch_outside) {
      ++c.refused_ok;
      return;
    }
    // A delivery inside its ranges that the flight refuses (e.g. more spin than it accepts)
    // is counted and reported, not a crash; the refusal itself is the clear message.
    ++c.flight_refused;
    return;
  }
  if (launch_outside) fail(i, "an out-of-range launch was flown");
  check_flight(i, launch, settings, t);
  ++c.accepted;
}

}  // namespace

int main(int argc, char** argv) {
  long count = 20000, first = 0;
  std::uint64_t seed = 20261123;
  for (int a = 1; a < argc; ++a) {
    const std::string_view arg = argv[a];
    auto value = [&]() -> const char* {
      if (a + 1 >= argc) {
        std::fprintf(stderr, "soak_tests: %s needs a value\n", argv[a]);
        std::exit(2);
      }
      return argv[++a];
    };
    char* end = nullptr;
    const char* v = nullptr;
    if (arg == "--count") count = std::strtol(v = value(), &end, 10);
    else if (arg == "--first") first = std::strtol(v = value(), &end, 10);
    else if (arg == "--seed") seed = std::strtoull(v = value(), &end, 10);
    else {
      std::fprintf(stderr, "soak_tests: unknown argument '%s' (allowed: --count N, --first I, --seed S)\n", argv[a]);
      return 2;
    }
    if (end == v || *end != '\0' || count < 0 || first < 0) {
      std::fprintf(stderr, "soak_tests: %s: expected a non-negative integer, got '%s'\n", argv[a - 1], v);
      return 2;
    }
  }
  try {
    const EquipmentCatalog& eq = sweetspot::test::assets().equipment();
    Worlds worlds;
    worlds.golf = sweetspot::test::assets().world("golf_hole")->world.get();
    worlds.park = sweetspot::test::assets().world("ballpark")->world.get();
    Counts c;
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = first; i < first + count; ++i) soak_one(i, seed, eq, worlds, c);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("soak: %ld shots (seed %llu) in %.1f s: %ld flown and finite (%ld on asset worlds), %ld out-of-range "
                "inputs refused with InputError, %ld in-range deliveries the flight refused, %ld misses\n",
                count, static_cast<unsigned long long>(seed), secs, c.accepted, c.world_shots, c.refused_ok,
                c.flight_refused, c.misses);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "soak: unexpected exception: %s\n", e.what());
    return 1;
  }
  return 0;
}
