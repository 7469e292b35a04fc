#include "game/modes/baseball/live_inning.hpp"

#include <algorithm>
#include <numeric>

#include "game/modes/baseball/fielding.hpp"

namespace sweetspot {

namespace {

std::string plural(int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

}  // namespace

int LiveInning::Board::runs() const { return std::accumulate(runs_by_inning.begin(), runs_by_inning.end(), 0); }
int LiveInning::Board::their_runs() const {
  return std::accumulate(their_runs_by_inning.begin(), their_runs_by_inning.end(), 0);
}

LiveInning::LiveInning(const Assets& assets, std::uint64_t seed)
    : assets_(assets),
      seed_(seed),
      batting_(assets, "You", batter_skill("pro"), seed * 2 + 1),
      fielding_(assets, "League", batter_skill("pro"), seed * 2 + 2),
      half_(empty_half_inning(assets)),
      throws_(seed * 0x9E3779B97F4A7C15ULL + 0x7468726F77ULL) {
  // The cage's balls are fielded by the league's defence (field_ball): its runners must be
  // thrown at by the same fielders.
  fielding_.defense = league_defense();
}

void LiveInning::next_batter() {
  if (board_.final) return;
  board_.note.clear();
  if (!board_.side_retired) return;
  // The next inning: bases empty, no outs; in extra innings the batter before this half's
  // leadoff man on second (MLB Rule 7.01(b), since 2023).
  ++board_.inning;
  board_.runs_by_inning.push_back(0);
  board_.side_retired = false;
  board_.outs = 0;
  half_.bases = {-1, -1, -1};
  if (board_.inning > kInnings) half_.bases[1] = (batter_ + 8) % 9;
  board_.bases = half_.bases;
  half_.outs = 0;
  inning_hits_ = 0;
}

namespace {
bool is_hit(const std::string& result) {
  return result == "single" || result == "double" || result == "triple" || result == "home_run";
}
}  // namespace

void LiveInning::play_their_half() {
  GameSituation s;
  s.scheduled = kInnings;
  s.inning = board_.inning;
  s.away_runs = board_.runs();
  s.home_runs = board_.their_runs();
  s.outs = 3;
  // The home side need not bat when it leads after the top of the 9th (or later).
  if (!game_over(s)) {
    s.bottom = true;
    s.outs = 0;
    HalfInning h = half_;
    h.bases = {-1, -1, -1};
    h.outs = 0;
    if (s.inning > kInnings) h.bases[1] = (their_batter_ + 8) % 9;
    int runs = 0, hits = 0;
    std::string scoring;
    bool inning_start = true;
    mound_runs_ = 0;
    while (h.outs < 3) {
      // The player's side's bullpen, as a game's manager works it (Team::to_the_bullpen).
      const Team::MoundVisit visit{s.inning, inning_start, runners_on(h.bases), mound_runs_, mound_outs_, s.away_runs - s.home_runs};
      const std::uint64_t mound_seed = seed_ * 1000003ULL + static_cast<std::uint64_t>(2 * s.inning + 1) +
                                       (inning_start ? 0ULL : 7919ULL * static_cast<std::uint64_t>(batting_.pitchers_used));
      if (batting_.to_the_bullpen(visit, mound_seed)) {
        mound_outs_ = 0;
        mound_runs_ = 0;
      }
      inning_start = false;
      const int batter = their_batter_;
      their_batter_ = (batter + 1) % 9;
      PlateAppearance pa = plate_appearance(assets_, fielding_.lineup[static_cast<std::size_t>(batter)], batting_);
      pa.inning = s.inning;
      pa.bottom = true;
      pa.batter = batter;
      pa.outs_before = h.outs;
      pa.bases_before = h.bases;
      std::vector<int> scored;
      if (pa.result == "walk" || pa.result == "hit_by_pitch") {
        if (force_advance(h.bases, batter) > 0) scored.push_back(pa.bases_before[2]);
      } else if (pa.result == "strikeout") {
        ++h.outs;
      } else {
        int outs_made = 0;
        h.runs_to_win = s.inning >= kInnings ? std::max(0, s.away_runs - s.home_runs + 1) : 0;
        h.advance(pa, fielding_, batting_, throws_, scored, outs_made, pa.description);
      }
      if (s.inning >= kInnings && pa.result != "home_run") walk_off_limit(pa, s, scored);
      const int r = static_cast<int>(scored.size());
      mound_outs_ += h.outs - pa.outs_before;
      mound_runs_ += r;
      runs += r;
      s.home_runs += r;
      hits += is_hit(pa.result);
      if (r > 0) scoring += (scoring.empty() ? "" : "; ") + pa.description + ", " + plural(r, "run", "runs");
      s.outs = h.outs;
      if (h.outs < 3 && game_over(s)) break;  // a walk-off
    }
    board_.their_runs_by_inning.push_back(runs);
    board_.their_hits += hits;
    board_.their_half = "Bottom of the " + ordinal(s.inning) + ": League " + plural(runs, "run", "runs") + ", " +
                        plural(hits, "hit", "hits") + (scoring.empty() ? "" : " (" + scoring + ")");
    if (s.outs < 3) board_.their_half += ". Walk-off";
    s.outs = 3;
  }
  if (!game_over(s)) return;
  board_.final = true;
  const bool we_won = s.away_runs > s.home_runs;
  board_.final_line = std::string("Final: ") + (we_won ? "You " : "League ") + std::to_string(std::max(s.away_runs, s.home_runs)) +
                      ", " + (we_won ? "League " : "You ") + std::to_string(std::min(s.away_runs, s.home_runs)) +
                      (s.inning != kInnings ? " in " + std::to_string(s.inning) + " innings" : "");
}

void LiveInning::end_plate_appearance(const std::string& result, const PitchRecord& last) {
  if (board_.final) return;
  board_.scored_as.clear();
  board_.their_half.clear();  // read through the next inning's first plate appearance
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
  board_.scored_as = play;
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
    play_their_half();
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
