#include "game/app/mode_registry.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "game/content/bag_file.hpp"
#include "game/content/course_file.hpp"
#include "game/content/settings_file.hpp"
#include "game/modes/golf/golfer.hpp"
#include "game/modes/golf/range_session.hpp"
#include "game/report/round_save.hpp"
#include "game/ui/cage_view.hpp"
#include "game/ui/golf_view.hpp"
#include "game/ui/lab_view.hpp"
#include "game/ui/range_view.hpp"
#include "physics/error.hpp"

namespace sweetspot {

namespace {

Course play_course(const Assets& assets, const PlayOptions& o) {
  Course course = load_course(assets, o.course);
  set_up(course, o.course_setup, "--tees", "--pins");
  if (o.holes > 0 && static_cast<std::size_t>(o.holes) < course.holes.size()) course.holes.resize(static_cast<std::size_t>(o.holes));
  return course;
}

// The round the window plays: you (and your bag), the bots you asked for (one of your skill
// when none), the format and its options, or a saved round to go on with.
std::unique_ptr<GolfPlay> golf_model(const Assets& assets, const PlayOptions& o) {
  GolfSetup setup;
  setup.flyover = o.flyover;
  setup.input_latency = load_settings(settings_path()).input_latency;
  setup.difficulty = meter_difficulty(o.difficulty);
  if (!o.resume.empty()) {
    const SavedRound saved = read_round_save(o.resume);
    setup.players = saved.players;
    setup.options = saved.options;
    setup.resume = saved.events;
    setup.resume_restarts = saved.restarts;
    setup.resume_cancelled = saved.cancelled;
    return std::make_unique<GolfPlay>(assets, saved_course(assets, saved), setup);
  }
  GolfPlayer you{"You", o.skill, true, 0, {}};
  // A bag the range has not written yet (play --mode range --bag F, Tab to golf) is no bag.
  if (!o.bag.empty() && std::filesystem::exists(o.bag)) you.bag = bag_stock(load_bag(assets, o.bag, golfer_skill_names()));
  setup.players.push_back(you);
  for (const std::string& name : o.humans) setup.players.push_back({name, o.skill, true, 0, {}});
  // No bot asked for: one of your skill when you play alone, none when friends play.
  const std::vector<std::string> bots = !o.bots.empty() ? o.bots : o.humans.empty() ? std::vector<std::string>{o.skill} : std::vector<std::string>{};
  for (const std::string& b : bots) {
    if (b == "none") continue;
    // Two bots of one skill are told apart: "amateur bot 1" and "amateur bot 2".
    const auto same = static_cast<int>(std::count(bots.begin(), bots.end(), b));
    int nth = 0;
    for (const GolfPlayer& p : setup.players) nth += p.skill == b && !p.human;
    setup.players.push_back({b + " bot" + (same > 1 ? " " + std::to_string(nth + 1) : ""), b, false, 0, {}});
  }
  for (std::size_t i = 0; i < o.handicaps.size() && i < setup.players.size(); ++i) setup.players[i].handicap = o.handicaps[i];
  setup.options.format = golf_format(o.format);
  setup.options.gimme_m = o.gimme >= 0.0 ? o.gimme : setup.options.format == GolfFormat::Match ? kMatchGimme : 0.0;
  setup.options.auto_putt = o.auto_putt;
  setup.options.seed = o.seed;
  return std::make_unique<GolfPlay>(assets, play_course(assets, o), setup);
}

}  // namespace

ModeRegistry play_modes(const Assets& assets, const PlayOptions& o, std::ostream& out) {
  const Assets* a = &assets;
  std::ostream* log = &out;
  return {
      {"lab", [a, o] { return make_lab_view(*a, std::make_unique<LabModel>(*a, o.scenario, o.overrides)); }},
      {"golf", [a, o, log] {
         return make_golf_view(*a, golf_model(*a, o), {o.exit_when_done, o.save, !o.metric}, *log);
       }},
      {"range", [a, o] {
         return make_range_view(*a, std::make_unique<RangePlay>(*a, golfer_skill(o.skill), 5, meter_difficulty(o.difficulty), o.seed),
                                {o.bag.empty() ? std::string("sweetspot_bag.toml") : o.bag, !o.metric});
       }},
      {"baseball",
       [a, o] {
         // The batting cage's difficulty is the pitch's pace: its swing window in the player's time.
         const MeterDifficulty d = meter_difficulty(o.difficulty);
         const double scale = d == MeterDifficulty::Easy  ? BattingCage::kEasyPitchTimeScale
                              : d == MeterDifficulty::Pro ? BattingCage::kProPitchTimeScale
                                                          : BattingCage::kPitchTimeScale;
         return make_cage_view(*a, std::make_unique<BattingCage>(*a, o.seed, scale), {o.exit_when_done, o.pitches});
       }},
  };
}

void check_play_course(const Assets& assets, const PlayOptions& o) {
  try {
    (void)play_course(assets, o);
  } catch (const InputError& e) {
    // The tee and pin sets' refusals name their flags; the course's is the course's.
    if (std::string(e.what()).starts_with("--")) throw;
    throw InputError(std::string("--course: ") + e.what());
  }
}

void check_play_mode(const Assets& assets, const PlayOptions& o) {
  std::ostringstream quiet;  // building the registry only names the modes; nothing is made yet
  std::string names;
  for (const ModeEntry& m : play_modes(assets, o, quiet)) {
    if (m.name == o.mode) return;
    names += (names.empty() ? "" : ", ") + m.name;
  }
  throw InputError("--mode " + o.mode + ": unknown mode (allowed: " + names + ")");
}

}  // namespace sweetspot
