// `sweetspot bench [--json] [--quick]`: throughput figures (DESIGN §8) as one JSON object
// or a table. Each figure is one row of `measurements`; further benchmarks add rows.
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/bench/impact_bench.hpp"
#include "game/bench/mode_bench.hpp"
#include "game/bench/shot_bench.hpp"
#include "game/bench/sweep_bench.hpp"
#include "game/render/render_command.hpp"
#include "game/render/render_error.hpp"
#include "game/app/connect_app.hpp"
#include "game/app/play_app.hpp"
#include "game/cli/command.hpp"
#include "game/report/report.hpp"

namespace sweetspot::cli {
namespace {

struct BenchOptions {
  bool json = false;
  bool quick = false;
};

struct Measurement {
  std::string key;    ///< JSON key, SI-style suffix ("impact_solves_per_s")
  double value;
  std::string label;  ///< table text
};

RunFn setup_bench(CLI::App& sub) {
  auto opts = std::make_shared<BenchOptions>();
  sub.add_flag("--json", opts->json, "print one JSON object");
  sub.add_flag("--quick", opts->quick, "short timing runs (tests, smoke checks)");
  return [opts](const Assets& assets) -> int {
    const double seconds = opts->quick ? 0.05 : 1.0;
    std::vector<Measurement> rows;
    rows.push_back({"impact_solves_per_s", measure_impact_solves_per_s(assets.equipment(), seconds), "impact solves/s (one core)"});

    // Whole shots, launch to rest on the asset worlds, and the same tour launches through
    // the Bullet-dynamics baseline, all measured in this run.
    const bench::ShotBenchResult golf = bench::bench_golf_shots(assets, seconds);
    const bench::ShotBenchResult golf_gjk = bench::bench_golf_shots(assets, seconds, SweepMethod::BulletConvexSweep);
    const bench::ShotBenchResult baseball = bench::bench_baseball_shots(assets, seconds);
    const bench::ShotBenchResult baseline = bench::bench_baseline_golf_shots(assets, seconds);
    const bench::CarryErrors carry = bench::golf_carry_errors(assets);
    const bench::ShotBenchResult flat = bench::bench_golf_shots_flat(assets, seconds);
    const bench::ShotBenchResult tight = bench::bench_golf_shots_tight(assets, seconds);
    const bench::ShotBenchResult course = bench::bench_course_shots(assets, seconds);
    rows.push_back({"golf_shots_per_s", golf.shots_per_second, "golf shots/s (tour driver/7-iron/PW, to rest)"});
    rows.push_back({"golf_us_per_shot", golf.us_per_shot, "us per golf shot (golf_hole)"});
    rows.push_back({"golf_us_per_shot_flat", flat.us_per_shot, "us per golf shot (flat ground, no world)"});
    rows.push_back({"terrain_cost_ratio", golf.us_per_shot / flat.us_per_shot, "golf_hole / flat ground time"});
    rows.push_back({"course_us_per_shot", course.us_per_shot, "us per golf shot (imported National)"});
    rows.push_back({"course_cost_ratio", course.us_per_shot / golf.us_per_shot, "Sweetspot National / golf_hole time"});
    rows.push_back({"golf_us_per_shot_tight", tight.us_per_shot, "us per golf shot, reference tolerance 1e-13"});
    rows.push_back({"tolerance_speedup", tight.us_per_shot / golf.us_per_shot, "speed-up of the default tolerances"});
    rows.push_back({"golf_shots_per_s_convex_sweep", golf_gjk.shots_per_second,
                    "golf shots/s, Bullet convexSweepTest narrow phase"});
    rows.push_back({"exact_sweep_speedup", golf.shots_per_second / golf_gjk.shots_per_second,
                    "speed-up of the exact sweep over convexSweepTest"});
    rows.push_back({"baseball_shots_per_s", baseball.shots_per_second, "baseball shots/s (ballpark)"});
    rows.push_back({"baseline_golf_shots_per_s", baseline.shots_per_second, "baseline golf shots/s (Bullet 240 Hz)"});
    rows.push_back({"speedup_vs_baseline", golf.shots_per_second / baseline.shots_per_second, "speed-up vs baseline"});
    rows.push_back({"carry_error_m", carry.ours_error_m, "carry error, ours, worst of the set (m)"});
    rows.push_back({"baseline_carry_error_m", carry.baseline_error_m, "carry error, baseline, worst of the set (m)"});
    for (const bench::CarryError& c : carry.shots) {
      const std::string n = c.name;
      rows.push_back({"reference_carry_m_" + n, c.reference_m, "  " + n + " reference carry (m)"});
      rows.push_back({"carry_error_m_" + n, c.ours_error_m, "  " + n + " carry error, ours (m)"});
      rows.push_back({"baseline_carry_error_m_" + n, c.baseline_error_m, "  " + n + " carry error, baseline (m)"});
    }

    // Game modes: what a player waits for while the bots play.
    rows.push_back({"bot_round_ms", bench::bench_bot_round_ms(assets, opts->quick ? 1 : 5), "ms per bot round of the links (tour bot)"});
    rows.push_back({"derby_ms", bench::bench_derby_ms(assets, opts->quick ? 1 : 5), "ms per home-run derby (pro bot, 10 outs)"});
    const bench::GameBench game = bench::bench_game(assets, opts->quick ? 1 : 3);
    rows.push_back({"game_ms", game.ms_per_game, "ms per nine-inning bot game (pro lineups, the league's pitcher)"});
    rows.push_back({"game_us_per_pitch", game.us_per_pitch, "  us per pitch of those games (comparable across rule changes)"});

    const int axis = opts->quick ? 6 : 60;
    const SweepThroughput s1 = measure_sweep(assets, 1, axis);
    const SweepThroughput s2 = measure_sweep(assets, 2, axis);
    rows.push_back({"sweep_shots_per_s_1_thread", s1.shots_per_s, "sweep shots/s, 1 thread"});
    rows.push_back({"sweep_shots_per_s_2_threads", s2.shots_per_s, "sweep shots/s, 2 threads"});
    rows.push_back({"sweep_scaling_2_threads", s2.shots_per_s / s1.shots_per_s, "sweep speed-up, 2 vs 1 thread"});

    // The frame: EGL off-screen (llvmpipe without a GPU). Absent without EGL, not an error.
    std::string frame_note;
    try {
      rows.push_back({"frame_ms_1280x720", measure_frame_ms(assets, 1280, 720, opts->quick ? 3 : 20), "ms per 1280x720 off-screen frame"});
      // The sun's shadow map forced on (auto leaves it off on a software rasteriser): its cost.
      rows.push_back({"frame_ms_1280x720_shadows", measure_frame_ms(assets, 1280, 720, opts->quick ? 3 : 20, 1),
                      "ms per 1280x720 off-screen frame with sun shadows"});
    } catch (const RenderUnavailable& e) {
      frame_note = e.what();
    }
    // The game window with its panels (the budget: <= 16 ms under Xvfb + llvmpipe). Needs a
    // display: `xvfb-run sweetspot bench`; without one the figure is absent, not an error.
    std::string window_note;
    try {
      const int n = opts->quick ? 10 : 60;
      rows.push_back({"frame_ms_window_1280x800", measure_window_frame_ms(assets, "lab", 1280, 800, n),
                      "ms per 1280x800 window frame with the lab panels (median)"});
      rows.push_back({"frame_ms_window_golf_1280x800", measure_window_frame_ms(assets, "golf", 1280, 800, n),
                      "ms per 1280x800 golf window frame, National hole 1 (median)"});
      rows.push_back({"frame_ms_window_range_1280x800", measure_window_frame_ms(assets, "range", 1280, 800, n),
                      "ms per 1280x800 range window frame (median)"});
      rows.push_back({"frame_ms_window_cage_1280x800", measure_window_frame_ms(assets, "baseball", 1280, 800, n),
                      "ms per 1280x800 batting-cage window frame (median)"});
      rows.push_back({"frame_ms_window_connect_1280x800", measure_connect_frame_ms(assets, 1280, 800, n),
                      "ms per 1280x800 launch-monitor window frame (median)"});
    } catch (const std::exception& e) {
      window_note = e.what();
    }

    if (opts->json) {
      nlohmann::json j = nlohmann::json::object();
      for (const auto& r : rows) j[r.key] = r.value;
      j["quick"] = opts->quick;
      if (!frame_note.empty()) j["frame_ms_1280x720"] = j["frame_ms_1280x720_shadows"] = nullptr, j["frame_note"] = frame_note;
      if (!window_note.empty()) {
        for (const char* k : {"frame_ms_window_1280x800", "frame_ms_window_golf_1280x800", "frame_ms_window_range_1280x800",
                              "frame_ms_window_cage_1280x800", "frame_ms_window_connect_1280x800"})
          if (!j.contains(k)) j[k] = nullptr;
        j["window_note"] = window_note;
      }
      std::cout << json_text(j) << "\n";
    } else {
      for (const auto& r : rows) {
        std::cout << std::left << std::setw(52) << r.label << std::right << std::setprecision(4) << r.value << "\n";
      }
      if (!frame_note.empty()) std::cout << "frame: not measured (" << frame_note << ")\n";
      if (!window_note.empty()) std::cout << "window frame: not measured (" << window_note << ")\n";
    }
    return 0;
  };
}

const CommandRegistrar bench_command{80, "bench", "measure throughput (impact solves/s, ...)", setup_bench};

}  // namespace
}  // namespace sweetspot::cli
