// `sweetspot connect` (DESIGN §10): a GSPro Open Connect v1 server on standalone Asio.
//
// One launch monitor at a time, as GSPro: a second client gets a 503 reply and is closed,
// unless the current one has gone (its close read within 250 ms of the knock, so a quick
// reconnect is served), sent no whole message for a minute (a dead connection), or held an
// unfinished message for 3 s (cut off, or trickling bytes): then it is replaced.
// The byte stream is cut into messages by MessageFramer (bounded; every whole message after
// a broken one is still found, and each broken part answered once); each shot is answered
// with 200 ("Ball Data received" / "Club & Ball Data received") and played by a ShotTable,
// its line (DESIGN §10) written to `out`; heartbeats and status ("ready") messages are
// answered with 200 and play nothing (real GSPro is silent to them; here every message is
// answered, and no connector is confused by a 200 it did not wait for: they
// drain or ignore unsolicited bytes); a malformed or oversized message gets 501 "Bad format"
// and the connection stays up. The player information (201) goes out on connect and
// whenever the club the game expects changes, in its own write once the client has been
// quiet for 50 ms (so it never overtakes the 200 a connector is waiting for); 203 "GSPro
// round ended" when a round is over. A client that half-closes (sends its last bytes and
// shuts its side) gets every reply before the close. A client silent for `idle_timeout` is
// closed; SIGINT and SIGTERM close the sockets and make run() return 0. With max_shots the
// server plays exactly that many shots: messages after the last are not answered.
//
// Single-threaded: every handler runs on the thread that calls run() (or poll(), for the
// window, which drives the server from its frame loop).
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>

#include "game/content/assets.hpp"
#include "game/net/shot_table.hpp"

namespace sweetspot {

struct ConnectOptions {
  std::string bind = "127.0.0.1";  ///< the vendor's page: the connector runs on the same PC
  int port = 921;                  ///< GSPro's port; below 1024 needs root on Linux (0 = any free port)
  static constexpr int kMaxPort = 65535;
  ShotTableOptions table;
  /// s without a byte before a client is dropped. Some connectors never send a heartbeat
  /// (MLM2Pro, travislang) and never reconnect, so this outlasts any pause in a round.
  double idle_timeout = 1800.0;
  static constexpr double kMinIdle = 1.0, kMaxIdle = 86400.0;
  std::size_t max_message = 64 * 1024;  ///< bytes; the largest real message is ~1.2 KB
  int max_shots = 0;               ///< return after this many shots have been answered (tests, replays; 0 = never)
  bool handle_signals = true;      ///< SIGINT/SIGTERM stop the server (false in unit tests)
  /// Append every shot message received, compacted to one line, to this file ("" = none):
  /// the session, to be played back with `sweetspot send`. Each line is written whole and
  /// flushed as it arrives, so a crash keeps the shots before it.
  std::string record;
};

class ConnectServer {
 public:
  /// Opens the table and binds the port. Throws InputError for a bad course, world, address
  /// or port, and when the port cannot be bound (with the system's reason).
  ConnectServer(const Assets& assets, const ConnectOptions& o, std::ostream& out, std::ostream& log);
  ~ConnectServer();
  ConnectServer(const ConnectServer&) = delete;
  ConnectServer& operator=(const ConnectServer&) = delete;

  /// The port listened on (the chosen one when the options said 0).
  int port() const;
  /// Serves until stop(), a signal or max_shots. Returns 0, or 2 when --record failed.
  int run();
  /// Runs the handlers that are ready, without waiting (the window's frame loop).
  void poll();
  /// Thread-safe: makes run() return soon.
  void stop();
  /// True once stopped (a signal, stop(), max_shots).
  bool stopped() const;
  /// Shots answered so far.
  int shots() const;
  /// The table the shots play (the window draws its round).
  const ShotTable& table() const;
  /// Called on the serving thread after each shot is played (the window draws it).
  void on_shot(std::function<void(const ShotTable::Played&)> f);

  struct Impl;  ///< opaque (the sessions of connect_server.cpp share it)

 private:
  std::shared_ptr<Impl> impl_;
};

}  // namespace sweetspot
