#include "game/tuning/fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "game/content/scenario_doc.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
namespace {

struct Eval {
  std::array<double, 3> r{};  // scaled residuals (0 for quantities not targeted)
  double cost = 0.0;
  ShotResult shot;
};

class Objective {
 public:
  Objective(const Scenario& base, const FitTarget& t) : s_(base.resolved), name_(base.name), t_(t) {}

  Eval operator()(double e, double mu) {
    s_.material.e = CorCurve::constant(e);
    s_.material.mu = mu;
    Eval out;
    out.shot = launch_shot(s_, name_);
    ++evaluations;
    const auto& L = out.shot.launch;
    if (t_.ball_speed) out.r[0] = (L.ball_speed - *t_.ball_speed) / kFitSpeedTolerance;
    if (t_.launch_angle) out.r[1] = (L.vertical_angle - *t_.launch_angle) / kFitAngleTolerance;
    if (t_.spin) out.r[2] = (L.spin.total - *t_.spin) / kFitSpinTolerance;
    for (const double x : out.r) out.cost += x * x;
    return out;
  }
  int evaluations = 0;

 private:
  ResolvedShot s_;
  std::string name_;
  FitTarget t_;
};

// The targets are launch numbers: their ranges are LaunchNumbers'.
KeySpec target_spec(std::string_view key) {
  KeySpec k;
  k.key = key;
  k.type = ValueType::Quantity;
  if (key == "ball_speed") {
    k.dim = Dimension::Speed;
    k.range = {&LaunchNumbers::kBallSpeed, nullptr, nullptr};
    k.unit = "mph";
  } else if (key == "launch_angle") {
    k.dim = Dimension::Angle;
    k.range = {&LaunchNumbers::kVerticalAngle, nullptr, nullptr};
    k.unit = "deg";
  } else {
    k.dim = Dimension::AngularVelocity;
    k.range = {&LaunchNumbers::kSpin, nullptr, nullptr};
    k.unit = "rpm";
  }
  return k;
}

}  // namespace

FitTarget parse_fit_target(std::string_view text) {
  FitTarget t;
  std::string_view rest = text;
  bool any = false;
  // Items are split at every comma, so "a,", ",a" and "a,,b" hold an empty item: refused
  // like any other malformed item rather than skipped.
  for (bool more = true; more;) {
    const auto comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    more = comma != std::string_view::npos;
    if (more) rest = rest.substr(comma + 1);
    if (item.empty() && !more && !any && text.empty()) break;
    const std::string origin = "--target " + std::string(item);
    if (item.empty())
      throw InputError("--target " + std::string(text) + ": an empty item (a stray comma); expected e.g. "
                       "ball_speed=167mph,launch_angle=10.9deg,spin=2686rpm");
    const auto eq = item.find('=');
    if (eq == std::string_view::npos) {
      throw InputError(origin + ": expected key=value; keys: ball_speed, launch_angle, spin");
    }
    const std::string_view key = item.substr(0, eq);
    if (key != "ball_speed" && key != "launch_angle" && key != "spin") {
      throw InputError(origin + ": unknown target '" + std::string(key) + "'; keys: ball_speed, launch_angle, spin");
    }
    const KeySpec spec = target_spec(key);
    const double v = check_value(spec, item.substr(eq + 1), RawKind::Text, "text", origin).number;
    auto& slot = key == "ball_speed" ? t.ball_speed : key == "launch_angle" ? t.launch_angle : t.spin;
    if (slot) throw InputError(origin + ": " + std::string(key) + " is given twice; give each target once");
    slot = v;
    any = true;
  }
  if (!any) throw InputError("--target: empty; expected e.g. ball_speed=167mph,launch_angle=10.9deg,spin=2686rpm");
  return t;
}

