// aero_fit: the procedure behind assets/aero_models.toml's tour_fit, so the fit can be run
// again (after a change to the flight model, or with more data) instead of trusted.
//
//   ninja -C build/release aero_fit && build/release/aero_fit [ITERATIONS] [MODEL]
//
// Starts from MODEL (default tour_fit) as the assets define it and runs ITERATIONS (default
// 5000) Nelder-Mead steps on the six drag and lift coefficients, the crisis's rise and the
// slope past it. Held: the crisis's place and width, lift_onset, the spin decay; s_max
// follows the first of the two parabolas to turn over. Prints the objective before and
// after, the values to paste into the TOML, and the rows: TrackMan's PGA averages (fitted),
// its LPGA averages (not fitted) and the carry gains at Denver.
//
// The objective: the rms over the calibration bands of the twelve PGA rows (|carry|/4 %,
// |apex|/15 %, |landing angle|/3°) and of the Denver drive's carry gain (7.5 ± 1.5 %:
// Titleist's ~6 %, Frank Thomas's ~9 %, aero_models.toml), plus 10 × how far the worst of
// them leaves its band, plus 10 × how far the 7-iron's Denver gain exceeds the driver's.
//
// AERO_FIT_TEMPERATURE=1 adds TrackMan's temperature study (each 10 F warmer: 1.33-1.66 yd
// more carry for every club, i.e. 6.0 +- 0.7 yd from 50 to 90 F for the driver, 7-iron and
// PW) to the objective and drops the 7-iron-below-driver penalty. Measured: the family of
// Cd(S), Cl(S) with a drag crisis cannot meet it and TrackMan's landing angles together
// (driver +7.5, 7-iron +6.3, PW +4.5 yd, but PGA rows 2.2 bands out: the fit flattens the
// crisis that steepens the irons' descent). docs/validation.md has the analysis.
//
// ctest runs it for a few hundred steps from the shipped model: a model at the fit's optimum
// barely improves (the check fails if the objective falls by more than 2 %, i.e. someone
// edited the coefficients without fitting them again).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <vector>

#include "game/content/assets.hpp"
#include "game/tuning/trackman_averages.hpp"
#include "physics/error.hpp"
#include "physics/flight.hpp"
#include "physics/ground.hpp"
#include "physics/units.hpp"

using namespace sweetspot;

