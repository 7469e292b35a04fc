#include "game/net/open_connect.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <system_error>

#include "game/content/json_unique_keys.hpp"
#include "physics/error.hpp"

namespace sweetspot {

namespace {

// The value under `key` matched without case; nullptr when absent or null.
const nlohmann::json* field(const nlohmann::json& o, const char* key) {
  if (!o.is_object()) return nullptr;
  const std::string want = ascii_lower(key);
  for (auto it = o.begin(); it != o.end(); ++it)
    if (ascii_lower(it.key()) == want) return it.value().is_null() ? nullptr : &it.value();
  return nullptr;
}

// A number for a message: %g, so 1e308 is not echoed as 309 digits.
std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A number as the protocol sends it: a JSON number, or a string holding exactly one (some
// connectors quote their numbers). A unit or any other text ("150 km/h", "150mph") is
// refused: the protocol's units are fixed (mph, degrees, rpm), so a unit could only be
// misread.
bool number_text(std::string_view t) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i > from;
  };
  if (i < t.size() && t[i] == '-') ++i;
  if (!digits()) return false;
  if (i < t.size() && t[i] == '.') {
    ++i;
    if (!digits()) return false;
  }
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (!digits()) return false;
  }
  return i == t.size();
}

// `unit`: the protocol's unit of the field (mph, deg, rpm; "" for a count), said with its range.
std::optional<double> number(const nlohmann::json& o, const char* key, const char* where, double lo, double hi, const char* unit = "") {
  const nlohmann::json* v = field(o, key);
  if (v == nullptr) return std::nullopt;
  double d = 0.0;
  if (v->is_number()) {
    d = v->get<double>();
  } else if (v->is_string() && number_text(v->get<std::string>())) {
    const std::string& t = v->get_ref<const std::string&>();
    // Past a double's range: "1e999" reads as infinite (refused below), "1e-999" as 0.
    if (std::from_chars(t.data(), t.data() + t.size(), d).ec != std::errc())
      d = t.find("e-") != std::string::npos || t.find("E-") != std::string::npos ? 0.0 : std::numeric_limits<double>::infinity();
  } else {
    throw InputError(std::string(where) + "." + key + " = " + v->dump().substr(0, 40) +
                     ": not a number (a JSON number, or a string of digits only: the protocol's units are mph, degrees and rpm)");
  }
  if (!std::isfinite(d) || d < lo || d > hi)
    throw InputError(std::string(where) + "." + key + " = " + short_number(d) + " is out of range (allowed [" +
                     short_number(lo) + ", " + short_number(hi) + "]" + (*unit ? std::string(" ") + unit : std::string()) + ")");
  return d;
}

// A flag: JSON true or false. Anything else ("true", 1) is refused rather than read as
// false: a shot whose ContainsBallData is "true" must not be answered and dropped.
bool flag(const nlohmann::json& o, const char* key, const char* where) {
  const nlohmann::json* v = field(o, key);
  if (v == nullptr) return false;
  if (!v->is_boolean())
    throw InputError(std::string(where) + "." + key + " = " + v->dump().substr(0, 40) + ": not a boolean (send true or false)");
  return v->get<bool>();
}


}  // namespace

