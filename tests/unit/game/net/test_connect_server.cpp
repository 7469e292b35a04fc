// The Open Connect server over loopback: a real TCP client (POSIX sockets, as a connector
// is) against ConnectServer running on its own thread, on a port the system picks.
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <deque>
#include <optional>
#include <sstream>
#include <string>
#include <memory>
#include <thread>

#include "game/net/connect_server.hpp"
#include "game/net/message_framer.hpp"
#include "game/net/open_connect.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

std::string shot(int number, double mph = 120.0, double vla = 16.0, double rpm = 6000.0) {
  return R"({"DeviceID":"loopback","Units":"Yards","ShotNumber":)" + std::to_string(number) +
         R"(,"APIversion":"1","BallData":{"Speed":)" + std::to_string(mph) + R"(,"VLA":)" + std::to_string(vla) +
         R"(,"HLA":0.5,"TotalSpin":)" + std::to_string(rpm) +
         R"(,"SpinAxis":-2},"ShotDataOptions":{"ContainsBallData":true,"ContainsClubData":false}})";
}
const std::string kHeartbeat =
    R"({"DeviceID":"loopback","ShotNumber":0,"APIversion":"1","ShotDataOptions":{"ContainsBallData":false,)"
    R"("ContainsClubData":false,"IsHeartBeat":true}})";

// A connector: blocking socket, 5 s receive timeout, replies framed as the server frames.
class Client {
 public:
  explicit Client(int port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    timeval tv{5, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    int one = 1;
    ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  }
  ~Client() { close(); }
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  bool connected() const { return connected_; }
  /// Half-closes: no more bytes from us, replies still read.
  void shutdown_write() { ::shutdown(fd_, SHUT_WR); }
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  bool send(const std::string& bytes) {
    std::size_t at = 0;
    while (at < bytes.size()) {
      const ssize_t n = ::send(fd_, bytes.data() + at, bytes.size() - at, MSG_NOSIGNAL);
      if (n <= 0) return false;
      at += static_cast<std::size_t>(n);
    }
    return true;
  }
  /// The next reply, or nullopt when the server closed the connection or 5 s passed.
  std::optional<nlohmann::json> next() {
    while (replies_.empty()) {
      char buf[4096];
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) {
        eof_ = n == 0;
        return std::nullopt;
      }
      for (auto& p : framer_.feed(std::string_view(buf, static_cast<std::size_t>(n))))
        if (p.kind == MessageFramer::Piece::Kind::Message) replies_.push_back(nlohmann::json::parse(p.text));
    }
    auto r = replies_.front();
    replies_.pop_front();
    return r;
  }
  /// The next reply whose Code is `code`, skipping others (201 player information).
  std::optional<nlohmann::json> next_with(int code) {
    for (auto r = next(); r; r = next())
      if ((*r)["Code"] == code) return r;
    return std::nullopt;
  }
  bool closed_by_server() {
    while (next()) {
    }
    return eof_;
  }

 private:
  int fd_ = -1;
  bool connected_ = false, eof_ = false;
  MessageFramer framer_{1 << 20};
  std::deque<nlohmann::json> replies_;
};

// The server on its own thread; finish() stops it and makes its output readable.
struct Served {
  std::ostringstream out, log;
  ConnectServer server;
  std::thread thread;
  explicit Served(ConnectOptions o = defaults()) : server(test::assets(), o, out, log), thread([this] { server.run(); }) {}
  ~Served() { finish(); }
  static ConnectOptions defaults() {
    ConnectOptions o;
    o.port = 0;
    o.handle_signals = false;
    o.table.world = "none";
    return o;
  }
  void finish() {
    if (!thread.joinable()) return;
    server.stop();
    thread.join();
  }
  int lines() const {
    int n = 0;
    for (const char c : out.str()) n += c == '\n';
    return n;
  }
};

}  // namespace

TEST_CASE("the page's example shot gets 200 and a result line", "[net][server][reference]") {
  Served s;
  Client c(s.server.port());
  REQUIRE(c.connected());
  const auto hello = c.next();  // the player information on connect
  REQUIRE(hello);
  CHECK((*hello)["Code"] == 201);
  CHECK((*hello)["Player"]["Club"] == "DR");
  REQUIRE(c.send(shot(13, 147.5, 14.3, 3250.0)));
  const auto ok = c.next();
  REQUIRE(ok);
  CHECK((*ok)["Code"] == 200);
  CHECK((*ok)["Message"] == "Ball Data received");
  REQUIRE(c.send(kHeartbeat));
  const auto hb = c.next();
  REQUIRE(hb);
  CHECK((*hb)["Code"] == 200);
  // A misread's zeros: received (200, as GSPro), and the reply says they were not flown.
  REQUIRE(c.send(shot(14, 0.0, 0.0, 0.0)));
  const auto zero = c.next();
  REQUIRE(zero);
  CHECK((*zero)["Code"] == 200);
  CHECK((*zero)["Message"] == "Shot received: no ball speed, not flown");
  s.finish();
  REQUIRE(s.lines() == 1);  // the heartbeat and the zeros played nothing
  const auto line = nlohmann::json::parse(s.out.str());
  CHECK(line["shot_number"] == 13);
  CHECK(line["launch"]["spin_rpm"].get<double>() == Approx(3250.0));
  CHECK(line["flight"]["carry_m"].get<double>() > 150.0);
}

