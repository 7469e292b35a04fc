// Work sharing: an atomic next-index counter hands grid points to worker threads; each
// writes only its own result slot, so no locks and a fixed output order.
#include "game/tuning/sweep.hpp"

#include "game/modes/lab/grip.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

#include "game/modes/lab/grip.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {
namespace {

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", std::fabs(v) < 1e-15 ? 0.0 : v);
  return buf;
}

}  // namespace

GridAxis parse_grid_axis(std::string_view text, std::string_view flag, const Range& allowed) {
  const double lo = allowed.min, hi = allowed.max;
  const std::string where = std::string(flag) + " " + std::string(text);
  char range[96];
  std::snprintf(range, sizeof range, "; expected A:B:N with %g <= A, B <= %g and 1 <= N <= %zu", lo, hi,
                kMaxSweepPoints);
  const auto c1 = text.find(':');
  const auto c2 = c1 == std::string_view::npos ? c1 : text.find(':', c1 + 1);
  if (c2 == std::string_view::npos) throw InputError(where + ": not of the form A:B:N" + range);
  auto number = [&](std::string_view s, const char* what) {
    try {
      return parse_quantity(s, Dimension::Dimensionless);
    } catch (const InputError& e) {
      throw InputError(where + ": " + what + ": " + e.what() + range);
    }
  };
  GridAxis g;
  g.from = number(text.substr(0, c1), "A");
  g.to = number(text.substr(c1 + 1, c2 - c1 - 1), "B");
  const std::string_view n = text.substr(c2 + 1);
  long long count = 0;
  const auto res = std::from_chars(n.data(), n.data() + n.size(), count);
  if (res.ec != std::errc() || res.ptr != n.data() + n.size()) {
    throw InputError(where + ": N must be a whole number" + range);
  }
  if (count < 1 || count > static_cast<long long>(kMaxSweepPoints)) {
    throw InputError(where + ": N = " + std::string(n) + " is out of range" + range);
  }
  g.count = static_cast<int>(count);
  if (g.count == 1 && g.from != g.to)
    throw InputError(where + ": N = 1 would run A alone and drop B; give N >= 2, or A:A:1 for one value");
  if (g.from < lo || g.from > hi || g.to < lo || g.to > hi) throw InputError(where + ": out of range" + range);
  return g;
}

std::vector<SweepPoint> run_sweep(const Scenario& base, const SweepOptions& o) {
  if (std::holds_alternative<LaunchStrike>(base.spec.strike)) {
    throw InputError(base.name + ": a launch-only scenario has no impact; e and mu would change nothing");
  }
  const std::size_t ne = static_cast<std::size_t>(o.e.count);
  const std::size_t nm = static_cast<std::size_t>(o.mu.count);
  const std::size_t total = ne * nm;
  if (total > kMaxSweepPoints) {
    throw InputError("sweep grid of " + std::to_string(ne) + " x " + std::to_string(nm) + " = " +
                     std::to_string(total) + " points exceeds the limit of " + std::to_string(kMaxSweepPoints));
  }
  std::vector<SweepPoint> out(total);
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  const RunOptions run{o.fly, false};

  auto worker = [&]() {
    ResolvedShot s = base.resolved;  // each thread edits its own copy
    for (std::size_t i = next.fetch_add(1); i < total && !failed.load(); i = next.fetch_add(1)) {
      SweepPoint& p = out[i];
      p.e = o.e.at(static_cast<int>(i / nm));
      p.mu = o.mu.at(static_cast<int>(i % nm));
      s.material.e = CorCurve::constant(p.e);
      s.material.mu = p.mu;
      try {
        p.shot = run_shot(s, base.name, run);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        failed.store(true);
      }
      done.fetch_add(1);
    }
  };

  int threads = o.threads > 0 ? o.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, static_cast<int>(std::max<std::size_t>(1, total)));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  if (o.progress) {
    // The calling thread reports progress while the pool works, then joins the work.
    pool.emplace_back(worker);
    while (done.load() < total && !failed.load()) {
      o.progress(done.load(), total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  } else {
    worker();
  }
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (o.grip) {
    // µ_grip depends on e (a livelier normal impulse needs less friction to stick) but not
    // on the µ being tried, so one search per row of the grid.
    ResolvedShot s = base.resolved;
    for (std::size_t ie = 0; ie < ne; ++ie) {
      s.material.e = CorCurve::constant(o.e.at(static_cast<int>(ie)));
      const double g = mu_grip(s);
      for (std::size_t im = 0; im < nm; ++im) out[ie * nm + im].shot.impact.mu_grip = g;
    }
  }
  if (o.progress) o.progress(total, total);
  return out;
}

std::string sweep_csv(const std::vector<SweepPoint>& points) {
  std::string out =
      "e,mu,ball_speed_mps,vertical_angle_deg,horizontal_angle_deg,spin_rpm,backspin_rpm,sidespin_rpm,"
      "spin_axis_deg,smash_factor,contact,mu_grip,grips,carry_m,total_m,apex_m,lateral_m,end\n";
  for (const auto& p : points) {
    const auto& L = p.shot.launch;
    const auto& F = p.shot.trajectory.summary;
    out += num(p.e) + "," + num(p.mu) + "," + num(L.ball_speed) + "," + num(rad_to_deg(L.vertical_angle)) + "," +
           num(rad_to_deg(L.horizontal_angle)) + "," + num(radps_to_rpm(L.spin.total)) + "," +
           num(radps_to_rpm(L.spin.backspin)) + "," + num(radps_to_rpm(L.spin.sidespin_right)) + "," +
           num(rad_to_deg(L.spin.axis_rad)) + "," + num(p.shot.smash_factor) + "," + to_string(p.shot.impact.contact) +
           "," + (p.shot.impact.mu_grip >= 0.0 ? num(p.shot.impact.mu_grip) : "") + "," +
           (p.shot.impact.mu_grip >= 0.0 ? (p.mu >= p.shot.impact.mu_grip ? "true" : "false") : "") + "," + num(F.carry_m) + "," + num(F.total_m) + "," + num(F.apex_m) + "," + num(F.lateral_m) + "," +
           to_string(p.shot.end) + "\n";
  }
  return out;
}

}  // namespace sweetspot
