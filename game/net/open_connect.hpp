// GSPro Open Connect v1 (DESIGN §10): the messages a launch monitor's connector sends and the
// replies a simulator gives, without sockets (the server is game/net/connect_server).
//
// Sources: the vendor's page (gsprogolf.com/GSProConnectV1.html: the root keys, BallData,
// ClubData, ShotDataOptions; codes 200 shot received, 201 player information, 5xx failure)
// and what the public connectors send and expect: keys matched without case ("APIVersion",
// "Backspin"), no delimiter between messages (so the stream is framed by brace depth), the
// exact reply strings of the real program ("Ball Data received", "Club & Ball Data received",
// "GSPro Player Information", "Bad format"), replies as compact JSON without a newline.
// The stream is cut into messages by game/net/message_framer.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace sweetspot {

struct OcBallData {
  double speed_mph = 0.0;      ///< ball speed
  double vla_deg = 0.0;        ///< vertical launch angle
  double hla_deg = 0.0;        ///< horizontal launch angle, + right of the target
  double total_spin_rpm = 0.0;
  double spin_axis_deg = 0.0;  ///< + tilted right (fade/slice for a right-hander)
};
struct OcClubData {
  std::optional<double> speed_mph, angle_of_attack_deg, face_to_target_deg, path_deg, loft_deg, lie_deg,
      vertical_impact_mm, horizontal_impact_mm, closure_rate_dps;
};

struct OcMessage {
  enum class Kind { Shot, Heartbeat, Status };
  Kind kind = Kind::Status;
  std::string device_id;
  int shot_number = 0;
  std::optional<OcBallData> ball;
  std::optional<OcClubData> club;
  bool ready = false, ball_detected = false;
};

/// Parses one framed message. Throws InputError naming the problem (malformed JSON, a shot
/// without a usable BallData, non-finite numbers, values beyond any launch monitor's range).
OcMessage parse_open_connect(std::string_view text);

/// Reply objects: 200 for a shot ("Ball Data received", or "Club & Ball Data received"),
/// 201 with the player (handed "RH"/"LH", a GSPro club code, distance to target in yards),
/// 501 "Bad format" (or another 5xx text). Compact JSON, no newline.
std::string reply_shot(bool with_club);
std::string reply_player(const std::string& handed, const std::string& club_code, std::optional<double> distance_yd);
std::string reply_status(int code, const std::string& message);

/// GSPro's club code for a club of our bag ("driver" -> "DR", "7-iron" -> "I7", "pw" -> "PW",
/// "putter" -> "PT").
std::string gspro_club_code(const std::string& club);

}  // namespace sweetspot
