// A baseball session as DESIGN §9's JSON (`derby --json`): every swing with its pitch,
// timing, launch, flight and outcome, and the session's tally (derby outs and home runs,
// an at-bat's count and result).
#pragma once

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/modes/baseball/session.hpp"

namespace sweetspot {

nlohmann::json session_json(const std::vector<SwingRecord>& swings, const SessionOptions& o, std::uint64_t seed);

}  // namespace sweetspot
