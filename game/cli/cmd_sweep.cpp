// `sweetspot sweep SCENARIO --e A:B:N --mu A:B:N [--csv FILE] [--threads N] [--units U]`: the e × µ
// grid on all cores. Without --csv a table goes to stdout; with it the CSV is written
// atomically (no partial file on any error). Progress goes to stderr only on a terminal.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/render/image.hpp"
#include "game/content/scenario.hpp"
#include "game/content/scenario_schema.hpp"
#include "game/render/sweep_plot.hpp"
#include "game/report/metrics.hpp"
#include "game/report/report.hpp"
#include "game/tuning/sweep.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/units.hpp"

namespace sweetspot::cli {
namespace {

struct SweepCliOptions {
  std::string scenario, e, mu, csv;
  std::string units = "imperial";
  std::string plot;
  std::vector<std::string> sets;
  int threads = 0;
  bool no_flight = false;
};

RunFn setup_sweep(CLI::App& sub) {
  auto o = std::make_shared<SweepCliOptions>();
  sub.add_option("scenario", o->scenario, "built-in name or .toml file")->required();
  sub.add_option("--e", o->e, "restitution grid A:B:N (0 <= A, B <= 1)")->required();
  sub.add_option("--mu", o->mu, "friction grid A:B:N (0 <= A, B <= 2)")->required();
  sub.add_option("--csv", o->csv, "write the grid as CSV to FILE (atomically)");
  sub.add_option("--set", o->sets, "override a scenario key: key=value")->type_name("KEY=VALUE");
  sub.add_option("--threads", o->threads, "worker threads (default: all cores)")->check(int_range<int>(1, 1024));
  sub.add_flag("--no-flight", o->no_flight, "launch numbers only, skip the flight (faster)");
  sub.add_option("--plot", o->plot,
                 "also write a PNG image to FILE (name it .png): heatmaps of ball speed, spin and carry over the grid with the grip boundary, "
                 "and the landing dispersion");
  sub.add_option("--units", o->units, "display units of the table: imperial or metric (the CSV is SI)")
      ->capture_default_str();
  return [o](const Assets& assets) -> int {
    const UnitSystem system = parse_unit_system(o->units);
    SweepOptions so;
    so.e = parse_grid_axis(o->e, "--e", ImpactMaterial::kE);
    so.mu = parse_grid_axis(o->mu, "--mu", ImpactMaterial::kMu);
    so.threads = o->threads;
    so.fly = !o->no_flight;
    const std::size_t points = static_cast<std::size_t>(so.e.count) * static_cast<std::size_t>(so.mu.count);
    if (points > kMaxSweepPoints) {
      throw InputError("--e " + o->e + " --mu " + o->mu + ": " + std::to_string(points) +
                       " grid points exceed the limit of " + std::to_string(kMaxSweepPoints));
    }
    if (!o->csv.empty()) check_output_path(o->csv, "--csv");
    if (!o->plot.empty()) check_png_output(o->plot, "--plot");
    if (!o->csv.empty()) refuse_output_over_input(o->csv, resolve_scenario(assets, o->scenario), "--csv");
    if (!o->plot.empty()) refuse_output_over_input(o->plot, resolve_scenario(assets, o->scenario), "--plot");
    if (!o->csv.empty() && !o->plot.empty() && same_output_file(o->csv, o->plot))
      throw InputError("--csv " + o->csv + " --plot " + o->plot + ": the CSV and the plot would overwrite each other");
    // The grid sets e and mu: a --set of either would be overwritten without a word.
    for (const auto& set : o->sets)
      if (const std::string key = set_key(set); key == "impact.e" || key == "impact.mu")
        throw InputError("--set " + set + ": the sweep's grid (--e / --mu) sets this value; leave the --set out");
    const Scenario base = load_scenario(assets, o->scenario, o->sets);
    if (base.resolved.material.friction == FrictionModel::None && so.mu.count > 1)
      throw InputError("--mu " + o->mu + ": the impact's friction model is none, so mu changes nothing; "
                       "sweep --mu A:A:1 or pick a friction model (--set impact.friction=coulomb)");
    if (::isatty(STDERR_FILENO) != 0) {
      so.progress = [](std::size_t done, std::size_t total) {
        std::fprintf(stderr, "\rsweep: %zu/%zu points", done, total);
        if (done == total) std::fprintf(stderr, "\n");
        std::fflush(stderr);
      };
    }
    const auto t0 = std::chrono::steady_clock::now();
    const auto result = run_sweep(base, so);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const DisplayUnits u = display_units(*base.resolved.sport, system);
    if (!o->plot.empty()) {
      write_sweep_plot(result, so, u, o->scenario, o->plot);
      std::cerr << "sweep: heatmaps written to " << o->plot << "\n";
    }
    if (!o->csv.empty()) {
      write_file_atomic(o->csv, sweep_csv(result));
      std::cout << "sweep: " << result.size() << " points of " << o->scenario << " written to " << o->csv << " in "
                << seconds << " s\n";
      return 0;
    }
    // One unit per quantity, named in the header: speed and distance follow --units (the
    // sport's distance unit in imperial), angles in degrees, spin in rpm. "cont" is the
    // solver's contact (grip: the patch stuck at some time); "mu_eff" says whether µ still
    // acts here: "live" below the row's µ_grip, "none" above it (the launch stops changing).
    const std::string speed_head = std::string("ball ") + u.speed_unit();
    const std::string carry_head = std::string("carry ") + u.distance_unit();
    std::printf("%-7s %-7s %10s %10s %9s %9s %-5s %-6s %7s %10s\n", "e", "mu", speed_head.c_str(), "launch deg",
                "spin rpm", "axis deg", "cont", "mu_eff", "mu_grip", carry_head.c_str());
    for (const auto& p : result) {
      const auto& L = p.shot.launch;
      char carry[32] = "         -";  // --no-flight: not computed
      if (so.fly) std::snprintf(carry, sizeof carry, "%10.2f", u.dist(p.shot.trajectory.summary.carry_m));
      const double g = p.shot.impact.mu_grip;
      std::printf("%-7.4g %-7.4g %10.2f %10.2f %9.0f %9.2f %-5s %-6s %7.3f %s\n", p.e, p.mu, u.speed(L.ball_speed),
                  rad_to_deg(L.vertical_angle), radps_to_rpm(L.spin.total), rad_to_deg(L.spin.axis_rad),
                  to_string(p.shot.impact.contact), p.mu >= g ? "none" : "live", g, carry);
    }
    return 0;
  };
}

const CommandRegistrar sweep_command{41, "sweep", "run the e x mu grid of a scenario on all cores", setup_sweep};

}  // namespace
}  // namespace sweetspot::cli
