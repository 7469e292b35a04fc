// A baseball game for people and programs (DESIGN §9): `derby --mode game --json` (every
// plate appearance with its pitches and batted ball, the line score and the box score) and
// the box score as a newspaper prints it.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "game/modes/baseball/ball_game.hpp"

namespace sweetspot {

nlohmann::json game_json(const GameRecord& game);
/// One swing's bat tracking (DESIGN §9), for every JSON that lists swings.
nlohmann::json bat_tracking_json(const BatTracking& t);
/// "home pitching change: RP2 replaces RP1, runners on 1st and 3rd" for the plate appearance
/// a new pitcher came in to face (the play-by-play's line before it).
std::string pitching_change_text(const PlateAppearance& pa);
/// The line score, each team's batting lines and the pitching lines.
std::string box_score_text(const GameRecord& game);
/// The league-rate table of `rates` (the note's and the test's).
std::string rates_text(const BattingRates& rates, const std::string& title);

}  // namespace sweetspot
