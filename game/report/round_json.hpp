// The scorecard of a golf round for people (a table) and programs (DESIGN §9 JSON).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/modes/golf/golf_group.hpp"
#include "game/modes/golf/round.hpp"

namespace sweetspot {

nlohmann::json round_json(const GolfRound& round, const std::string& player, std::uint64_t seed);
/// Hole, par, strokes, putts, fairway (hit, or the side missed), green in regulation,
/// penalties, then the totals (fairways and greens as hit/of) and the score against par.
std::string round_table(const GolfRound& round, const std::string& player);
/// A score against par as golfers write it: "E", "+3", "-2".
std::string to_par_text(int diff);

/// A group's round (DESIGN §9 "Players and formats"): the players with their holes and
/// totals, the format and its result, each hole's wind; with one player, also the
/// single-player fields of round_json.
nlohmann::json group_json(const GolfGroup& group);
/// The card a golfer checks by hand: per hole par, stroke index and every player's strokes
/// (with the strokes received), putts and the format's column; then the sum rows and result.
/// `restarts`: per hole, how often it was restarted from the window's menu (an R beside the
/// hole's number, as the window's card marks it); none from a headless round.
std::string group_table(const GolfGroup& group, const std::vector<int>& restarts = {});

}  // namespace sweetspot
