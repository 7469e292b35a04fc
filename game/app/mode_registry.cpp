#include "game/app/mode_registry.hpp"

#include "game/content/course_file.hpp"
#include "game/ui/cage_view.hpp"
#include "game/ui/golf_view.hpp"
#include "game/ui/lab_view.hpp"

namespace sweetspot {

namespace {

Course play_course(const Assets& assets, const PlayOptions& o) {
  Course course = load_course(assets, o.course);
  if (o.holes > 0 && static_cast<std::size_t>(o.holes) < course.holes.size()) course.holes.resize(static_cast<std::size_t>(o.holes));
  return course;
}

}  // namespace

ModeRegistry play_modes(const Assets& assets, const PlayOptions& o, std::ostream& out) {
  const Assets* a = &assets;
  std::ostream* log = &out;
  return {
      {"lab", [a, o] { return make_lab_view(*a, std::make_unique<LabModel>(*a, o.scenario, o.overrides)); }},
      {"golf", [a, o, log] {
         return make_golf_view(*a, std::make_unique<GolfPlay>(*a, play_course(*a, o), golfer_skill(o.skill)),
                               {o.exit_when_done}, *log);
       }},
      {"baseball", [a, o] { return make_cage_view(*a, std::make_unique<BattingCage>(*a), {o.exit_when_done, o.pitches}); }},
  };
}

}  // namespace sweetspot
