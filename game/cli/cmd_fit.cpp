// `sweetspot fit SCENARIO --target ball_speed=Q,launch_angle=Q,spin=Q`: solve e and µ.
// Exit 0 when the target is reached within launch-monitor precision, 1 when it cannot be.
#include <cstdio>
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/content/scenario_doc.hpp"
#include "game/tuning/fit.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot::cli {
namespace {

struct FitOptions {
  std::string scenario, target;
  std::vector<std::string> sets;
};

RunFn setup_fit(CLI::App& sub) {
  auto o = std::make_shared<FitOptions>();
  sub.add_option("scenario", o->scenario, "built-in name or .toml file")->required();
  sub.add_option("--target", o->target, "measured launch: ball_speed=Q,launch_angle=Q,spin=Q (any subset)")
      ->required();
  sub.add_option("--set", o->sets, "override a scenario key: key=value")->type_name("KEY=VALUE");
  return [o](const Assets& assets) -> int {
    const FitTarget t = parse_fit_target(o->target);
    // The fit solves e and mu: a --set of either would be overwritten without a word.
    for (const auto& set : o->sets)
      if (const std::string key = set_key(set); key == "impact.e" || key == "impact.mu")
        throw InputError("--set " + set + ": the fit solves this value; leave the --set out");
    const Scenario s = load_scenario(assets, o->scenario, o->sets);
    const FitResult r = fit_e_mu(s, t);
    std::printf("fit %s: e = %.4f, mu = %.4f  (%s, %d deliveries solved)\n", o->scenario.c_str(), r.e, r.mu,
                to_string(r.contact), r.evaluations);
    if (r.contact == ContactKind::Grip) {
      std::printf("  the contact grips: any mu >= %.4f gives the same launch\n", r.mu_grip_threshold);
    }
    std::printf("  %-13s %12s %12s %12s %10s\n", "quantity", "target", "got", "residual", "allowed");
    if (t.ball_speed) {
      std::printf("  %-13s %8.2f mph %8.2f mph %8.2f mph %6.2f mph\n", "ball_speed", mps_to_mph(*t.ball_speed),
                  mps_to_mph(r.launch.ball_speed), mps_to_mph(r.ball_speed_residual), mps_to_mph(kFitSpeedTolerance));
    }
    if (t.launch_angle) {
      std::printf("  %-13s %8.2f deg %8.2f deg %8.2f deg %6.2f deg\n", "launch_angle", rad_to_deg(*t.launch_angle),
                  rad_to_deg(r.launch.vertical_angle), rad_to_deg(r.launch_angle_residual),
                  rad_to_deg(kFitAngleTolerance));
    }
    if (t.spin) {
      std::printf("  %-13s %8.0f rpm %8.0f rpm %8.0f rpm %6.0f rpm\n", "spin", radps_to_rpm(*t.spin),
                  radps_to_rpm(r.launch.spin.total), radps_to_rpm(r.spin_residual), radps_to_rpm(kFitSpinTolerance));
    }
    if (r.reached) {
      std::printf("target reached\n");
      return 0;
    }
    std::printf("target cannot be reached with e in [0, 1] and mu in [0, %g] for this delivery; the best fit is shown\n",
                r.mu_max);
    return 1;
  };
}

const CommandRegistrar fit_command{50, "fit", "solve e and mu that reproduce measured launch numbers", setup_fit};

}  // namespace
}  // namespace sweetspot::cli