OcMessage parse_open_connect(std::string_view text) {
  const nlohmann::json j = parse_json_unique_keys(text, "message");
  if (!j.is_object()) throw InputError("a message must be a JSON object");
  OcMessage m;
  if (const nlohmann::json* d = field(j, "DeviceID"); d && d->is_string()) m.device_id = d->get<std::string>();
  // A count of the launch monitor's shots: never negative (GSPro's own counts from 0 or 1).
  if (const auto n = number(j, "ShotNumber", "message", 0.0, 1e9)) {
    if (*n != std::floor(*n)) throw InputError("message.ShotNumber = " + short_number(*n) + " is not a whole number");
    m.shot_number = static_cast<int>(*n);
  }
  // The header's version and units: v1 only; its speeds are mph and angles degrees whatever
  // the distance unit ("Yards" or "Meters"), so any other word is a client we do not speak.
  if (const nlohmann::json* v = field(j, "APIversion"); v != nullptr) {
    const std::string text = v->is_string() ? v->get<std::string>() : v->dump();
    if (text != "1") throw InputError("message.APIversion = " + v->dump() + ": this server speaks Open Connect v1 (\"1\")");
  }
  if (const nlohmann::json* u = field(j, "Units"); u != nullptr) {
    const std::string text = u->is_string() ? ascii_lower(u->get<std::string>()) : std::string();
    if (text != "yards" && text != "meters")
      throw InputError("message.Units = " + u->dump() + " (allowed: \"Yards\", \"Meters\")");
  }
  const nlohmann::json* opts = field(j, "ShotDataOptions");
  // Options that are not an object would read as "no options": a shot's data dropped.
  if (opts != nullptr && !opts->is_object())
    throw InputError("message.ShotDataOptions = " + opts->dump().substr(0, 40) + ": not an object (send {\"ContainsBallData\": true, ...})");
  for (const char* key : {"BallData", "ClubData"})
    if (const nlohmann::json* d = field(j, key); d != nullptr && !d->is_object())
      throw InputError(std::string("message.") + key + " = " + d->dump().substr(0, 40) + ": not an object");
  const nlohmann::json empty = nlohmann::json::object();
  const nlohmann::json& o = opts ? *opts : empty;
  const bool has_ball = flag(o, "ContainsBallData", "ShotDataOptions") || (opts == nullptr && field(j, "BallData") != nullptr);
  const bool has_club = flag(o, "ContainsClubData", "ShotDataOptions");
  m.ready = flag(o, "LaunchMonitorIsReady", "ShotDataOptions");
  m.ball_detected = flag(o, "LaunchMonitorBallDetected", "ShotDataOptions");
  if (!has_ball && !has_club) {
    m.kind = flag(o, "IsHeartBeat", "ShotDataOptions") ? OcMessage::Kind::Heartbeat : OcMessage::Kind::Status;
    return m;
  }
  m.kind = OcMessage::Kind::Shot;
  if (has_ball) {
    const nlohmann::json* b = field(j, "BallData");
    if (b == nullptr || !b->is_object()) throw InputError("ContainsBallData is true but BallData is missing");
    OcBallData ball;
    // Ranges: a ball speed up to 250 mph and spins to 20000 rpm cover every launch monitor.
    const auto speed = number(*b, "Speed", "BallData", 0.0, 250.0, "mph");
    if (!speed) throw InputError("BallData.Speed is missing");
    ball.speed_mph = *speed;
    // A launch angle is what makes a shot: a message without one is refused, never flown
    // as a 0° skimmer. A missing HLA is a straight shot (some connectors omit it then).
    const auto vla = number(*b, "VLA", "BallData", -90.0, 90.0, "deg");
    if (!vla) throw InputError("BallData.VLA is missing");
    ball.vla_deg = *vla;
    ball.hla_deg = number(*b, "HLA", "BallData", -90.0, 90.0, "deg").value_or(0.0);
    const auto total = number(*b, "TotalSpin", "BallData", 0.0, 20000.0, "rpm");
    const auto axis = number(*b, "SpinAxis", "BallData", -180.0, 180.0, "deg");
    const auto back = number(*b, "BackSpin", "BallData", -20000.0, 20000.0, "rpm");
    const auto side = number(*b, "SideSpin", "BallData", -20000.0, 20000.0, "rpm");
    if (!total && !back && !side)
      throw InputError("BallData has no spin: give TotalSpin (and SpinAxis), or BackSpin and SideSpin");
    // Both forms given: TotalSpin and SpinAxis win. They need not agree with BackSpin and
    // SideSpin: the vendor page's own example sends 3250 rpm with 2500 back and -800 side
    // (2625 rpm together), so refusing a disagreement would refuse the reference message.
    if (total && *total > 0.0) {
      ball.total_spin_rpm = *total;
      ball.spin_axis_deg = axis.value_or(back && side ? std::atan2(*side, *back) * 180.0 / 3.14159265358979323846 : 0.0);
    } else if (back || side) {
      // Back and side spin instead of total and axis (the page allows either).
      const double bs = back.value_or(0.0), ss = side.value_or(0.0);
      ball.total_spin_rpm = std::hypot(bs, ss);
      ball.spin_axis_deg = std::atan2(ss, bs) * 180.0 / 3.14159265358979323846;
    } else {
      ball.total_spin_rpm = 0.0;
      ball.spin_axis_deg = axis.value_or(0.0);
    }
    if (ball.total_spin_rpm > 20000.0) throw InputError("BallData spin is beyond 20000 rpm");
    m.ball = ball;
  }
  if (has_club) {
    if (const nlohmann::json* c = field(j, "ClubData"); c && c->is_object()) {
      OcClubData club;
      club.speed_mph = number(*c, "Speed", "ClubData", 0.0, 250.0, "mph");
      club.angle_of_attack_deg = number(*c, "AngleOfAttack", "ClubData", -45.0, 45.0, "deg");
      club.face_to_target_deg = number(*c, "FaceToTarget", "ClubData", -45.0, 45.0, "deg");
      club.path_deg = number(*c, "Path", "ClubData", -45.0, 45.0, "deg");
      club.loft_deg = number(*c, "Loft", "ClubData", -10.0, 90.0, "deg");
      club.lie_deg = number(*c, "Lie", "ClubData", -90.0, 90.0, "deg");
      club.vertical_impact_mm = number(*c, "VerticalFaceImpact", "ClubData", -100.0, 100.0, "mm");
      club.horizontal_impact_mm = number(*c, "HorizontalFaceImpact", "ClubData", -100.0, 100.0, "mm");
      club.closure_rate_dps = number(*c, "ClosureRate", "ClubData", -20000.0, 20000.0, "deg/s");
      m.club = club;
    }
  }
  if (!m.ball) throw InputError("a shot needs BallData (ClubData alone cannot be flown)");
  return m;
}

