// `sweetspot round [COURSE]`: play a course headless (DESIGN §9). A bot of the chosen skill
// plays every stroke, or a swings file scripts the meter inputs (the bot, when given, plays
// on after the file runs out). Stroke play prints the scorecard or the §9 JSON; `--mode ctp`
// plays N balls at the course's par 3 (closest to the pin), `--mode long-drive` N drives on
// its longest hole (longest in bounds). Same seed, same output, bit for bit.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "game/cli/command.hpp"
#include "game/render/image.hpp"
#include "game/report/report.hpp"
#include "game/content/course_file.hpp"
#include "game/content/swings_file.hpp"
#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/golf_group.hpp"
#include "game/modes/golf/golfer.hpp"
#include "game/rules/golf_scoring.hpp"
#include "game/modes/golf/range_session.hpp"
#include "game/render/dispersion_plot.hpp"
#include "game/report/round_json.hpp"
#include "game/report/round_save.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot::cli {
namespace {

struct RoundOptions {
  std::string course = "national";
  std::vector<std::string> bots;
  std::vector<int> handicaps;
  std::string format = "stroke";
  double gimme = -1.0;  // m; < 0: the format's default
  bool calm = false;
  std::uint64_t seed = 1;
  std::string swings;
  std::string mode = "stroke";
  int balls = 5;
  bool json = false;
  std::string plot;
  std::string save, resume, bag;
  int stop_after = 0;  // holes; 0: the whole round
  CourseSetup setup;
};

// The players: the scripted one first (a swings file), then one per --bot; names say the
// skill, numbered when two share one.
std::vector<GolfPlayer> round_players(const RoundOptions& o) {
  std::vector<GolfPlayer> players;
  if (!o.swings.empty()) players.push_back({"swings " + o.swings, o.bots.empty() ? "tour" : o.bots.front(), true, 0, {}});
  const std::size_t first_bot = o.swings.empty() ? 0 : 1;  // with a script, the first --bot plays on after it
  for (std::size_t i = first_bot; i < o.bots.size(); ++i) players.push_back({o.bots[i] + " bot", o.bots[i], false, 0, {}});
  if (players.empty()) players.push_back({"tour bot", "tour", false, 0, {}});
  // Counted on the names as given: numbering the first "amateur bot" must not make the
  // second look unique.
  std::vector<std::string> given;
  for (const GolfPlayer& p : players) given.push_back(p.name);
  for (std::size_t i = 0; i < players.size(); ++i) {
    int same = 0, before = 0;
    for (std::size_t k = 0; k < players.size(); ++k) {
      if (given[k] != given[i]) continue;
      ++same;
      if (k < i) ++before;
    }
    if (same > 1) players[i].name += " " + std::to_string(before + 1);
  }
  if (!o.handicaps.empty() && o.handicaps.size() != players.size())
    throw InputError("--handicap: give one per player (" + std::to_string(players.size()) + "), not " +
                     std::to_string(o.handicaps.size()));
  for (std::size_t i = 0; i < o.handicaps.size(); ++i) players[i].handicap = o.handicaps[i];
  return players;
}

void give_bag(const Assets& assets, const RoundOptions& o, std::vector<GolfPlayer>& players) {
  if (!o.bag.empty()) players.front().bag = bag_stock(load_bag(assets, o.bag, golfer_skill_names()));
}

// `resumed`: the save a --resume read, whose window record a --save carries on.
GolfGroup new_group(const Assets& assets, const RoundOptions& o, SavedRound& resumed) {
  if (!o.resume.empty()) {
    resumed = read_round_save(o.resume);
    return resume_round(assets, resumed);
  }
  Course course = load_course(assets, o.course);
  set_up(course, o.setup, "--tees", "--pins");
  // Stopping after the last hole (or past it) would save a finished round as one to go on with.
  if (o.stop_after > 0 && static_cast<std::size_t>(o.stop_after) >= course.holes.size())
    throw InputError("--stop-after " + std::to_string(o.stop_after) + ": " + course.name +
                     (course.holes.size() < 2 ? std::string(" has one hole: its round cannot stop part way")
                                              : " has " + std::to_string(course.holes.size()) + " holes (allowed [1, " +
                                                    std::to_string(course.holes.size() - 1) + "])"));
  if (o.calm)
    for (CourseHole& h : course.holes) {
      h.wind_speed = 0.0;
      h.wind_toward = 0.0;
    }
  GolfOptions options;
  options.format = golf_format(o.format);
  options.gimme_m = o.gimme >= 0.0 ? o.gimme : options.format == GolfFormat::Match ? kMatchGimme : 0.0;
  options.seed = o.seed;
  std::vector<GolfPlayer> players = round_players(o);
  if (options.format == GolfFormat::Match && players.size() != 2)
    throw InputError("--format match: match play is between two players (--bot twice, or --swings and one --bot), not " +
                     std::to_string(players.size()));
  if (options.format == GolfFormat::Skins && (players.size() < 2 || players.size() > 4))
    throw InputError("--format skins: skins is played by 2 to 4 players (--bot two to four times, or --swings and --bot), not " +
                     std::to_string(players.size()));
  give_bag(assets, o, players);
  return GolfGroup(assets, course, players, options);
}

int play_stroke_round(const Assets& assets, const RoundOptions& o) {
  SavedRound resumed;
  GolfGroup group = new_group(assets, o, resumed);
  const GolfOptions& options = group.options();
  std::vector<ScriptedStroke> script;
  if (!o.swings.empty()) script = load_swings(o.swings);
  const bool scripted_plays_on = !o.bots.empty();
  std::size_t at = 0;
  while (!group.finished()) {
    if (o.stop_after > 0 && group.hole_index() >= static_cast<std::size_t>(o.stop_after)) break;
    const bool script_turn = !o.swings.empty() && group.to_play() == 0;
    if (script_turn && at < script.size()) {
      const ScriptedStroke& s = script[at++];
      const GolfRound& r = group.round(0);
      StrokeInput in;
      in.club = s.club ? *s.club : (r.lie() == "green" ? "putter" : group.caddie(0).suggest(r.to_pin(), r.teed()));
      in.meter = s.meter;
      in.aim = s.aim;
      try {
        group.play(in);
      } catch (const InputError& e) {
        // Say which of the stroke's inputs led there: a speed or a club the player never wrote
        // comes from its power and the club chosen for it.
        char power[48];
        std::snprintf(power, sizeof power, "%.4g %%", 100.0 * s.meter.power);
        throw InputError(s.where + ": the stroke (" + in.club + ", power = " + power + "): " + e.what());
      }
    } else if (script_turn && !scripted_plays_on) {
      // The script ran out mid-round and no bot plays on: a card with unfinished holes is
      // not a round.
      throw InputError(o.swings + ": the script ran out after its " + std::to_string(script.size()) +
                       " strokes, on hole " + std::to_string(group.hole_index() + 1) +
                       " (give more [[stroke]] entries, or a --bot to play on after it)");
    } else if (group.hole_lost_for_next()) {
      group.concede_hole();  // a match's hole he can no longer halve: picked up
    } else {
      group.play_bot();
    }
  }
  // The save and the plot are replaced together, or neither is.
  OutputBatch outputs;
  if (!o.save.empty()) {
    // The course by its file, found again from wherever the save is resumed.
    write_file_atomic(o.save,
                      json_text(round_save_json(group, std::filesystem::absolute(group.course().source).string(),
                                                resumed.restarts, resumed.cancelled)) +
                          "\n",
                      OverInput::Allow);
  }
  if (!o.plot.empty()) {
    std::vector<StrokeRecord> strokes;
    for (const HoleCard& h : group.round(0).card()) strokes.insert(strokes.end(), h.shots.begin(), h.shots.end());
    write_dispersion_plot(strokes, group.players()[0].name, display_units(assets.sport("golf"), UnitSystem::Imperial), o.plot);
  }
  outputs.commit();
  if (o.json) std::cout << json_text(group_json(group)) << "\n";
  else if (group.players().size() == 1 && options.format == GolfFormat::Stroke)
    std::cout << round_table(group.round(0), group.players()[0].name);
  else std::cout << group_table(group);
  return 0;
}

// Closest to the pin (the course's shortest hole) or long drive (its longest): N balls from
// the tee, each a fresh one-hole round.
int play_contest(const Assets& assets, const RoundOptions& o) {
  Course course = load_course(assets, o.course);
  set_up(course, o.setup, "--tees", "--pins");
  const bool ctp = o.mode == "ctp";
  auto by_length = [](const CourseHole& a, const CourseHole& b) { return a.length() < b.length(); };
  const CourseHole hole = ctp ? *std::min_element(course.holes.begin(), course.holes.end(), by_length)
                              : *std::max_element(course.holes.begin(), course.holes.end(), by_length);
  Course one = course;
  one.holes = {hole};
  one.holes[0].number = 1;
  const std::string skill = o.bots.empty() ? "tour" : o.bots.front();
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
  nlohmann::json j = {{"mode", o.mode},     {"course", course.name},         {"hole", hole.world_name},
                      {"hole_number", hole.number}, {"par", hole.par}, {"length_m", hole.length()},
                      {"player", skill + " bot"}, {"seed", o.seed}, {"balls", balls}};
  if ((ctp && best < 1e9) || (!ctp && best > 0.0)) j[ctp ? "best_to_pin_m" : "best_distance_m"] = best;
  if (!o.plot.empty())
    write_dispersion_plot(contest_strokes, std::string(ctp ? "closest to the pin, " : "long drive, ") + skill + " bot",
                          display_units(assets.sport("golf"), UnitSystem::Imperial), o.plot);
  if (o.json) {
    std::cout << json_text(j) << "\n";
  } else {
    // A golfer's words: the hole by its number, par and yardage; a ball's distance to the pin
    // in feet, a drive in yards, each with its metres.
    const auto shown = [&](double m) {
      char text[64];
      if (ctp) std::snprintf(text, sizeof text, "%.0f ft (%.1f m)", m_to_ft(m), m);
      else std::snprintf(text, sizeof text, "%.0f yd (%.1f m)", m_to_yd(m), m);
      return std::string(text);
    };
    std::cout << (ctp ? "closest to the pin" : "long drive") << " on " << course.name << ", hole " << hole.number << " (par "
              << hole.par << ", " << std::lround(m_to_yd(hole.length())) << " yd), " << skill << " bot\n";
    for (const auto& b : balls)
      std::cout << "  " << b["club"].get<std::string>() << "  " << b["end"].get<std::string>() << "  "
                << shown(b[ctp ? "to_pin_m" : "distance_m"].get<double>()) << (b["in_play"].get<bool>() ? "" : "  (not in play)")
                << "\n";
    if (j.contains(ctp ? "best_to_pin_m" : "best_distance_m"))
      std::cout << "best: " << shown(j[ctp ? "best_to_pin_m" : "best_distance_m"].get<double>()) << "\n";
  }
  return 0;
}

RunFn setup_round(CLI::App& sub) {
  auto o = std::make_shared<RoundOptions>();
  auto* course_arg = sub.add_option("course", o->course, "a course of assets/courses (default national: 18 holes; national_3 its first three; links a generated three), a .toml file, or a directory from course import");
  sub.add_option("--bot", o->bots, "a bot player of this skill: tour, scratch, amateur or beginner; repeat for up to 4 players (default one tour bot)")
      ->check(checked_by([](const std::string& t) { golfer_skill(t); }, "SKILL"));
  sub.add_option("--bag", o->bag, "the first player's measured bag (range --bag-out): their caddie's carries");
  sub.add_option("--handicap", o->handicaps, "course handicap per player in order, 0..54 (default 0)")
      ->check(int_range<int>(0, kMaxHandicap));
  sub.add_option("--format", o->format, "stroke (default), match (two players), stableford or skins")
      ->check(checked_by([](const std::string& t) { golf_format(t); }, "FORMAT"));
  sub.add_option("--gimme", o->gimme, "putts this close (m) are conceded, 0..3 (default: 0.6 in match play, else off)")
      ->check(finite_range(GolfOptions::kGimme.min, GolfOptions::kGimme.max));
  sub.add_option("--tees", o->setup.tees, "the tee set to play from, as the course names them (\"white\"; default: each hole's own tee)");
  o->setup.pin_set = CourseSetup::kDayPinSet;
  auto* pins = sub.add_option("--pins", o->setup.pin_set, "the pin set, 0..9: where the cups are today (default 0, a mix: the holes take their sets in turn; 1 each hole's own pin; a course from course import has up to 4)")
      ->check(int_range<int>(0, 9));
  sub.add_flag("--calm", o->calm, "no wind on any hole (default: the course's wind, else drawn from the seed)");
  sub.add_option("--seed", o->seed, "seed of the bot's swing errors, 0..18446744073709551615 (default 1)")->check(kSeedText);
  sub.add_option("--swings", o->swings, "scripted meter inputs, one [[stroke]] per stroke (TOML)");
  sub.add_option("--mode", o->mode, "stroke (default), ctp (closest to the pin) or long-drive");
  auto* balls = sub.add_option("--balls", o->balls, "balls for ctp and long-drive, 1..100 (default 5)");
  sub.add_flag("--json", o->json, "print the DESIGN §9 JSON");
  sub.add_option("--save", o->save, "write the round (players, options, every turn) to FILE to resume later");
  sub.add_option("--stop-after", o->stop_after, "stop once the group has finished this many holes, 1..18 (with --save)")
      ->check(int_range<int>(1, 18));
  sub.add_option("--resume", o->resume, "go on with a round written by --save (its players, format and options)");
  sub.add_option("--plot", o->plot, "also write the session's dispersion (carry vs side per club) to FILE.png");
  auto* seed = sub.get_option("--seed");
  return [o, balls, pins, course_arg, seed](const Assets& assets) -> int {
    if (o->mode != "stroke" && o->mode != "ctp" && o->mode != "long-drive")
      throw InputError("--mode " + o->mode + ": unknown mode (allowed: stroke, ctp, long-drive)");
    if (!o->swings.empty() && o->mode != "stroke")
      throw InputError("--swings: scripted strokes play a stroke round; --mode " + o->mode + " is the bot's");
    if (balls->count() > 0 && o->mode == "stroke")
      throw InputError("--balls: a stroke round plays one ball to each cup; --balls is for --mode ctp or long-drive");
    if (!o->plot.empty()) check_png_output(o->plot, "--plot");
    if (o->balls < 1 || o->balls > 100) throw InputError("--balls " + std::to_string(o->balls) + " is out of range (allowed [1, 100])");
    if (!o->resume.empty() && (!o->bots.empty() || !o->handicaps.empty() || o->format != "stroke" || !o->swings.empty() ||
                               o->calm || o->gimme >= 0.0 || o->mode != "stroke" || !o->bag.empty() || seed->count() > 0))
      throw InputError("--resume: the saved round sets its players, format, seed and options; give none of --bot, --handicap, "
                       "--format, --gimme, --calm, --swings, --mode, --bag, --seed");
    if (!o->resume.empty() && (course_arg->count() > 0 || !o->setup.tees.empty() || pins->count() > 0))
      throw InputError("--resume: the saved round sets its course, tees and pins; give no COURSE, --tees or --pins");
    if (o->calm && !o->save.empty()) throw InputError("--calm: a saved round keeps the course's winds; not with --save");
    if (!o->swings.empty() && !o->save.empty()) throw InputError("--save: a scripted round is replayed from its file; not with --swings");
    if (o->stop_after < 0 || o->stop_after > 18)
      throw InputError("--stop-after " + std::to_string(o->stop_after) + " is out of range (allowed [1, 18])");
    if (o->stop_after > 0 && o->save.empty()) throw InputError("--stop-after: the round stops to be saved; give --save FILE");
    if (!o->save.empty()) check_output_path(o->save, "--save");
    if (!o->save.empty() && !o->plot.empty() && same_output_file(o->save, o->plot))
      throw InputError("--save " + o->save + " --plot " + o->plot + ": the saved round and the plot would overwrite each other");
    for (const std::string& b : o->bots) golfer_skill(b);  // refuse an unknown skill before any work
    golf_format(o->format);
    if (o->mode != "stroke" && (o->bots.size() > 1 || o->format != "stroke"))
      throw InputError("--mode " + o->mode + ": a contest is one bot's; --bot once, no --format");
    // A contest scores one ball's finish: no putts to concede, no strokes to give, no round
    // to save, and a long drive has no cup to place. Said, not silently ignored.
    if (o->mode != "stroke") {
      const std::vector<std::pair<bool, const char*>> stroke_only{
          {o->gimme >= 0.0, "--gimme"}, {!o->handicaps.empty(), "--handicap"}, {!o->save.empty(), "--save"},
          {o->stop_after > 0, "--stop-after"}, {o->mode == "long-drive" && pins->count() > 0, "--pins"}};
      for (const auto& [given, flag] : stroke_only)
        if (given) throw InputError(std::string(flag) + ": not part of --mode " + o->mode + " (a stroke round's option)");
    }
    if (o->bots.size() > 4) throw InputError("--bot: a round has at most 4 players, not " + std::to_string(o->bots.size()));
    // The files this run reads are not its outputs (a resumed round may be saved over itself).
    for (const auto& [flag, out] : {std::pair{"--save", &o->save}, std::pair{"--plot", &o->plot}}) {
      if (out->empty()) continue;
      for (const std::string* in : {&o->bag, &o->swings})
        if (!in->empty()) refuse_output_over_input(*out, *in, flag);
      if (std::string(flag) == "--plot" && !o->resume.empty()) refuse_output_over_input(*out, o->resume, flag);
    }
    return o->mode == "stroke" ? play_stroke_round(assets, *o) : play_contest(assets, *o);
  };
}

const CommandRegistrar round_command{35, "round", "play a golf course headless: a bot or scripted swings, scorecard or §9 JSON",
                           setup_round};

}  // namespace
}  // namespace sweetspot::cli
