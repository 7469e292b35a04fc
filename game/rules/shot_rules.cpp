#include "game/rules/shot_rules.hpp"

#include "game/rules/baseball_rules.hpp"
#include "game/rules/golf_rules.hpp"
#include "physics/error.hpp"

namespace sweetspot {

std::unique_ptr<ShotRules> make_shot_rules(const SportProfile& sport, const WorldAsset* world, const ShotModel& model) {
  if (sport.rules == "golf") return std::make_unique<GolfShotRules>(world, model);
  if (sport.rules == "baseball") return std::make_unique<BaseballShotRules>(world, model);
  throw InputError("sport '" + sport.name + "': unknown rules '" + sport.rules + "' (allowed: golf, baseball)");
}

}  // namespace sweetspot