namespace {

constexpr double kDenver = 1609.0;                     // m, "mile high"
constexpr double kGainTarget = 0.075, kGainBand = 0.015;  // Titleist ~6 %, F. Thomas ~9 %

FlightSummary fly(const AeroModel& aero, const TourFlight& r, double altitude, double temperature = 294.15) {
  Environment env;
  env.altitude = altitude;
  env.temperature = temperature;
  const BallProperties ball = golf_ball_properties();
  const ShotModel m = make_shot_model(ball, aero, env, nullptr, FlightSettings{});
  const LaunchState l = launch_from_metrics(mph_to_mps(r.ball_mph), deg_to_rad(r.launch_deg), 0.0,
                                            rpm_to_radps(r.spin_rpm), 0.0, Vec3(0.0, ball.radius, 0.0));
  return simulate_shot(m, l, false).summary;
}

double warm_gain_yd(const AeroModel& aero, const TourFlight& r) {
  return m_to_yd(fly(aero, r, 0.0, fahrenheit_to_kelvin(90.0)).carry_m - fly(aero, r, 0.0, fahrenheit_to_kelvin(50.0)).carry_m);
}

double denver_gain(const AeroModel& aero, const TourFlight& r) { return fly(aero, r, kDenver).carry_m / fly(aero, r, 0.0).carry_m - 1.0; }

/// Each row's distances from the table in units of its band; printed when `print`.
std::vector<double> bands(const AeroModel& aero, std::span<const TourFlight> rows, bool print) {
  std::vector<double> out;
  for (const TourFlight& r : rows) {
    const FlightSummary s = fly(aero, r, 0.0);
    const double carry = m_to_yd(s.carry_m), apex = m_to_yd(s.apex_m), land = s.landing_angle_deg;
    out.push_back(std::abs(carry / r.carry_yd - 1.0) / 0.04);
    out.push_back(std::abs(apex / r.apex_yd - 1.0) / 0.15);
    out.push_back(std::abs(land - r.landing_deg) / 3.0);
    if (print)
      std::printf("  %-7s carry %6.1f yd (%+5.1f %%)  apex %5.1f yd (%+5.1f %%)  landing %4.1f deg (%+4.1f)\n", r.club,
                  carry, 100.0 * (carry / r.carry_yd - 1.0), apex, 100.0 * (apex / r.apex_yd - 1.0), land,
                  land - r.landing_deg);
  }
  return out;
}

constexpr int kFree = 8;  // d0 d1 d2 l0 l1 l2 crisis_rise drag_re_slope
using Params = std::array<double, kFree>;

Params params_of(const AeroModel& m) { return {m.d0, m.d1, m.d2, m.l0, m.l1, m.l2, m.crisis_rise, m.drag_re_slope}; }

AeroModel model_with(AeroModel m, const Params& p) {
  m.d0 = p[0], m.d1 = p[1], m.d2 = p[2], m.l0 = p[3], m.l1 = p[4], m.l2 = p[5], m.crisis_rise = p[6];
  m.drag_re_slope = p[7];
  // Hold S where the first parabola turns over, so neither coefficient turns back.
  const double lift_peak = m.l2 < 0.0 ? -m.l1 / (2.0 * m.l2) : 1e9, drag_peak = m.d2 < 0.0 ? -m.d1 / (2.0 * m.d2) : 1e9;
  m.s_max = std::min({lift_peak, drag_peak, 1.0});
  return m;
}

double objective(const AeroModel& base, const Params& p) {
  const AeroModel m = model_with(base, p);
  if (!(m.s_max > m.lift_onset) || !validate_aero_model(m).empty()) return 1e9;
  std::vector<double> b = bands(m, kPgaTourFlights, false);
  const double driver = denver_gain(m, tour_flight(kPgaTourFlights, "driver")),
               seven = denver_gain(m, tour_flight(kPgaTourFlights, "7-iron"));
  b.push_back(std::abs(driver - kGainTarget) / kGainBand);
  if (std::getenv("AERO_FIT_TEMPERATURE"))
    for (const char* club : {"driver", "7-iron", "pw"})
      b.push_back(std::abs(warm_gain_yd(m, tour_flight(kPgaTourFlights, club)) - 6.0) / 0.7);
  double ss = 0.0, worst = 0.0;
  for (const double x : b) ss += x * x, worst = std::max(worst, x);
  return std::sqrt(ss / static_cast<double>(b.size())) + 10.0 * std::max(0.0, worst - 1.0) +
         (std::getenv("AERO_FIT_TEMPERATURE") ? 0.0 : 10.0 * std::max(0.0, seven - driver));
}

/// Nelder-Mead (reflection 1, expansion 2, contraction 1/2, shrink 1/2) from `start`, each
/// coordinate's first step 10 % of it (0.02 where it is near 0).
Params nelder_mead(const AeroModel& base, const Params& start, int iterations, double* best) {
  std::array<Params, kFree + 1> pts;
  std::array<double, kFree + 1> f{};
  for (int i = 0; i <= kFree; ++i) {
    pts[i] = start;
    if (i > 0) pts[i][i - 1] += std::abs(start[i - 1]) > 0.01 ? 0.1 * start[i - 1] : 0.02;
    f[i] = objective(base, pts[i]);
  }
  for (int it = 0; it < iterations; ++it) {
    int hi = 0, lo = 0;
    for (int i = 0; i <= kFree; ++i) {
      if (f[i] > f[hi]) hi = i;
      if (f[i] < f[lo]) lo = i;
    }
    int next = lo;
    for (int i = 0; i <= kFree; ++i)
      if (i != hi && f[i] > f[next]) next = i;
    Params centre{};
    for (int i = 0; i <= kFree; ++i)
      if (i != hi)
        for (int j = 0; j < kFree; ++j) centre[j] += pts[i][j] / kFree;
    auto along = [&](double t) {
      Params q;
      for (int j = 0; j < kFree; ++j) q[j] = centre[j] + t * (centre[j] - pts[hi][j]);
      return q;
    };
    const Params reflected = along(1.0);
    const double fr = objective(base, reflected);
    if (fr < f[lo]) {
      const Params expanded = along(2.0);
      const double fe = objective(base, expanded);
      pts[hi] = fe < fr ? expanded : reflected;
      f[hi] = std::min(fe, fr);
    } else if (fr < f[next]) {
      pts[hi] = reflected, f[hi] = fr;
    } else {
      const Params contracted = along(-0.5);
      const double fc = objective(base, contracted);
      if (fc < f[hi]) {
        pts[hi] = contracted, f[hi] = fc;
      } else {
        for (int i = 0; i <= kFree; ++i) {
          if (i == lo) continue;
          for (int j = 0; j < kFree; ++j) pts[i][j] = pts[lo][j] + 0.5 * (pts[i][j] - pts[lo][j]);
          f[i] = objective(base, pts[i]);
        }
      }
    }
  }
  const int lo = static_cast<int>(std::min_element(f.begin(), f.end()) - f.begin());
  *best = f[lo];
  return pts[lo];
}

int run(int argc, char** argv) {
  const int iterations = argc > 1 ? std::atoi(argv[1]) : 5000;
  const std::string name = argc > 2 ? argv[2] : "tour_fit";
  if (iterations < 0) throw InputError("ITERATIONS must be >= 0");
  const Assets assets;
  const AeroModel& base = assets.aero(name);
  if (!(base.crisis_rise > 0.0)) throw InputError("aero model '" + name + "' has no drag crisis to fit around");
  const double before = objective(base, params_of(base));
  double after = before;
  const Params fitted = iterations > 0 ? nelder_mead(base, params_of(base), iterations, &after) : params_of(base);
  const AeroModel m = model_with(base, fitted);
  std::printf("%s: objective %.4f -> %.4f after %d iterations\n", name.c_str(), before, after, iterations);
  std::printf("drag = [%.6f, %.6f, %.6f]\nlift = [%.6f, %.6f, %.6f]\ns_max = %.5f\n", m.d0, m.d1, m.d2, m.l0, m.l1,
              m.l2, m.s_max);
  std::printf("drag_crisis = [%.5g, %.6f, %.5g]\ndrag_re_slope = %.6f\n", m.crisis_re, m.crisis_rise, m.crisis_width,
              m.drag_re_slope);
  auto worst = [](const std::vector<double>& b) { return *std::max_element(b.begin(), b.end()); };
  std::printf("TrackMan PGA (fitted):\n");
  const double pga = worst(bands(m, kPgaTourFlights, true));
  std::printf("TrackMan LPGA (not fitted):\n");
  const double lpga = worst(bands(m, kLpgaTourFlights, true));
  std::printf("worst of a band: PGA %.2f, LPGA %.2f\n", pga, lpga);
  std::printf("50->90 F carry gain: driver %+.1f yd, 7-iron %+.1f yd, PW %+.1f yd\n",
              warm_gain_yd(m, tour_flight(kPgaTourFlights, "driver")), warm_gain_yd(m, tour_flight(kPgaTourFlights, "7-iron")),
              warm_gain_yd(m, tour_flight(kPgaTourFlights, "pw")));
  std::printf("Denver carry gain: driver %+.1f %%, 7-iron %+.1f %%, PW %+.1f %%, LPGA driver %+.1f %%\n",
              100.0 * denver_gain(m, tour_flight(kPgaTourFlights, "driver")),
              100.0 * denver_gain(m, tour_flight(kPgaTourFlights, "7-iron")),
              100.0 * denver_gain(m, tour_flight(kPgaTourFlights, "pw")),
              100.0 * denver_gain(m, tour_flight(kLpgaTourFlights, "driver")));
  // The check ctest runs: the shipped model is the fit's optimum.
  if (const char* check = std::getenv("AERO_FIT_CHECK"); check != nullptr && after < 0.98 * before) {
    std::printf("FAIL: %s is not at the fit's optimum (objective %.4f -> %.4f): fit it again\n", name.c_str(), before,
                after);
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const InputError& e) {
    std::fprintf(stderr, "aero_fit: %s\n", e.what());
    return 2;
  }
}