FitResult fit_e_mu(const Scenario& base, const FitTarget& target) {
  if (std::holds_alternative<LaunchStrike>(base.spec.strike))
    throw InputError(base.name + ": a launch-only scenario has no impact to fit");
  if (!target.ball_speed && !target.launch_angle && !target.spin) throw InputError("--target: nothing to fit");
  const double mu_max = ImpactMaterial::kMu.max;
  Objective f(base, target);

  // Coarse grid: the best point starts the local search away from grip/slip kinks.
  double e = 0.5, mu = 0.5 * mu_max;
  Eval best = f(e, mu);
  constexpr int kGrid = 20;
  for (int i = 0; i <= kGrid; ++i) {
    for (int j = 0; j <= kGrid; ++j) {
      const double ei = static_cast<double>(i) / kGrid;
      const double mj = mu_max * j / kGrid;
      Eval ev = f(ei, mj);
      if (ev.cost < best.cost) best = std::move(ev), e = ei, mu = mj;
    }
  }

  // A finer grid over the neighbouring cells: in the grip region µ has no effect, so the
  // slip side of the grip threshold is only found by looking there.
  const double e0 = e, mu0 = mu;
  for (int i = -kGrid / 2; i <= kGrid / 2; ++i) {
    for (int j = -kGrid / 2; j <= kGrid / 2; ++j) {
      const double ei = std::clamp(e0 + 2.0 * i / (kGrid * kGrid), 0.0, 1.0);
      const double mj = std::clamp(mu0 + 2.0 * mu_max * j / (kGrid * kGrid), 0.0, mu_max);
      Eval ev = f(ei, mj);
      if (ev.cost < best.cost) best = std::move(ev), e = ei, mu = mj;
    }
  }

  // Projected Levenberg–Marquardt with central-difference Jacobians.
  double lambda = 1e-3;
  for (int iter = 0; iter < 100 && best.cost > 1e-16; ++iter) {
    std::array<std::array<double, 2>, 3> J{};
    const double h[2] = {1e-5, 1e-5 * mu_max};
    for (int p = 0; p < 2; ++p) {
      const double x = p == 0 ? e : mu;
      const double hi_bound = p == 0 ? 1.0 : mu_max;
      const double xp = std::min(x + h[p], hi_bound), xm = std::max(x - h[p], 0.0);
      const Eval a = p == 0 ? f(xp, mu) : f(e, xp);
      const Eval b = p == 0 ? f(xm, mu) : f(e, xm);
      for (int k = 0; k < 3; ++k) J[k][p] = (a.r[k] - b.r[k]) / (xp - xm);
    }
    double A[2][2] = {{0, 0}, {0, 0}}, g[2] = {0, 0};
    for (int k = 0; k < 3; ++k) {
      for (int p = 0; p < 2; ++p) {
        g[p] += J[k][p] * best.r[k];
        for (int q = 0; q < 2; ++q) A[p][q] += J[k][p] * J[k][q];
      }
    }
    bool improved = false;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      const double a00 = A[0][0] * (1 + lambda) + 1e-12, a11 = A[1][1] * (1 + lambda) + 1e-12;
      const double det = a00 * a11 - A[0][1] * A[1][0];
      if (!(std::fabs(det) > 0)) break;
      const double de = -(a11 * g[0] - A[0][1] * g[1]) / det;
      const double dm = -(a00 * g[1] - A[1][0] * g[0]) / det;
      const double en = std::clamp(e + de, 0.0, 1.0), mn = std::clamp(mu + dm, 0.0, mu_max);
      Eval ev = f(en, mn);
      if (ev.cost < best.cost) {
        improved = true;
        const double step = std::fabs(en - e) + std::fabs(mn - mu) / mu_max;
        best = std::move(ev), e = en, mu = mn;
        lambda = std::max(lambda / 3.0, 1e-12);
        if (step < 1e-12) iter = 100;
      } else {
        lambda *= 4.0;
      }
    }
    if (!improved) break;
  }

  FitResult r;
  r.e = e;
  r.mu = mu;
  r.mu_max = mu_max;
  r.launch = best.shot.launch;
  r.contact = best.shot.impact.contact;
  if (r.contact == ContactKind::Grip && best.shot.impact.normal_impulse > 0.0) {
    r.mu_grip_threshold = best.shot.impact.tangential_impulse / best.shot.impact.normal_impulse;
  }
  if (target.ball_speed) r.ball_speed_residual = r.launch.ball_speed - *target.ball_speed;
  if (target.launch_angle) r.launch_angle_residual = r.launch.vertical_angle - *target.launch_angle;
  if (target.spin) r.spin_residual = r.launch.spin.total - *target.spin;
  r.reached = std::fabs(r.ball_speed_residual) <= kFitSpeedTolerance &&
              std::fabs(r.launch_angle_residual) <= kFitAngleTolerance && std::fabs(r.spin_residual) <= kFitSpinTolerance;
  r.evaluations = f.evaluations;
  return r;
}

}  // namespace sweetspot