TEST_CASE("split and concatenated messages are each answered once", "[net][server]") {
  Served s;
  Client c(s.server.port());
  REQUIRE(c.next_with(201));
  // One message in three TCP segments.
  const std::string m = shot(1);
  REQUIRE(c.send(m.substr(0, 10)));
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  REQUIRE(c.send(m.substr(10, 100)));
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  REQUIRE(c.send(m.substr(110)));
  CHECK(c.next_with(200));
  // Three messages and a heartbeat in one segment (what gc2-connect-desktop does).
  REQUIRE(c.send(kHeartbeat + shot(2) + shot(3) + "\n" + shot(4)));
  int oks = 0;
  for (int i = 0; i < 4; ++i) oks += c.next_with(200).has_value();
  CHECK(oks == 4);
  s.finish();
  CHECK(s.lines() == 4);
}

TEST_CASE("garbage and bad numbers get 501 and the connection stays up", "[net][server][hostile]") {
  Served s;
  Client c(s.server.port());
  REQUIRE(c.next_with(201));
  REQUIRE(c.send("GET / HTTP/1.1\r\n\r\n"));
  auto bad = c.next();
  REQUIRE(bad);
  CHECK((*bad)["Code"] == 501);
  CHECK((*bad)["Message"].get<std::string>().rfind("Bad format", 0) == 0);
  REQUIRE(c.send(R"({"ShotNumber":1,"BallData":{"Speed":1e300},"ShotDataOptions":{"ContainsBallData":true}})"));
  bad = c.next();
  REQUIRE(bad);
  CHECK((*bad)["Code"] == 501);
  CHECK((*bad)["Message"].get<std::string>().find("BallData.Speed") != std::string::npos);
  REQUIRE(c.send(shot(2)));
  CHECK(c.next_with(200));
}

TEST_CASE("a 10 MB message is refused and the next shot is played", "[net][server][hostile]") {
  Served s;
  Client c(s.server.port());
  REQUIRE(c.next_with(201));
  const std::string big = R"({"DeviceID":")" + std::string(10 * 1024 * 1024, 'A') + R"("})";
  REQUIRE(c.send(big + shot(5)));
  const auto bad = c.next();
  REQUIRE(bad);
  CHECK((*bad)["Code"] == 501);
  CHECK((*bad)["Message"].get<std::string>().find("longer than 65536 bytes") != std::string::npos);
  CHECK(c.next_with(200));
  s.finish();
  CHECK(s.lines() == 1);
}

