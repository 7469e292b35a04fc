// `sweetspot range`: a bag-gapping session on the practice range. A bot of a skill hits N
// full swings with every club; the table shows each club's mean carry and total, their
// spread and the gap to the next club; --bag-out writes them as the player's bag, which
// `round --bag` and `play --bag` give the caddie.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/modes/golf/range_session.hpp"
#include "game/report/report.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot::cli {
namespace {

struct RangeOptions {
  std::string bot = "scratch";
  int shots = 10;
  std::uint64_t seed = 1;
  std::string bag_out;
  bool json = false;
};

int run_range(const Assets& assets, const RangeOptions& o) {
  const Bag bag = gap_bag(assets, golfer_skill(o.bot), o.shots, o.seed);
  if (!o.bag_out.empty()) write_file_atomic(o.bag_out, bag_toml(bag));
  if (o.json) {
    nlohmann::json clubs = nlohmann::json::array();
    for (const BagClub& c : bag.clubs)
      clubs.push_back({{"club", c.club}, {"shots", c.shots}, {"carry_m", c.carry}, {"total_m", c.total},
                       {"carry_sd_m", c.carry_sd}, {"side_sd_m", c.side_sd}});
    std::cout << json_text({{"player", bag.player}, {"skill", bag.skill}, {"seed", o.seed}, {"clubs", clubs}}) << "\n";
    return 0;
  }
  std::printf("bag gapping: %s, %d shots a club (yards; carry± one standard deviation about the mean, side the root mean\n"
              "square distance from the target line)\n", bag.player.c_str(), o.shots);
  std::printf("%-8s %7s %7s %8s %8s %6s\n", "club", "carry", "total", "carry±", "side", "gap");
  for (std::size_t k = 0; k < bag.clubs.size(); ++k) {
    const BagClub& c = bag.clubs[k];
    char gap[16] = "";
    if (k + 1 < bag.clubs.size()) std::snprintf(gap, sizeof gap, "%.0f", m_to_yd(c.carry - bag.clubs[k + 1].carry));
    std::printf("%-8s %7.0f %7.0f %8.1f %8.1f %6s\n", c.club.c_str(), m_to_yd(c.carry), m_to_yd(c.total), m_to_yd(c.carry_sd),
                m_to_yd(c.side_sd), gap);
  }
  if (!o.bag_out.empty()) std::printf("bag written to %s (round --bag, play --bag)\n", o.bag_out.c_str());
  return 0;
}

RunFn setup_range(CLI::App& sub) {
  auto o = std::make_shared<RangeOptions>();
  sub.add_option("--bot", o->bot, "the golfer who hits: tour, scratch (default), amateur or beginner");
  sub.add_option("--shots", o->shots, "full swings per club, 1..100 (default 10)");
  sub.add_option("--seed", o->seed, "seed of the swing errors, 0..18446744073709551615 (default 1)")->check(kSeedText);
  sub.add_option("--bag-out", o->bag_out, "write the measured bag to FILE (TOML)");
  sub.add_flag("--json", o->json, "print the clubs as JSON");
  return [o](const Assets& assets) -> int {
    golfer_skill(o->bot);
    if (o->shots < 1 || o->shots > 100) throw InputError("--shots " + std::to_string(o->shots) + " is out of range (allowed [1, 100])");
    if (!o->bag_out.empty()) check_output_path(o->bag_out, "--bag-out");
    return run_range(assets, *o);
  };
}

const CommandRegistrar range_command{36, "range", "the practice range: a bag-gapping session, each club's carry and spread (--bag-out)",
                           setup_range};

}  // namespace
}  // namespace sweetspot::cli
