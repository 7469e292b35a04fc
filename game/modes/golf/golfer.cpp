#include "game/modes/golf/golfer.hpp"

#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {

const std::vector<GolferSkill>& golfer_skills() {
  static const std::vector<GolferSkill> skills = {
      {"tour", mph_to_mps(113.0), 12.0, 0.015, 0.06, 0.014},
      {"scratch", mph_to_mps(105.0), 20.0, 0.025, 0.08, 0.019},
      {"amateur", mph_to_mps(93.0), 30.0, 0.05, 0.12, 0.028},
      {"beginner", mph_to_mps(80.0), 55.0, 0.09, 0.18, 0.040},
  };
  return skills;
}

std::vector<std::string> golfer_skill_names() {
  std::vector<std::string> names;
  for (const GolferSkill& g : golfer_skills()) names.push_back(g.name);
  return names;
}

const GolferSkill& golfer_skill(std::string_view name) {
  std::string names;
  for (const GolferSkill& g : golfer_skills()) {
    if (g.name == name) return g;
    names += (names.empty() ? "" : ", ") + g.name;
  }
  throw InputError("unknown golfer skill '" + std::string(name) + "' (allowed: " + names + ")");
}

double full_swing_speed(const GolferSkill& g, const ClubInfo& club) {
  if (club.kind == "putter") return club.tour_speed;
  return club.tour_speed * g.driver_speed / mph_to_mps(113.0);
}

const std::vector<std::string>& golf_bag() {
  static const std::vector<std::string> bag = {"driver", "3-wood", "5-wood", "hybrid", "4-iron", "5-iron", "6-iron",
                                               "7-iron", "8-iron", "9-iron", "pw",     "sw",     "lw",     "putter"};
  return bag;
}

}  // namespace sweetspot