TEST_CASE("a client that disconnects mid-message leaves the server serving", "[net][server][hostile]") {
  Served s;
  {
    Client a(s.server.port());
    REQUIRE(a.next_with(201));
    const std::string m = shot(1);
    REQUIRE(a.send(m.substr(0, m.size() / 2)));
  }  // closed with half a message sent
  // The server notices the close and takes the next connector (retry while it has not yet).
  std::optional<nlohmann::json> ok;
  for (int attempt = 0; attempt < 50 && !ok; ++attempt) {
    Client b(s.server.port());
    const auto first = b.next();
    if (first && (*first)["Code"] == 201) {
      REQUIRE(b.send(shot(2)));
      ok = b.next_with(200);
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  CHECK(ok);
  s.finish();
  CHECK(s.lines() == 1);
}

TEST_CASE("a second launch monitor is refused politely while the first plays on", "[net][server]") {
  Served s;
  Client a(s.server.port());
  REQUIRE(a.next_with(201));
  Client b(s.server.port());
  const auto no = b.next();
  REQUIRE(no);
  CHECK((*no)["Code"] == 503);
  CHECK((*no)["Message"] == "Another launch monitor is connected");
  CHECK(b.closed_by_server());
  REQUIRE(a.send(shot(1)));
  CHECK(a.next_with(200));
}

TEST_CASE("a silent client times out", "[net][server]") {
  ConnectOptions o = Served::defaults();
  o.idle_timeout = 1.0;
  Served s(o);
  Client c(s.server.port());
  REQUIRE(c.next_with(201));
  const auto t0 = std::chrono::steady_clock::now();
  CHECK(c.closed_by_server());
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(waited > 0.8);
  CHECK(waited < 4.0);
  s.finish();
  CHECK(s.log.str().find("timed out") != std::string::npos);
}

TEST_CASE("the idle timeout is checked", "[net][server][hostile]") {
  ConnectOptions o = Served::defaults();
  o.idle_timeout = 0.0;
  std::ostringstream out, log;
  CHECK_THROWS_WITH(ConnectServer(test::assets(), o, out, log), Catch::Contains("--idle-timeout") && Catch::Contains("86400"));
  o = Served::defaults();
  o.port = 70000;
  CHECK_THROWS_WITH(ConnectServer(test::assets(), o, out, log), Catch::Contains("--port"));
  o = Served::defaults();
  o.bind = "not-an-address";
  CHECK_THROWS_WITH(ConnectServer(test::assets(), o, out, log), Catch::Contains("--bind"));
}

TEST_CASE("10000 shots in a row leave the server healthy", "[net][server][soak]") {
  Served s;
  Client c(s.server.port());
  REQUIRE(c.next_with(201));
  constexpr int kShots = 10000;
  int oks = 0;
  for (int i = 1; i <= kShots; ++i) {
    // A spread of real shots: chips to drives, draws and fades.
    const double mph = 20.0 + (i * 37) % 150;
    const double vla = 8.0 + (i * 13) % 30;
    const double rpm = 1500.0 + (i * 211) % 8000;
    if (!c.send(shot(i, mph, vla, rpm))) break;
    const auto r = c.next_with(200);
    if (!r) break;
    ++oks;
  }
  CHECK(oks == kShots);
  s.finish();
  CHECK(s.server.shots() == kShots);
  CHECK(s.lines() == kShots);
  // Every line is whole and its numbers finite (a NaN would be written as null).
  std::istringstream lines(s.out.str());
  int checked = 0;
  for (std::string line; std::getline(lines, line);) {
    const auto j = nlohmann::json::parse(line);
    for (const char* key : {"carry_m", "total_m", "apex_m", "hang_time_s"})
      if (!j["flight"][key].is_number()) FAIL("shot " << j["shot_number"] << ": flight." << key << " is not a number");
    ++checked;
  }
  CHECK(checked == kShots);
}

TEST_CASE("a client that half-closes after its last shots gets every reply", "[net][server][hostile]") {
  // Before: the server closed on reading the end of the stream, and only the first of the
  // replies (spaced 5 ms apart) went out.
  Served s;
  Client c(s.server.port());
  REQUIRE(c.next_with(201));
  std::string burst;
  for (int i = 1; i <= 5; ++i) burst += shot(i);
  REQUIRE(c.send(burst + R"({"DeviceID":"cut","BallData":{"Speed":1)"));
  c.shutdown_write();
  int ok = 0, bad = 0;
  for (auto r = c.next(); r; r = c.next()) {
    ok += (*r)["Code"] == 200;
    bad += (*r)["Code"] == 501;
  }
  CHECK(ok == 5);
  CHECK(bad == 1);  // the message cut off by the close, answered once
  s.finish();
  CHECK(s.lines() == 5);
}

TEST_CASE("a client that trickles bytes does not hold the slot against a launch monitor", "[net][server][hostile]") {
  // Before: any byte kept the slot, so a client sending one a second held it forever.
  Served s;
  Client trickler(s.server.port());
  REQUIRE(trickler.next_with(201));
  REQUIRE(trickler.send(R"({"DeviceID":"slow","BallData":{"Speed":)"));
  const auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::milliseconds(3500)) {
    REQUIRE(trickler.send("1"));
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  Client monitor(s.server.port());
  REQUIRE(monitor.next_with(201));
  REQUIRE(monitor.send(shot(1)));
  CHECK(monitor.next_with(200));
  CHECK(trickler.closed_by_server());
}

TEST_CASE("a launch monitor that knocks while a client trickles waits and is served, not sent away", "[net][server][hostile]") {
  // Before: a knock 0.5 s into a trickle was answered 503 (the holder not yet stuck), and the
  // launch monitor had to retry. Now the knock waits for the holder's message: finished, the
  // knock is refused; held 3 s, the knock takes the slot.
  Served s;
  Client trickler(s.server.port());
  REQUIRE(trickler.next_with(201));
  REQUIRE(trickler.send(R"({"DeviceID":"slow","BallData":{"Speed":)"));
  std::atomic<bool> stop{false};
  std::thread drip([&] {
    for (int i = 0; i < 24 && !stop; ++i) {
      if (!trickler.send("1")) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  Client monitor(s.server.port());
  const auto first = monitor.next();
  stop = true;
  drip.join();
  REQUIRE(first);
  CHECK((*first)["Code"] == 201);
  REQUIRE(monitor.send(shot(1)));
  CHECK(monitor.next_with(200));
}

TEST_CASE("a knock while the holder finishes its message is refused once it is whole", "[net][server][hostile]") {
  Served s;
  Client holder(s.server.port());
  REQUIRE(holder.next_with(201));
  const std::string whole = shot(1);
  REQUIRE(holder.send(whole.substr(0, 20)));
  Client knocker(s.server.port());
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  REQUIRE(holder.send(whole.substr(20)));
  CHECK(holder.next_with(200));
  const auto reply = knocker.next();
  REQUIRE(reply);
  CHECK((*reply)["Code"] == 503);
}

TEST_CASE("a knock while the holder streams shot after shot is answered within kStuckAfter, not kept waiting",
          "[net][server][hostile]") {
  // The holder finishes each message and at once starts the next, so it is nearly always in
  // the middle of one. Before, the knock waited for a moment when it was not, which such a
  // client never gives: the launch monitor heard nothing for as long as the stream lasted.
  Served s;
  Client holder(s.server.port());
  REQUIRE(holder.next_with(201));
  std::atomic<bool> stop{false};
  std::thread stream([&] {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    std::string rest;
    for (int i = 1; !stop && std::chrono::steady_clock::now() < until; ++i) {
      const std::string whole = shot(i);
      if (!holder.send(rest + whole.substr(0, 20))) break;
      rest = whole.substr(20);
      std::this_thread::sleep_for(std::chrono::milliseconds(150));
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto knocked = std::chrono::steady_clock::now();
  Client knocker(s.server.port());
  const auto reply = knocker.next();
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - knocked).count();
  stop = true;
  stream.join();
  REQUIRE(reply);
  CHECK((*reply)["Code"] == 503);
  CHECK(waited < 4.5);  // kKnockGrace + kStuckAfter = 3.25 s, and scheduling
}

TEST_CASE("a launch monitor that reconnects at once is served, not refused", "[net][server][hostile]") {
  // Before: about half of quick reconnects got 503 before the old socket's close was read.
  Served s;
  for (int round = 0; round < 20; ++round) {
    auto a = std::make_unique<Client>(s.server.port());
    REQUIRE(a->next_with(201));
    a.reset();  // closed
    Client b(s.server.port());
    const auto first = b.next();
    REQUIRE(first);
    INFO("round " << round);
    CHECK((*first)["Code"] == 201);
  }
}

TEST_CASE("--max-shots plays exactly that many shots, a burst included", "[net][server][hostile]") {
  ConnectOptions o = Served::defaults();
  o.max_shots = 3;
  Served s(o);
  Client c(s.server.port());
  REQUIRE(c.next_with(201));
  std::string burst;
  for (int i = 1; i <= 6; ++i) burst += shot(i);
  REQUIRE(c.send(burst));
  int ok = 0;
  for (auto r = c.next(); r; r = c.next()) ok += (*r)["Code"] == 200;
  CHECK(ok == 3);
  s.finish();
  CHECK(s.server.shots() == 3);
  CHECK(s.lines() == 3);
}

TEST_CASE("--max-shots ends the server even when the client closes at once", "[net][server][hostile]") {
  // The greeting (201) may still be waiting when the last 200 is out; a client that closes
  // then must not leave the server running forever.
  ConnectOptions o = Served::defaults();
  o.max_shots = 1;
  Served s(o);
  {
    Client c(s.server.port());
    REQUIRE(c.send(shot(1)));
    c.shutdown_write();
  }
  const auto t0 = std::chrono::steady_clock::now();
  while (!s.server.stopped() && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(5))
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  CHECK(s.server.stopped());
  s.finish();
  CHECK(s.server.shots() == 1);
}

TEST_CASE("a flag sent as a string is refused, not answered and dropped", "[net][server][hostile]") {
  Served s;
  Client c(s.server.port());
  REQUIRE(c.next_with(201));
  std::string quoted = shot(1);
  quoted.replace(quoted.find("\"ContainsBallData\":true"), 23, "\"ContainsBallData\":\"true\"");
  REQUIRE(c.send(quoted));
  const auto r = c.next();
  REQUIRE(r);
  CHECK((*r)["Code"] == 501);
  CHECK((*r)["Message"].get<std::string>().find("ContainsBallData") != std::string::npos);
  s.finish();
  CHECK(s.lines() == 0);
}
