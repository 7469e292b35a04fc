// `sweetspot round [COURSE]`: play a course headless (DESIGN §9). A bot of the chosen skill
// plays every stroke, or a swings file scripts the meter inputs (the bot, when given, plays
// on after the file runs out). Stroke play prints the scorecard or the §9 JSON; `--mode ctp`
// plays N balls at the course's par 3 (closest to the pin), `--mode long-drive` N drives on
// its longest hole (longest in bounds). Same seed, same output, bit for bit.
#include <algorithm>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>

#include "game/cli/command.hpp"
#include "game/render/image.hpp"
#include "game/report/report.hpp"
#include "game/content/course_file.hpp"
#include "game/content/swings_file.hpp"
#include "game/modes/golf/bot.hpp"
#include "game/render/dispersion_plot.hpp"
#include "game/report/round_json.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"

namespace sweetspot::cli {
namespace {

struct RoundOptions {
  std::string course = "links";
  std::string bot;
  std::uint64_t seed = 1;
  std::string swings;
  std::string mode = "stroke";
  int balls = 5;
  bool json = false;
  std::string plot;
};

// The next stroke: from the script while it lasts, else the bot's.
std::optional<StrokeInput> next_stroke(const GolfRound& round, const std::vector<ScriptedStroke>& script, std::size_t& at,
                                       GolfBot* bot, const GolfBot& caddie) {
  if (at < script.size()) {
    const ScriptedStroke& s = script[at++];
    StrokeInput in;
    in.club = s.club ? *s.club : (round.lie() == "green" ? "putter" : caddie.suggest(round.to_pin(), round.teed()));
    in.meter = s.meter;
    in.aim = s.aim;
    return in;
  }
  if (bot != nullptr) return bot->plan(round);
  return std::nullopt;
}

int play_stroke_round(const Assets& assets, const RoundOptions& o) {
  const std::string skill = o.bot.empty() ? "tour" : o.bot;
  GolfRound round(assets, load_course(assets, o.course), golfer_skill(skill));
  std::vector<ScriptedStroke> script;
  if (!o.swings.empty()) script = load_swings(o.swings);
  GolfBot bot(assets, golfer_skill(skill), o.seed);
  GolfBot* player = o.swings.empty() || !o.bot.empty() ? &bot : nullptr;
  std::size_t at = 0;
  while (!round.finished()) {
    const std::optional<StrokeInput> in = next_stroke(round, script, at, player, bot);
    if (!in) break;
    try {
      round.play(*in);
    } catch (const InputError& e) {
      if (at > 0 && at <= script.size()) throw InputError(script[at - 1].where + ": " + e.what());
      throw;
    }
  }
  const std::string name = o.swings.empty() ? skill + " bot" : "swings " + o.swings;
  if (!o.plot.empty()) {
    std::vector<StrokeRecord> strokes;
    for (const HoleCard& h : round.card()) strokes.insert(strokes.end(), h.shots.begin(), h.shots.end());
    write_dispersion_plot(strokes, name, display_units(assets.sport("golf"), UnitSystem::Imperial), o.plot);
  }
  if (o.json) std::cout << json_text(round_json(round, name, o.seed)) << "\n";
  else std::cout << round_table(round, name);
  return 0;
}

// Closest to the pin (the course's shortest hole) or long drive (its longest): N balls from
// the tee, each a fresh one-hole round.
int play_contest(const Assets& assets, const RoundOptions& o) {
  const Course course = load_course(assets, o.course);
  const bool ctp = o.mode == "ctp";
  auto by_length = [](const CourseHole& a, const CourseHole& b) { return a.length() < b.length(); };
  const CourseHole hole = ctp ? *std::min_element(course.holes.begin(), course.holes.end(), by_length)
                              : *std::max_element(course.holes.begin(), course.holes.end(), by_length);
  Course one = course;
  one.holes = {hole};
  one.holes[0].number = 1;
  const std::string skill = o.bot.empty() ? "tour" : o.bot;
  GolfBot bot(assets, golfer_skill(skill), o.seed);
  nlohmann::json balls = nlohmann::json::array();
  double best = ctp ? 1e9 : 0.0;
  std::vector<StrokeRecord> contest_strokes;
  for (int i = 0; i < o.balls; ++i) {
    GolfRound round(assets, one, golfer_skill(skill));
    StrokeInput in = bot.plan(round);
    if (!ctp) in.club = "driver";
    const StrokeRecord& r = round.play(in);
    contest_strokes.push_back(r);
    const bool in_play = r.end == StrokeEnd::Rest || r.end == StrokeEnd::Holed;
    const double line = std::atan2(hole.pin.z() - hole.tee.z(), hole.pin.x() - hole.tee.x());
    const double along = (r.rest.x() - hole.tee.x()) * std::cos(line) + (r.rest.z() - hole.tee.z()) * std::sin(line);
    const double value = ctp ? r.to_pin_m : along;
    if (in_play) best = ctp ? std::min(best, value) : std::max(best, value);
    balls.push_back({{"club", r.club}, {"end", to_string(r.end)}, {ctp ? "to_pin_m" : "distance_m", value}, {"in_play", in_play}});
  }
  nlohmann::json j = {{"mode", o.mode}, {"course", course.name}, {"hole", hole.world_name}, {"player", skill + " bot"},
                      {"seed", o.seed}, {"balls", balls}};
  if ((ctp && best < 1e9) || (!ctp && best > 0.0)) j[ctp ? "best_to_pin_m" : "best_distance_m"] = best;
  if (!o.plot.empty())
    write_dispersion_plot(contest_strokes, std::string(ctp ? "closest to the pin, " : "long drive, ") + skill + " bot",
                          display_units(assets.sport("golf"), UnitSystem::Imperial), o.plot);
  if (o.json) {
    std::cout << json_text(j) << "\n";
  } else {
    std::cout << (ctp ? "closest to the pin" : "long drive") << " on " << course.name << " (" << hole.world_name
              << "), " << skill << " bot\n";
    for (const auto& b : balls)
      std::cout << "  " << b["club"].get<std::string>() << "  " << b["end"].get<std::string>() << "  "
                << b[ctp ? "to_pin_m" : "distance_m"].get<double>() << " m\n";
    if (j.contains(ctp ? "best_to_pin_m" : "best_distance_m"))
      std::cout << "best: " << j[ctp ? "best_to_pin_m" : "best_distance_m"].get<double>() << " m\n";
  }
  return 0;
}

RunFn setup_round(CLI::App& sub) {
  auto o = std::make_shared<RoundOptions>();
  sub.add_option("course", o->course, "a course of assets/courses (default links) or a .toml file");
  sub.add_option("--bot", o->bot, "golfer skill: tour, scratch, amateur or beginner (default tour)");
  sub.add_option("--seed", o->seed, "seed of the bot's swing errors, 0..18446744073709551615 (default 1)")->check(kSeedText);
  sub.add_option("--swings", o->swings, "scripted meter inputs, one [[stroke]] per stroke (TOML)");
  sub.add_option("--mode", o->mode, "stroke (default), ctp (closest to the pin) or long-drive");
  auto* balls = sub.add_option("--balls", o->balls, "balls for ctp and long-drive, 1..100 (default 5)");
  sub.add_flag("--json", o->json, "print the DESIGN §9 JSON");
  sub.add_option("--plot", o->plot, "also write the session's dispersion (carry vs side per club) to FILE.png");
  return [o, balls](const Assets& assets) -> int {
    if (o->mode != "stroke" && o->mode != "ctp" && o->mode != "long-drive")
      throw InputError("--mode " + o->mode + ": unknown mode (allowed: stroke, ctp, long-drive)");
    if (!o->swings.empty() && o->mode != "stroke")
      throw InputError("--swings: scripted strokes play a stroke round; --mode " + o->mode + " is the bot's");
    if (balls->count() > 0 && o->mode == "stroke")
      throw InputError("--balls: a stroke round plays one ball to each cup; --balls is for --mode ctp or long-drive");
    if (!o->plot.empty()) check_png_output(o->plot, "--plot");
    if (o->balls < 1 || o->balls > 100) throw InputError("--balls " + std::to_string(o->balls) + " is out of range (allowed [1, 100])");
    if (!o->bot.empty()) golfer_skill(o->bot);  // refuse an unknown skill before any work
    if (!o->plot.empty() && !o->swings.empty()) refuse_output_over_input(o->plot, o->swings, "--plot");
    return o->mode == "stroke" ? play_stroke_round(assets, *o) : play_contest(assets, *o);
  };
}

const CommandRegistrar reg{35, "round", "play a golf course headless: a bot or scripted swings, scorecard or §9 JSON",
                           setup_round};

}  // namespace
}  // namespace sweetspot::cli