namespace {
// Compact JSON; bytes that are not UTF-8 (a parse error quotes what the client sent) become
// U+FFFD instead of making the serializer throw (which would take the server down).
std::string compact(const nlohmann::json& j) { return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }
}  // namespace

std::string reply_shot(bool with_club) {
  return compact({{"Code", 200}, {"Message", with_club ? "Club & Ball Data received" : "Ball Data received"}, {"Player", nullptr}});
}

std::string reply_player(const std::string& handed, const std::string& club_code, std::optional<double> distance_yd) {
  nlohmann::json player = {{"Handed", handed}, {"Club", club_code}};
  if (distance_yd) player["DistanceToTarget"] = *distance_yd;
  return compact({{"Code", 201}, {"Message", "GSPro Player Information"}, {"Player", player}});
}

std::string reply_status(int code, const std::string& message) {
  return compact({{"Code", code}, {"Message", message}, {"Player", nullptr}});
}

std::string gspro_club_code(const std::string& c) {
  if (c == "driver") return "DR";
  if (c == "putter") return "PT";
  if (c == "pw") return "PW";
  if (c == "sw") return "SW";
  if (c == "lw") return "LW";
  if (c == "hybrid") return "H3";
  // "3-wood" -> "W3", "7-iron" -> "I7" (built char by char: GCC 12 warns falsely on "W" + string).
  const auto ends_with = [&](const char* tail) { return c.size() == 6 && c.compare(1, 5, tail) == 0; };
  if (ends_with("-wood")) return std::string{'W', c[0]};
  if (ends_with("-iron")) return std::string{'I', c[0]};
  return "DR";
}

}  // namespace sweetspot
