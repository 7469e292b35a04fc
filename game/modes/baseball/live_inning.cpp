#include "game/modes/baseball/live_inning.hpp"

#include <algorithm>
#include <numeric>

#include "game/modes/baseball/fielding.hpp"

namespace sweetspot {

namespace {

std::string plural(int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

}  // namespace

int LiveInning::Board::runs() const { return std::accumulate(runs_by_inning.begin(), runs_by_inning.end(), 0); }

LiveInning::LiveInning(const Assets& assets, std::uint64_t seed)
    : batting_(assets, "You", batter_skill("pro"), seed * 2 + 1),
      fielding_(assets, "League", batter_skill("pro"), seed * 2 + 2),
      half_(empty_half_inning(assets)),
      throws_(seed * 0x9E3779B97F4A7C15ULL + 0x7468726F77ULL) {
  // The cage's balls are fielded by the league's defence (field_ball): its runners must be
  // thrown at by the same fielders.
  fielding_.defense = league_defense();
}

void LiveInning::next_batter() {
  board_.note.clear();
  if (!board_.side_retired) return;
  // The next inning: bases empty, no outs.
  ++board_.inning;
  board_.runs_by_inning.push_back(0);
  board_.side_retired = false;
  board_.outs = 0;
  board_.bases = {-1, -1, -1};
  half_.bases = {-1, -1, -1};
  half_.outs = 0;
  inning_hits_ = 0;
}

void LiveInning::end_plate_appearance(const std::string& result, const PitchRecord& last) {
  next_batter();  // a plate appearance ended without its first pitch told (the tests' scripts)
  PlateAppearance pa;
  pa.batter = batter_;
  pa.outs_before = half_.outs;
  pa.bases_before = half_.bases;
  pa.pitches = {last};
  pa.result = result;
  std::vector<int> scored;
  // The play with the runners' part: base_running adds a runner thrown out to the batted
  // ball's words, or rewrites them (a double play, a fielder's choice). Said only when it did.
  std::string play;
  if (result == "walk" || result == "hit_by_pitch") {
    if (force_advance(half_.bases, batter_) > 0) scored.push_back(pa.bases_before[2]);
  } else if (result == "strikeout") {
    ++half_.outs;
  } else {
    int outs_made = 0;
    const std::string& batted = last.result.play.description;
    play = batted;
    half_.advance(pa, batting_, fielding_, throws_, scored, outs_made, play);
    if (play == batted) play.clear();
  }
  const bool hit = result == "single" || result == "double" || result == "triple" || result == "home_run";
  board_.hits += hit;
  inning_hits_ += hit;
  const int runs = static_cast<int>(scored.size());
  board_.runs_by_inning.back() += runs;
  batter_ = (batter_ + 1) % 9;
  std::string note = play;
  const auto add = [&note](const char* between, const std::string& words) {
    if (!note.empty()) note += between;
    note += words;
  };
  if (runs > 0) add(", ", plural(runs, "run scores", "runs score"));
  if (half_.outs >= 3) {
    const int left = runners_on(half_.bases);
    board_.left_on_base += left;
    board_.side_retired = true;
    add(". ", "Side retired: " + plural(board_.runs_by_inning.back(), "run", "runs") + ", " + plural(inning_hits_, "hit", "hits") +
                  ", " + std::to_string(left) + " left on base");
  }
  board_.outs = std::min(half_.outs, 3);
  board_.bases = half_.bases;
  board_.note = note;
}

std::string runners_text(const Bases& b) {
  static const char* kBase[] = {"1st", "2nd", "3rd"};
  std::vector<const char*> on;
  for (int i = 0; i < 3; ++i)
    if (b[static_cast<std::size_t>(i)] >= 0) on.push_back(kBase[i]);
  if (on.empty()) return "bases empty";
  if (on.size() == 3) return "bases loaded";
  if (on.size() == 1) return std::string("runner on ") + on[0];
  return std::string("runners on ") + on[0] + " and " + on[1];
}

}  // namespace sweetspot
