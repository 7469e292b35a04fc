#include "game/modes/golf/golfer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "game/modes/golf/swing_meter.hpp"
#include "physics/error.hpp"
#include "physics/sand_splash.hpp"
#include "physics/units.hpp"

namespace sweetspot {

const std::vector<GolferSkill>& golfer_skills() {
  constexpr double kClubs = std::numeric_limits<double>::quiet_NaN();  // the club's own (tour) delivery
  static const std::vector<GolferSkill> skills = {
      {"tour", mph_to_mps(113.0), 12.0, 0.035, 0.06, 0.020, kClubs, kClubs, 0.13},
      {"scratch", mph_to_mps(105.0), 18.0, 0.025, 0.08, 0.019, deg_to_rad(-0.9), deg_to_rad(13.0), 0.18},
      {"amateur", mph_to_mps(93.0), 25.0, 0.05, 0.08, 0.028, deg_to_rad(-1.8), deg_to_rad(15.1), 0.35},
      {"beginner", mph_to_mps(80.0), 55.0, 0.09, 0.11, 0.036, deg_to_rad(-2.3), deg_to_rad(16.5), 0.45},
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

double added_loft(const GolferSkill& g, const EquipmentCatalog& eq) {
  if (std::isnan(g.driver_strike_loft)) return 0.0;
  const ClubSpec& driver = eq.club("driver");
  return g.driver_strike_loft - (driver.dynamic_loft + strike_tilt(driver, driver.strike_height));
}

GolfSwing golfer_swing(const GolferSkill& g, const MeterInput& m, const EquipmentCatalog& eq, const std::string& club) {
  const ClubSpec& spec = eq.club(club);
  const ClubInfo& info = eq.club_info_of(club);
  GolfSwing s = meter_swing(m, spec, info, full_swing_speed(g, info));
  if (info.kind == "putter") return s;
  s.dynamic_loft = spec.dynamic_loft + added_loft(g, eq);
  if (club == "driver" && !std::isnan(g.driver_attack)) s.attack_angle = g.driver_attack;
  return s;
}

double sand_entry_for(const ClubSpec& club, const std::string& lie, double timing_ms) {
  constexpr double kSplashLoft = deg_to_rad(54.0);  // the SW's 56° and the LW's 60°, not the PW's 46°
  if (lie != "sand") return 0.0;
  const double meant = club.loft >= kSplashLoft ? kSplashEntry : -kPickBeyond;  // + behind the ball
  return std::clamp(meant - kLowPointPerMs * timing_ms, kSandEntry.min, kSandEntry.max);
}

std::string splash_words(const ClubSpec& club, const std::string& lie, double entry) {
  if (lie != "sand") return "";
  if (sand_entry_for(club, lie) <= 0.0) return entry > 0.0 ? "heavy, sand before the ball" : "";
  if (entry <= 0.0) return "caught clean, no sand before the ball";
  if (entry >= 2.0 * kSplashEntry) return "heavy, deep in the sand behind it";
  return "";
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

std::string club_name(const std::string& club) {
  if (club == "pw") return "pitching wedge";
  if (club == "sw") return "sand wedge";
  if (club == "lw") return "lob wedge";
  return club;
}

}  // namespace sweetspot
