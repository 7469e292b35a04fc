// `sweetspot play`: the game window (GLFW + Dear ImGui over the renderer) or, without a
// display, the same shot headless (launch-monitor table + an off-screen PNG).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "game/content/assets.hpp"
#include "game/content/course_file.hpp"

namespace sweetspot {

struct PlayOptions {
  std::string scenario = "golf/driver";   ///< built-in name or .toml path
  std::vector<std::string> overrides;     ///< `--set key=value` applied before the first shot
  int frames = 0;                         ///< window: run this many frames then exit (0 = until closed)
  std::string screenshot;                 ///< window: PNG of the last frame; headless: the shot's PNG
  int width = 1280, height = 800;         ///< px, window size
  /// "lab" (the shot and its tuning panels), "golf" (a round on `course`) or "baseball"
  /// (the batting cage); Tab cycles through them.
  std::string mode = "lab";
  std::string course = "national";       ///< golf: a course of assets/courses or a .toml
  std::string skill = "scratch";         ///< golf: the player's swing speed (and the bot opponent's skill)
  int holes = 0;                         ///< golf: play only the first N holes (0 = all)
  CourseSetup course_setup;              ///< golf: the tee set and pin set
  std::vector<std::string> bots;         ///< golf: the bot players' skills (empty: one of `skill`, unless humans join; "none": no bot)
  std::vector<std::string> humans;       ///< golf: more people at the same keys, by name (hot seat), after you
  std::string format = "stroke";         ///< golf: stroke, match, stableford, skins
  std::vector<int> handicaps;            ///< golf: course handicaps, yours first, then the bots' in order
  double gimme = -1.0;                   ///< golf: m; < 0 the format's default
  bool auto_putt = false;                ///< golf: your putts played by the physics with your skill
  std::string difficulty = "standard";   ///< golf: the meter's perfect window (easy, standard, pro)
  bool flyover = true;                   ///< golf: each hole opens with its flyover
  std::string bag;                       ///< golf: a bag file (range --bag-out) the caddie uses
  std::string resume;                    ///< golf: a saved round to go on with
  std::string save = "sweetspot_round.json";  ///< golf: where S saves the round
  bool metric = false;                   ///< golf: metres instead of yards and feet
  std::string shots_dir = ".";           ///< F12 screenshots go here
  bool exit_when_done = false;           ///< golf / baseball: close the window once the round or the pitches are done
  int pitches = 0;                       ///< baseball: pitches in the session (0 = until closed)
  bool mute = false;                     ///< window: no impact sound (no audio device is opened)
  /// window: the golf round's winds and bots' swings, the range caddie's swings and the
  /// cage's pitches. 0: a fresh draw for the session (printed, so it can be played again).
  std::uint64_t seed = 0;
  /// window: "auto" (the 3D view's resolution drops while frames run over budget; sun
  /// shadows on a GPU), "low" (as auto, never shadows), "high" (full resolution and shadows,
  /// whatever it costs).
  std::string quality = "auto";
};

/// Opens the window and runs until closed (or `frames`). Returns the exit code. Prints the
/// mean frame time on exit. Throws InputError for a bad scenario, std::runtime_error when
/// no window can be opened.
int run_play_window(const Assets& assets, const PlayOptions& options, std::ostream& out);
/// Refuses a --quality other than auto, low and high (InputError naming them).
void check_quality(const std::string& quality);

/// A window mode's frame time (ms): `mode` (lab: golf/driver with its panels; golf: the first
/// hole of Sweetspot National as it opens; range; baseball: the cage) at width x height,
/// vsync off, muted, the median of `frames` frames after 10 warm-up frames (shader compiles,
/// the first shot). What `bench` reports as frame_ms_window_*. Throws std::runtime_error when
/// no window can be opened (no display).
double measure_window_frame_ms(const Assets& assets, const std::string& mode, int width, int height, int frames);

/// Runs the shot without a window: prints the launch-monitor table and, when `screenshot`
/// names a file, writes a PNG of the shot there through EGL (nothing is written otherwise:
/// a command run in some folder must not leave files in it). Without EGL the table is
/// still printed and the PNG skipped with a note. Returns 0.
int run_play_headless(const Assets& assets, const PlayOptions& options, std::ostream& out);

}  // namespace sweetspot
