// `sweetspot play [SCENARIO]`: the game window, or the shot headless when there is no display.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "game/app/mode_registry.hpp"
#include "game/app/play_app.hpp"
#include "game/cli/command.hpp"
#include "game/render/image.hpp"
#include "game/app/display.hpp"
#include "game/content/bag_file.hpp"
#include "game/content/settings_file.hpp"
#include "game/modes/golf/golfer.hpp"
#include "game/modes/golf/golf_group.hpp"
#include "game/modes/golf/meter_clock.hpp"
#include "game/report/round_save.hpp"
#include "game/util/atomic_file.hpp"
#include "game/util/terminal_text.hpp"
#include "physics/error.hpp"

namespace sweetspot::cli {
namespace {

RunFn setup_play(CLI::App& sub) {
  auto o = std::make_shared<PlayOptions>();
  sub.add_option("scenario", o->scenario, "built-in scenario name or .toml path")->capture_default_str();
  sub.add_option("--set", o->overrides, "override a scenario key, e.g. swing.speed=105mph (repeatable)");
  sub.add_option("--frames", o->frames, "run N frames then exit (automation)")->check(int_range<int>(1, 1000000));
  sub.add_option("--screenshot", o->screenshot, "save the last frame to FILE.png (headless: the shot's image)");
  sub.add_option("--width", o->width, "window width in px")->check(int_range<int>(640, 7680))->capture_default_str();
  sub.add_option("--height", o->height, "window height in px")->check(int_range<int>(480, 4320))->capture_default_str();
  std::vector<const CLI::Option*> window_only;
  window_only.push_back(sub.add_option("--mode", o->mode, "lab (the shot and its tuning), golf (a round on --course), range (bag gapping) or baseball (the batting cage); Tab switches")
      ->capture_default_str());
  window_only.push_back(sub.add_option("--course", o->course, "golf: a course of assets/courses, a .toml, or a directory from course import")->capture_default_str());
  window_only.push_back(sub.add_option("--skill", o->skill, "golf: tour, scratch, amateur or beginner (swing speed; the bot opponent)")
      ->capture_default_str());
  window_only.push_back(sub.add_option("--holes", o->holes, "golf: play only the first N holes")->check(int_range<int>(1, 18)));
  window_only.push_back(sub.add_option("--tees", o->course_setup.tees, "golf: the tee set to play from, as the course names them (default: each hole's own tee)"));
  o->course_setup.pin_set = CourseSetup::kDayPinSet;
  window_only.push_back(sub.add_option("--pins", o->course_setup.pin_set, "golf: the pin set, 0..9 (default 0, a mix: the holes take their sets in turn)")->check(int_range<int>(0, 9)));
  window_only.push_back(sub.add_option("--bot", o->bots, "golf: a bot player of this skill, repeat for up to 3 (default one of --skill; none: alone)"));
  window_only.push_back(sub.add_option("--format", o->format, "golf: stroke (default), match (one bot), stableford or skins"));
  window_only.push_back(sub.add_option("--human", o->humans, "golf: a friend at the same keys (hot seat), by name; repeat for up to 3"));
  window_only.push_back(sub.add_option("--handicap", o->handicaps, "golf: course handicaps 0..54, yours first, then each friend's (--human) and each bot's"));
  window_only.push_back(sub.add_option("--gimme", o->gimme, "golf: putts this close (m) are conceded, 0..3 (default 0.6 in match play, else off)")
      ->check(finite_range(GolfOptions::kGimme.min, GolfOptions::kGimme.max)));
  window_only.push_back(sub.add_flag("--auto-putt", o->auto_putt, "golf: your putts are played for you, with your skill"));
  window_only.push_back(sub.add_option("--difficulty", o->difficulty, "golf: the meter's perfect window: easy (25 ms), standard (10 ms, default), pro (0); baseball: the pitch's pace, easy 0.3 of real time, standard 0.5, pro real time"));
  window_only.push_back(sub.add_flag("--no-flyover", [o](std::int64_t) { o->flyover = false; }, "golf: no flyover as a hole opens"));
  window_only.push_back(sub.add_option("--bag", o->bag, "golf: your measured bag (range --bag-out) for your caddie and map"));
  window_only.push_back(sub.add_option("--resume", o->resume, "golf: go on with a round saved with S"));
  window_only.push_back(sub.add_option("--save", o->save, "golf: where S saves the round (default sweetspot_round.json)"));
  window_only.push_back(sub.add_flag("--metric", o->metric, "golf: metres (default yards and feet; U switches in play)"));
  window_only.push_back(sub.add_option("--quality", o->quality, "auto (the 3D view's resolution drops to keep frames under 20 ms; sun shadows on a GPU), low (never shadows) or high (full resolution and shadows)")->capture_default_str());
  window_only.push_back(sub.add_flag("--mute", o->mute, "no impact sound (without an audio device the game is silent anyway)"));
  window_only.push_back(sub.add_option("--shots-dir", o->shots_dir, "where F12 writes its screenshots (default: here)"));
  window_only.push_back(sub.add_flag("--exit-when-done", o->exit_when_done, "golf, baseball: close once the round or the pitches are done (automation)"));
  window_only.push_back(sub.add_option("--pitches", o->pitches, "baseball: pitches in the session")->check(int_range<int>(1, 1000)));
  window_only.push_back(sub.add_option("--seed", o->seed, "the session's winds, bot and caddie swings and pitches, 1..2^64-1 (default: a fresh draw, printed)")
      ->check(int_range<std::uint64_t>(1, std::numeric_limits<std::uint64_t>::max())));
  // The save holds the round's course, players, format and options: a flag that would set one
  // of them again is refused with --resume, not silently dropped.
  std::vector<const CLI::Option*> set_by_save;
  for (const char* name : {"--course", "--holes", "--tees", "--pins", "--bot", "--format", "--human", "--handicap", "--gimme",
                           "--auto-putt", "--bag"})
    set_by_save.push_back(sub.get_option(name));
  std::vector<const CLI::Option*> course_options;
  for (const char* name : {"--course", "--tees", "--pins", "--holes"}) course_options.push_back(sub.get_option(name));
  return [o, window_only, set_by_save, course_options](const Assets& assets) -> int {
    check_play_mode(assets, *o);  // first: an unknown mode is that, with or without a display
    if (!o->screenshot.empty()) check_png_output(o->screenshot, "--screenshot");  // before the frames run
    // The golf options are checked now, not when Tab first opens the golf mode.
    // Each refusal names the flag it came from.
    const auto as_flag = [](const char* flag, const auto& check) {
      try {
        check();
      } catch (const InputError& e) {
        throw InputError(std::string(flag) + ": " + e.what());
      }
    };
    check_quality(o->quality);
    // A course, tee set or pin set that is not there is named now, not when golf opens.
    if (o->resume.empty() && std::any_of(course_options.begin(), course_options.end(), [](const CLI::Option* c) { return c->count() > 0; }))
      check_play_course(assets, *o);
    as_flag("--format", [&] { golf_format(o->format); });
    as_flag("--difficulty", [&] { meter_difficulty(o->difficulty); });
    as_flag("--skill", [&] { golfer_skill(o->skill); });
    for (const std::string& b : o->bots)
      if (b != "none") as_flag("--bot", [&] { golfer_skill(b); });
    std::size_t others = o->humans.size();
    for (const std::string& b : o->bots) others += b != "none";
    if (o->bots.empty() && o->humans.empty()) others = 1;  // the default bot
    if (others > 3) throw InputError("--bot/--human: a round has at most 4 players (you and 3 more)");
    if (o->format == "match" && others != 1)
      throw InputError("--format match: match play is between two (you and one --bot or --human)");
    if (o->format == "skins" && others < 1)
      throw InputError("--format skins: skins is played by 2 to 4 (you and at least one --bot or --human)");
    for (const std::string& h : o->humans)
      if (const std::string why = name_problem(h, 24); !why.empty())
        throw InputError("--human '" + terminal_safe(h.substr(0, 60)) + "': " + why + " (a name of 1 to 24 characters)");
    if (o->handicaps.size() > 1 + others)
      throw InputError("--handicap: " + std::to_string(o->handicaps.size()) + " given for " + std::to_string(1 + others) +
                       (others == 0 ? " player (yours)" : " players (yours first, then each friend's and each bot's)"));
    for (const int hc : o->handicaps)
      if (hc < 0 || hc > kMaxHandicap) throw InputError("--handicap " + std::to_string(hc) + " is out of range (allowed [0, 54])");
    // Where S and F12 write is checked now, not when the player presses them mid-round.
    if (!o->save.empty()) check_output_path(o->save, "--save");
    if (std::error_code ec; !o->shots_dir.empty() && !std::filesystem::is_directory(o->shots_dir, ec))
      throw InputError("--shots-dir " + o->shots_dir + ": no such folder");
    if (!o->resume.empty())
      for (const CLI::Option* opt : set_by_save)
        if (opt->count() > 0)
          throw InputError("--resume: the saved round sets its course, players, format and options; " + opt->get_name() +
                           " cannot change them");
    // The range writes the bag (S): there the file may not exist yet.
    if (!o->bag.empty() && (o->mode != "range" || std::filesystem::exists(o->bag))) load_bag(assets, o->bag, golfer_skill_names());
    if (!o->resume.empty()) resume_round(assets, read_round_save(o->resume));  // its turns replay, or it is named now
    load_settings(settings_path());  // a bad settings file is named now, not when golf opens
    std::string why;
    // Headless plays the lab's one shot: the game modes' options would be ignored, so
    // they are refused (--frames and --screenshot have a headless meaning).
    const auto refuse_window_options = [&](const std::string& reason) {
      for (const CLI::Option* opt : window_only)
        if (opt->count() > 0) throw InputError(opt->get_name() + " needs the game window, and " + reason);
    };
    if (!display_available(&why)) {
      refuse_window_options(why);
      std::cerr << "sweetspot play: " << why << "; running " << o->scenario << " headless.\n";
      return run_play_headless(assets, *o, std::cout);
    }
    try {
      return run_play_window(assets, *o, std::cout);
    } catch (const InputError&) {
      throw;
    } catch (const std::runtime_error& e) {
      // A display was named but no GL window opened (e.g. a stale DISPLAY): fall back.
      refuse_window_options(e.what());
      std::cerr << "sweetspot play: " << e.what() << "; running " << o->scenario << " headless.\n";
      return run_play_headless(assets, *o, std::cout);
    }
  };
}

const CommandRegistrar play_command{10, "play", "play a shot scenario in a window (headless without a display)", setup_play};

}  // namespace
}  // namespace sweetspot::cli
