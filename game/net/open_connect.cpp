#include "game/net/open_connect.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "physics/error.hpp"

namespace sweetspot {

void MessageFramer::start_message() {
  buf_.assign(1, '{');
  depth_ = 1;
  in_string_ = escape_ = skipping_ = false;
  last_ = '{';
}

std::vector<MessageFramer::Piece> MessageFramer::feed(std::string_view bytes) {
  std::vector<Piece> out;
  const auto flush_garbage = [&] {
    if (!garbage_.empty()) {
      out.push_back({Piece::Kind::Garbage, garbage_.substr(0, 64)});
      garbage_.clear();
    }
  };
  const auto is_space = [](char ch) { return std::isspace(static_cast<unsigned char>(ch)) || ch == '\0'; };
  for (const char ch : bytes) {
    if (depth_ == 0 && !skipping_) {
      if (ch == '{') {
        flush_garbage();
        start_message();
      } else if (!is_space(ch)) {
        garbage_ += ch;
        if (garbage_.size() > max_) flush_garbage();
      }
      continue;
    }
    if (skipping_) {
      // After a refused message: drop bytes until the braces balance or a "}{" boundary.
      // Strings are not trusted here (the refused bytes may have opened one and never
      // closed it), so the boundary is looked for in the raw bytes.
      if (ch == '{' && last_ == '}') {
        start_message();
        continue;
      }
      if (!is_space(ch)) last_ = ch;
      if (in_string_) {
        if (escape_) escape_ = false;
        else if (ch == '\\') escape_ = true;
        else if (ch == '"') in_string_ = false;
      } else if (ch == '"') {
        in_string_ = true;
      } else if (ch == '{') {
        depth_ = std::min(depth_ + 1, kSkipDepthCap);
      } else if (ch == '}' && --depth_ <= 0) {
        depth_ = 0;
        skipping_ = false;
        in_string_ = escape_ = false;
      }
      continue;
    }
    if (in_string_) {
      buf_ += ch;
      if (escape_) escape_ = false;
      else if (ch == '\\') escape_ = true;
      else if (ch == '"') in_string_ = false;
    } else if (ch == '{' && last_ == '}') {
      // "}{" inside an unfinished message: that message was cut short. Hand it on (it will
      // not parse) and start the new one here.
      out.push_back({Piece::Kind::Message, std::move(buf_)});
      start_message();
      continue;
    } else {
      buf_ += ch;
      if (!is_space(ch)) last_ = ch;
      if (ch == '"') {
        in_string_ = true;
      } else if (ch == '{') {
        if (++depth_ > kMaxDepth) {
          out.push_back({Piece::Kind::TooDeep, buf_.substr(0, 64)});
          buf_.clear();
          skipping_ = true;
          continue;
        }
      } else if (ch == '}' && --depth_ == 0 && buf_.size() <= max_) {
        out.push_back({Piece::Kind::Message, std::move(buf_)});
        buf_.clear();
        continue;
      }
    }
    if (buf_.size() > max_) {
      out.push_back({Piece::Kind::Oversized, buf_.substr(0, 64)});
      buf_.clear();
      skipping_ = depth_ > 0;  // at depth 0 the refused message is already complete
    }
  }
  flush_garbage();
  return out;
}

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The value under `key` matched without case; nullptr when absent or null.
const nlohmann::json* field(const nlohmann::json& o, const char* key) {
  if (!o.is_object()) return nullptr;
  const std::string want = lower(key);
  for (auto it = o.begin(); it != o.end(); ++it)
    if (lower(it.key()) == want) return it.value().is_null() ? nullptr : &it.value();
  return nullptr;
}

// A number for a message: %g, so 1e308 is not echoed as 309 digits.
std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::optional<double> number(const nlohmann::json& o, const char* key, const char* where, double lo, double hi) {
  const nlohmann::json* v = field(o, key);
  if (v == nullptr) return std::nullopt;
  double d = 0.0;
  if (v->is_number()) d = v->get<double>();
  else if (v->is_string()) {  // some connectors quote their numbers
    try {
      std::size_t used = 0;
      d = std::stod(v->get<std::string>(), &used);
    } catch (const std::exception&) {
      throw InputError(std::string(where) + "." + key + ": not a number");
    }
  } else {
    throw InputError(std::string(where) + "." + key + ": not a number");
  }
  if (!std::isfinite(d) || d < lo || d > hi)
    throw InputError(std::string(where) + "." + key + " = " + short_number(d) + " is out of range (allowed [" +
                     short_number(lo) + ", " + short_number(hi) + "])");
  return d;
}

bool flag(const nlohmann::json& o, const char* key) {
  const nlohmann::json* v = field(o, key);
  return v != nullptr && v->is_boolean() && v->get<bool>();
}

}  // namespace

