// The `launch` and `flight` objects of DESIGN §6, shared by `shot --json` and `flight --json`.
// SI values; keys are a public contract (tests and users depend on them).
#pragma once

#include <nlohmann/json.hpp>

#include "physics/launch.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

/// {"ball_speed_mps", "vertical_angle_deg", "horizontal_angle_deg", "spin_rpm", "backspin_rpm",
///  "sidespin_rpm", "spin_axis_deg", "smash_factor"}; smash_factor is null when not known (< 0).
nlohmann::json launch_json(const LaunchMetrics& m, double smash_factor = -1.0);

/// {"carry_m", "total_m", "apex_m", "landing_angle_deg", "hang_time_s", "lateral_m", "end",
///  "rest_position_m": [x, y, z], "bounces", "total_time_s"}.
nlohmann::json flight_json(const FlightSummary& s);

}  // namespace sweetspot
