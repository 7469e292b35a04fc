// libFuzzer target: the Open Connect stream a launch monitor (or anyone on the port) sends.
// The bytes go through the framer in pieces cut where the input says (as TCP may cut them),
// each framed message through the parser. Nothing may crash, hang or throw anything but
// InputError; the framer's memory stays bounded; a parsed shot has finite numbers inside
// the protocol's ranges; every reply is valid compact JSON.
// The resynchronisation property (issue 42): the input (up to 64 KiB) as a garbage prefix,
// then a valid shot: the shot is framed exactly once, as the last message, and parses.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/net/message_framer.hpp"
#include "game/net/open_connect.hpp"
#include "physics/error.hpp"

namespace {

void check_shot(const sweetspot::OcMessage& m) {
  if (m.kind != sweetspot::OcMessage::Kind::Shot) return;
  if (!m.ball) std::abort();  // a shot always carries BallData
  const auto& b = *m.ball;
  for (const double v : {b.speed_mph, b.vla_deg, b.hla_deg, b.total_spin_rpm, b.spin_axis_deg})
    if (!std::isfinite(v)) std::abort();
  if (b.speed_mph < 0.0 || b.speed_mph > 250.0 || b.total_spin_rpm < 0.0 || b.total_spin_rpm > 20000.0) std::abort();
  if (m.club && m.club->speed_mph && !std::isfinite(*m.club->speed_mph)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // First byte: how the stream is cut into "packets" (1..256 bytes each) and the framer's
  // size bound (small bounds exercise the oversized path).
  const std::size_t packet = 1 + data[0];
  const std::size_t max_bytes = (data[0] & 1) ? 64 : 64 * 1024;
  const std::string_view stream(reinterpret_cast<const char*>(data + 1), size - 1);
  sweetspot::MessageFramer framer(max_bytes);
  for (std::size_t at = 0; at < stream.size(); at += packet) {
    for (const auto& piece : framer.feed(stream.substr(at, packet))) {
      if (piece.kind != sweetspot::MessageFramer::Piece::Kind::Message) {
        if (piece.text.size() > 64) std::abort();  // excerpts only
        continue;
      }
      if (piece.text.size() > max_bytes || piece.text.empty() || piece.text.front() != '{') std::abort();
      try {
        check_shot(sweetspot::parse_open_connect(piece.text));
      } catch (const sweetspot::InputError& e) {
        // The reply carries the reason: it must still be valid JSON.
        const auto reply = nlohmann::json::parse(sweetspot::reply_status(501, e.what()), nullptr, false);
        if (reply.is_discarded()) std::abort();
      }
    }
    if (framer.pending() > max_bytes + 1) std::abort();
  }
  for (const auto& piece : framer.finish())
    if (piece.kind == sweetspot::MessageFramer::Piece::Kind::Message && piece.text.size() > max_bytes) std::abort();
  if (framer.pending() != 0) std::abort();

  static const std::string kShot =
      R"({"DeviceID":"fuzz-property-7f3a","ShotNumber":9,"BallData":{"Speed":150,"VLA":12,"TotalSpin":3000},)"
      R"("ShotDataOptions":{"ContainsBallData":true}})";
  const std::string resync = std::string(stream.substr(0, 64 * 1024)) + kShot;
  sweetspot::MessageFramer again;
  std::vector<std::string> found;
  const auto take = [&](const std::vector<sweetspot::MessageFramer::Piece>& pieces) {
    for (const auto& p : pieces)
      if (p.kind == sweetspot::MessageFramer::Piece::Kind::Message) found.push_back(p.text);
  };
  for (std::size_t at = 0; at < resync.size(); at += packet) take(again.feed(std::string_view(resync).substr(at, packet)));
  take(again.finish());
  if (found.empty() || found.back() != kShot) std::abort();
  if (stream.find("fuzz-property-7f3a") == std::string_view::npos &&
      std::count(found.begin(), found.end(), kShot) != 1)
    std::abort();
  if (sweetspot::parse_open_connect(found.back()).kind != sweetspot::OcMessage::Kind::Shot) std::abort();
  return 0;
}