OcMessage parse_open_connect(std::string_view text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("malformed JSON: ") + e.what());
  }
  if (!j.is_object()) throw InputError("a message must be a JSON object");
  OcMessage m;
  if (const nlohmann::json* d = field(j, "DeviceID"); d && d->is_string()) m.device_id = d->get<std::string>();
  if (const auto n = number(j, "ShotNumber", "message", -1e9, 1e9)) {
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
    const std::string text = u->is_string() ? lower(u->get<std::string>()) : std::string();
    if (text != "yards" && text != "meters")
      throw InputError("message.Units = " + u->dump() + " (allowed: \"Yards\", \"Meters\")");
  }
  const nlohmann::json* opts = field(j, "ShotDataOptions");
  const nlohmann::json empty = nlohmann::json::object();
  const nlohmann::json& o = opts ? *opts : empty;
  const bool has_ball = flag(o, "ContainsBallData") || (opts == nullptr && field(j, "BallData") != nullptr);
  const bool has_club = flag(o, "ContainsClubData");
  m.ready = flag(o, "LaunchMonitorIsReady");
  m.ball_detected = flag(o, "LaunchMonitorBallDetected");
  if (!has_ball && !has_club) {
    m.kind = flag(o, "IsHeartBeat") ? OcMessage::Kind::Heartbeat : OcMessage::Kind::Status;
    return m;
  }
  m.kind = OcMessage::Kind::Shot;
  if (has_ball) {
    const nlohmann::json* b = field(j, "BallData");
    if (b == nullptr || !b->is_object()) throw InputError("ContainsBallData is true but BallData is missing");
    OcBallData ball;
    // Ranges: a ball speed up to 250 mph and spins to 20000 rpm cover every launch monitor.
    const auto speed = number(*b, "Speed", "BallData", 0.0, 250.0);
    if (!speed) throw InputError("BallData.Speed is missing");
    ball.speed_mph = *speed;
    // A launch angle is what makes a shot: a message without one is refused, never flown
    // as a 0° skimmer. A missing HLA is a straight shot (some connectors omit it then).
    const auto vla = number(*b, "VLA", "BallData", -90.0, 90.0);
    if (!vla) throw InputError("BallData.VLA is missing");
    ball.vla_deg = *vla;
    ball.hla_deg = number(*b, "HLA", "BallData", -90.0, 90.0).value_or(0.0);
    const auto total = number(*b, "TotalSpin", "BallData", 0.0, 20000.0);
    const auto axis = number(*b, "SpinAxis", "BallData", -180.0, 180.0);
    const auto back = number(*b, "BackSpin", "BallData", -20000.0, 20000.0);
    const auto side = number(*b, "SideSpin", "BallData", -20000.0, 20000.0);
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
      club.speed_mph = number(*c, "Speed", "ClubData", 0.0, 250.0);
      club.angle_of_attack_deg = number(*c, "AngleOfAttack", "ClubData", -45.0, 45.0);
      club.face_to_target_deg = number(*c, "FaceToTarget", "ClubData", -45.0, 45.0);
      club.path_deg = number(*c, "Path", "ClubData", -45.0, 45.0);
      club.loft_deg = number(*c, "Loft", "ClubData", -10.0, 90.0);
      club.lie_deg = number(*c, "Lie", "ClubData", -90.0, 90.0);
      club.vertical_impact_mm = number(*c, "VerticalFaceImpact", "ClubData", -100.0, 100.0);
      club.horizontal_impact_mm = number(*c, "HorizontalFaceImpact", "ClubData", -100.0, 100.0);
      club.closure_rate_dps = number(*c, "ClosureRate", "ClubData", -20000.0, 20000.0);
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
