#include "game/report/session_json.hpp"

#include <algorithm>

#include "game/report/box_score.hpp"
#include "game/report/flight_json.hpp"
#include "game/rules/baseball_game.hpp"
#include "physics/units.hpp"

namespace sweetspot {

nlohmann::json session_json(const std::vector<SwingRecord>& swings, const SessionOptions& o, std::uint64_t seed) {
  using nlohmann::json;
  json list = json::array();
  int outs = 0, hrs = 0;
  for (const SwingRecord& s : swings) {
    json pitch = {{"type", s.call.type.type},
                  {"speed_mps", s.call.type.speed},
                  {"spin_rpm", radps_to_rpm(s.call.type.spin)},
                  {"plate_position_m", {s.pitch.plate.x(), s.pitch.plate.y(), s.pitch.plate.z()}}};
    json j = {{"pitch", pitch}, {"timing_ms", s.timing_ms}, {"contact", s.result.contact}, {"outcome", s.call_text},
              {"barrel", s.result.barrel}, {"hard_hit", s.result.hard_hit}, {"swung", s.swung}};
    if (s.swung) j["bat_tracking"] = bat_tracking_json(s.result.tracking);
    if (s.result.contact) {
      j["launch"] = launch_json(s.result.shot.launch, -1.0);
      j["flight"] = flight_json(s.result.shot.trajectory.summary);
      j["flight"]["end"] = to_string(s.result.shot.end);
      if (!s.result.fielder.empty()) j["fielder"] = s.result.fielder;
    } else {
      j["launch"] = nullptr;
      j["flight"] = nullptr;
    }
    if (s.result.outcome == BattedOutcome::HomeRun) ++hrs;
    else if (s.swung) ++outs;
    list.push_back(j);
  }
  json out = {{"mode", o.mode}, {"seed", seed}, {"swings", list}};
  if (o.mode == "derby") {
    out["outs"] = outs;
    out["home_runs"] = hrs;
  } else if (o.mode == "at-bat") {
    // The count by the rules, pitch by pitch; the last call ends the at-bat.
    Count count;
    std::string result;
    for (const SwingRecord& s : swings) {
      PitchResult r = PitchResult::InPlay;
      for (PitchResult k : {PitchResult::Ball, PitchResult::CalledStrike, PitchResult::SwingingStrike, PitchResult::Foul,
                            PitchResult::FoulTip, PitchResult::HitByPitch})
        if (s.call_text == to_string(k)) r = k;
      const PlateEnd end = apply_pitch(count, r);
      if (end == PlateEnd::InPlay) result = s.call_text;
      if (end == PlateEnd::Strikeout) result = "strikeout";
      if (end == PlateEnd::Walk) result = "walk";
      if (end == PlateEnd::HitByPitch) result = "hit_by_pitch";
    }
    const int balls = count.balls, strikes = count.strikes;
    out["balls"] = balls;
    out["strikes"] = strikes;
    out["result"] = result;
  }
  return out;
}

}  // namespace sweetspot
