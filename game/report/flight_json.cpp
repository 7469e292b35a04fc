#include "game/report/flight_json.hpp"

#include "physics/units.hpp"

namespace sweetspot {

nlohmann::json launch_json(const LaunchMetrics& m, double smash_factor) {
  nlohmann::json j;
  j["ball_speed_mps"] = m.ball_speed;
  j["vertical_angle_deg"] = rad_to_deg(m.vertical_angle);
  j["horizontal_angle_deg"] = rad_to_deg(m.horizontal_angle);
  j["spin_rpm"] = radps_to_rpm(m.spin.total);
  j["backspin_rpm"] = radps_to_rpm(m.spin.backspin);
  j["sidespin_rpm"] = radps_to_rpm(m.spin.sidespin_right);
  j["spin_axis_deg"] = rad_to_deg(m.spin.axis_rad);
  j["smash_factor"] = smash_factor >= 0.0 ? nlohmann::json(smash_factor) : nlohmann::json(nullptr);
  return j;
}

nlohmann::json flight_json(const FlightSummary& s) {
  nlohmann::json j;
  j["carry_m"] = s.carry_m;
  j["total_m"] = s.total_m;
  j["apex_m"] = s.apex_m;
  j["landing_angle_deg"] = s.landing_angle_deg;
  j["hang_time_s"] = s.hang_time_s;
  j["lateral_m"] = s.lateral_m;
  j["end"] = to_string(s.end);
  j["rest_position_m"] = {s.rest_position.x(), s.rest_position.y(), s.rest_position.z()};
  j["bounces"] = s.bounces;
  j["total_time_s"] = s.total_time_s;
  return j;
}

}  // namespace sweetspot
