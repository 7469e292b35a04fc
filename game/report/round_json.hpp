// The scorecard of a golf round for people (a table) and programs (DESIGN §9 JSON).
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "game/modes/golf/round.hpp"

namespace sweetspot {

nlohmann::json round_json(const GolfRound& round, const std::string& player, std::uint64_t seed);
/// Hole, par, strokes, putts, penalties, then the totals and the score against par.
std::string round_table(const GolfRound& round, const std::string& player);

}  // namespace sweetspot
