#include "game/net/connect_server.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>

#include <asio.hpp>

#include "game/net/message_framer.hpp"
#include "game/net/session_file.hpp"
#include "game/util/terminal_text.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

using asio::ip::tcp;
using Clock = std::chrono::steady_clock;

// Replies produced by one read go out this far apart: connectors that parse one JSON object
// per recv() (the Node and PiTrac clients) fail on replies that arrive
// coalesced. 5 ms is far below any connector's reply timeout (the strictest waits 2 s).
constexpr auto kReplyGap = std::chrono::milliseconds(5);
// The player information (201, on connect and on a club change) goes out only once the
// client has been quiet this long. Connectors take the first object they read after a send
// as its answer (gc2-connect-desktop: raw_decode of one recv; MLM: one recv), so a 201 must
// never overtake the 200 of a message already on its way: gc2-connect-desktop connects and
// writes a heartbeat and a shot back to back (< 1 ms apart), which a greeting sent at once
// would precede. 50 ms is above such gaps and below MLM's 250 ms poller that handles 201.
constexpr auto kPlayerInfoQuiet = std::chrono::milliseconds(50);
// A client that stops reading while we queue more than this is dropped (a reply is ~60 B).
constexpr std::size_t kMaxQueuedBytes = 1 << 20;
// A connection silent this long is presumed dead when another launch monitor knocks: a
// connector whose PC lost its Wi-Fi or slept leaves a socket with no FIN behind, and it
// reconnects within ~5 s (the R10 adapter, travislang) - without this it would be refused
// until the idle timeout. A live connector between shots is silent too, but then nobody
// else is knocking. 60 s is longer than any connector's heartbeat period (3-6 s).
constexpr auto kStaleAfter = std::chrono::seconds(60);
// A client that has held an unfinished message this long is stuck (cut off, or trickling a
// byte at a time): it does not keep the slot from a launch monitor that knocks. Connectors
// write each message whole, in one send.
constexpr auto kStuckAfter = std::chrono::seconds(3);
// Bytes of an unfinished message that then sat this long without another byte are looked
// through for a whole message that began inside them (MessageFramer::flush_stalled): a
// message cut short and followed by a shot is answered although the sender waits.
constexpr auto kStallAfter = std::chrono::seconds(2);
// A knock while the slot is held is decided this much later: a launch monitor that drops
// and reconnects at once is served once its old socket's close has been read.
constexpr auto kKnockGrace = std::chrono::milliseconds(250);

// What a client sent, made safe for a terminal (an escape sequence could rewrite the
// operator's screen) and short.
std::string printable(std::string_view text) { return terminal_safe(text.substr(0, 200)); }

std::string endpoint_text(const tcp::socket& s) {
  asio::error_code ec;
  const tcp::endpoint e = s.remote_endpoint(ec);
  return ec ? std::string("?") : e.address().to_string() + ":" + std::to_string(e.port());
}

}  // namespace

class Session;

struct ConnectServer::Impl : std::enable_shared_from_this<ConnectServer::Impl> {
  const Assets& assets;
  ConnectOptions options;
  std::ostream& out;
  std::ostream& log;
  ShotTable table;
  asio::io_context io;
  tcp::acceptor acceptor{io};
  std::optional<asio::signal_set> signals;
  std::weak_ptr<Session> current;
  std::function<void(const ShotTable::Played&)> shot_hook;
  std::ofstream record;
  bool record_failed = false;
  std::uintmax_t record_bytes = 0;  ///< the record file's size after its last whole line
  int shots = 0;
  bool stopping = false;

  Impl(const Assets& a, const ConnectOptions& o, std::ostream& out_, std::ostream& log_)
      : assets(a), options(o), out(out_), log(log_), table(a, o.table) {}

  bool stopping_all = false;  ///< shutdown() ran: knocks still waiting are dropped

  void listen();
  void accept();
  void decide_knock(std::shared_ptr<tcp::socket> knock, Clock::duration after, Clock::time_point deadline);
  void take(tcp::socket socket);
  void refuse(tcp::socket socket);
  void shutdown();
};

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, ConnectServer::Impl& server)
      : socket_(std::move(socket)), server_(server), idle_(server.io), gap_(server.io), player_(server.io),
        stall_(server.io), framer_(server.options.max_message), peer_(endpoint_text(socket_)) {}

  void start() {
    asio::error_code ec;
    socket_.set_option(tcp::no_delay(true), ec);  // one reply per segment, sent at once
    server_.log << "sweetspot connect: " << peer_ << " connected; " << server_.table.where() << "\n";
    last_heard_ = last_message_ = Clock::now();
    arm_idle();
    want_player_info();  // the greeting: which club the game expects
    read();
  }

  void close(const std::string& why) {
    if (closed_) return;
    closed_ = true;
    server_.log << "sweetspot connect: " << peer_ << " " << why << "\n";
    asio::error_code ec;
    socket_.shutdown(tcp::socket::shutdown_both, ec);
    socket_.close(ec);
    idle_.cancel();
    gap_.cancel();
    player_.cancel();
    stall_.cancel();
  }

  bool open() const { return !closed_; }
  /// The client sent its last bytes; its replies may still be going out.
  bool half_closed() const { return read_closed_; }
  /// May a launch monitor that knocks take this one's place? When it has gone (its close
  /// read), sent no whole message for kStaleAfter, or held an unfinished one for kStuckAfter.
  bool replaceable() const {
    return closed_ || read_closed_ || Clock::now() - last_message_ >= kStaleAfter ||
           (framer_.pending() > 0 && until_stuck() == Clock::duration::zero());
  }
  bool idle_writer() const { return out_.empty() && !writing_; }
  /// How long until an unfinished message makes this one replaceable (zero when none is
  /// unfinished): a knock meanwhile waits for it rather than being refused at once.
  Clock::duration until_stuck() const {
    if (framer_.pending() == 0) return Clock::duration::zero();
    return std::max(Clock::duration::zero(), pending_since_ + kStuckAfter - Clock::now());
  }

 private:
  void read() {
    auto self = shared_from_this();
    socket_.async_read_some(asio::buffer(buf_), [this, self](const asio::error_code& ec, std::size_t n) {
      if (closed_) return;
      if (ec == asio::error::eof) {
        // The client has sent its last bytes (it may still read): answer everything it
        // sent, a message cut off at the end included, then close once the replies are out.
        read_closed_ = true;
        player_due_ = false;
        stall_.cancel();
        guarded([&] { handle_pieces(framer_.finish()); });
        if (idle_writer()) finish_writing();
        return;
      }
      if (ec) {
        close("dropped: " + ec.message());
        return;
      }
      last_heard_ = Clock::now();
      const bool was_pending = framer_.pending() > 0;
      const std::uint64_t candidate = framer_.candidates();
      guarded([&] { handle_pieces(framer_.feed(std::string_view(buf_.data(), n))); });
      if (framer_.pending() > 0 && !closed_) {
        // Since when the unfinished message now held has been coming: a new one restarts it.
        if (!was_pending || framer_.candidates() != candidate) pending_since_ = last_heard_;
        arm_stall();
      }
      if (!closed_) read();
    });
  }

  // A bug of ours must not take the server (and the player's round) down: say so and go on
  // with the next message.
  template <class F>
  void guarded(F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      server_.log << "sweetspot connect: " << peer_ << ": internal error: " << printable(e.what()) << "\n";
      send(reply_status(500, "Internal error"), Clock::duration{0});
    }
  }

  // The sender went quiet with an unfinished message: a whole one that began inside it
  // (the first was cut short) is answered now rather than when more bytes come.
  void arm_stall() {
    auto self = shared_from_this();
    stall_.expires_at(last_heard_ + kStallAfter);
    stall_.async_wait([this, self](const asio::error_code& ec) {
      if (ec || closed_ || read_closed_) return;
      if (Clock::now() - last_heard_ < kStallAfter) return;  // bytes came since: re-armed then
      const std::uint64_t candidate = framer_.candidates();
      guarded([&] { handle_pieces(framer_.flush_stalled()); });
      if (framer_.candidates() != candidate) pending_since_ = last_heard_;
    });
  }

  // Answers what the framer found, each reply kReplyGap after the one before.
  void handle_pieces(const std::vector<MessageFramer::Piece>& pieces) {
    Clock::duration delay{0};
    for (const MessageFramer::Piece& piece : pieces) {
      // Stopping (max_shots): not one shot more is played or answered.
      if (closed_ || server_.stopping) return;
      using Kind = MessageFramer::Piece::Kind;
      if (piece.kind != Kind::Message) {
        const std::string why =
            piece.kind == Kind::Oversized ? "message longer than " + std::to_string(server_.options.max_message) + " bytes"
            : piece.kind == Kind::TooDeep ? "objects nested deeper than " + std::to_string(MessageFramer::kMaxDepth)
            : piece.kind == Kind::Broken  ? "malformed JSON: " + piece.reason
                                          : std::string("bytes outside a JSON object");
        server_.log << "sweetspot connect: " << peer_ << ": bad format: " << printable(why) << " (near '"
                    << printable(piece.text.substr(0, 40)) << "')\n";
        send(reply_status(501, "Bad format: " + why), delay);
        delay += kReplyGap;
        continue;
      }
      last_message_ = Clock::now();
      handle(piece.text, delay);
      delay += kReplyGap;
    }
  }

  void handle(const std::string& text, Clock::duration delay) {
    OcMessage m;
    try {
      m = parse_open_connect(text);
    } catch (const InputError& e) {
      server_.log << "sweetspot connect: " << peer_ << ": bad format: " << printable(e.what()) << "\n";
      send(reply_status(501, std::string("Bad format: ") + e.what()), delay);
      return;
    }
    if (m.kind == OcMessage::Kind::Heartbeat) {
      send(reply_status(200, "Heartbeat received"), delay);
      return;
    }
    if (m.kind == OcMessage::Kind::Status) {
      send(reply_status(200, m.ready ? "Launch monitor ready" : "Status received"), delay);
      return;
    }
    if (server_.record.is_open()) {
      // The message as received, on one line (a connector may pretty-print).
      const std::string line = nlohmann::json::parse(text).dump() + "\n";
      server_.record.write(line.data(), static_cast<std::streamsize>(line.size()));
      server_.record.flush();
      if (!server_.record) {
        // Disk full, a file-size limit: say so now (the shots still play) and exit non-zero.
        server_.log << "sweetspot connect: error: --record " << server_.options.record
                    << ": writing failed (disk full or file too large); recording stopped\n";
        server_.record.close();
        server_.record_failed = true;
        // No half line: cut the file back to its last whole shot.
        std::error_code ec;
        std::filesystem::resize_file(server_.options.record, server_.record_bytes, ec);
      } else {
        server_.record_bytes += line.size();
      }
    }
    ShotTable::Played played;
    try {
      played = server_.table.play(m, static_cast<bool>(server_.shot_hook));
    } catch (const InputError& e) {
      server_.log << "sweetspot connect: " << peer_ << ": shot " << m.shot_number << " refused: " << printable(e.what()) << "\n";
      send(reply_status(501, std::string("Bad format: ") + e.what()), delay);
      return;
    }
    // A misread's zeros are received as GSPro receives them (200), and the reply says they
    // were not flown, so a client is not left to think a shot is in the air.
    send(played.flown ? reply_shot(m.club.has_value()) : reply_status(200, "Shot received: no ball speed, not flown"), delay);
    if (played.flown) {
      server_.out << played.line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n" << std::flush;
      if (server_.shot_hook) server_.shot_hook(played);
    } else {
      server_.log << "sweetspot connect: " << peer_ << ": shot " << m.shot_number << " has no ball speed: not flown\n";
    }
    if (played.round_over) send(reply_status(203, "GSPro round ended"), delay + kReplyGap);
    if (played.club_changed) want_player_info();
    ++server_.shots;
    if (server_.options.max_shots > 0 && server_.shots >= server_.options.max_shots) server_.stopping = true;
  }

  // Every reply is out: stopping (max_shots) ends the server, once the player information
  // is out too (a half-closed client is sent none); a half-closed client is closed.
  void finish_writing() {
    if (server_.stopping) server_.shutdown();
    else if (read_closed_) close("disconnected");
  }

  // Queues a reply to go out no earlier than `delay` from now, after those queued before it.
  void send(std::string text, Clock::duration delay) {
    if (closed_) return;
    queued_bytes_ += text.size();
    if (queued_bytes_ > kMaxQueuedBytes) {
      close("dropped: it does not read its replies");
      return;
    }
    out_.push_back({std::move(text), Clock::now() + delay});
    if (!writing_) write_next();
  }

  void write_next() {
    if (closed_) return;
    if (out_.empty()) {
      writing_ = false;
      if (server_.stopping ? !player_due_ || read_closed_ : read_closed_) finish_writing();
      return;
    }
    writing_ = true;
    auto self = shared_from_this();
    if (Clock::now() < out_.front().not_before) {
      gap_.expires_at(out_.front().not_before);
      gap_.async_wait([this, self](const asio::error_code& ec) {
        if (!ec) write_next();
      });
      return;
    }
    asio::async_write(socket_, asio::buffer(out_.front().text), [this, self](const asio::error_code& ec, std::size_t) {
      if (closed_) return;
      if (ec) {
        close("dropped while writing: " + ec.message());
        return;
      }
      queued_bytes_ -= out_.front().text.size();
      out_.pop_front();
      last_written_ = Clock::now();
      write_next();
    });
  }

  // Sends the 201 once the client has been quiet for kPlayerInfoQuiet (the club as it is
  // then: several changes in a burst give one message).
  void want_player_info() {
    player_due_ = true;
    arm_player(quiet_from());
  }
  // The line is quiet once nothing was received or written for kPlayerInfoQuiet (a shot's
  // 200 may leave long after its bytes came in: the flight is played first).
  Clock::time_point quiet_from() const { return std::max(last_heard_, last_written_) + kPlayerInfoQuiet; }
  void arm_player(Clock::time_point when) {
    auto self = shared_from_this();
    player_.expires_at(when);
    player_.async_wait([this, self](const asio::error_code& ec) {
      if (ec || closed_ || !player_due_ || read_closed_) return;
      if (!idle_writer() || Clock::now() < quiet_from()) {
        // The client spoke, or a reply is still going out: wait again.
        arm_player(idle_writer() ? quiet_from() : Clock::now() + kPlayerInfoQuiet);
        return;
      }
      player_due_ = false;
      send(server_.table.player_reply(), Clock::duration{0});
      if (server_.stopping && idle_writer()) server_.shutdown();
    });
  }

  void arm_idle() {
    auto self = shared_from_this();
    const auto limit = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(server_.options.idle_timeout));
    idle_.expires_at(last_heard_ + limit);
    idle_.async_wait([this, self, limit](const asio::error_code& ec) {
      if (ec || closed_) return;
      if (Clock::now() - last_heard_ >= limit) {
        close("timed out: silent for " + std::to_string(static_cast<int>(server_.options.idle_timeout)) + " s");
        return;
      }
      arm_idle();
    });
  }

  struct Outgoing {
    std::string text;
    Clock::time_point not_before;
  };
  tcp::socket socket_;
  ConnectServer::Impl& server_;
  asio::steady_timer idle_, gap_, player_, stall_;
  MessageFramer framer_;
  std::array<char, 16 * 1024> buf_{};
  std::deque<Outgoing> out_;
  std::size_t queued_bytes_ = 0;
  bool writing_ = false, closed_ = false, player_due_ = false;
  bool read_closed_ = false;  ///< the client half-closed: no more bytes will come
  Clock::time_point last_heard_, last_written_;
  Clock::time_point last_message_;   ///< the last whole message (or the connect)
  Clock::time_point pending_since_;  ///< since when an unfinished message has been held
  std::string peer_;
};

void ConnectServer::Impl::listen() {
  asio::error_code ec;
  const asio::ip::address address = asio::ip::make_address(options.bind, ec);
  if (ec) throw InputError("--bind " + options.bind + ": not an IP address (e.g. 127.0.0.1, or 0.0.0.0 for every interface)");
  if (options.port < 0 || options.port > ConnectOptions::kMaxPort)
    throw InputError("--port " + std::to_string(options.port) + " is out of range (allowed [0, 65535])");
  const tcp::endpoint endpoint(address, static_cast<unsigned short>(options.port));
  acceptor.open(endpoint.protocol(), ec);
  if (!ec) acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor.bind(endpoint, ec);
  if (!ec) acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) {
    std::string hint;
    if (ec == asio::error::access_denied && options.port < 1024)
      hint = " (ports below 1024 need root on Linux: use --port 9210 and point the connector at it)";
    throw InputError("cannot listen on " + options.bind + ":" + std::to_string(options.port) + ": " + ec.message() + hint);
  }
  if (options.handle_signals) {
    signals.emplace(io, SIGINT, SIGTERM);
    signals->async_wait([this](const asio::error_code& e, int signal) {
      if (e) return;
      log << "sweetspot connect: " << (signal == SIGINT ? "SIGINT" : "SIGTERM") << ": closing\n";
      shutdown();
    });
  }
}

void ConnectServer::Impl::accept() {
  acceptor.async_accept([this](const asio::error_code& ec, tcp::socket socket) {
    if (ec) return;  // closed by shutdown()
    const auto live = current.lock();
    if (live && live->open() && !live->replaceable()) {
      // Held: decide a moment later (a reconnect's old socket may have closed meanwhile).
      decide_knock(std::make_shared<tcp::socket>(std::move(socket)), kKnockGrace, Clock::now() + kKnockGrace + kStuckAfter);
    } else {
      take(std::move(socket));
    }
    accept();
  });
}

void ConnectServer::Impl::decide_knock(std::shared_ptr<tcp::socket> knock, Clock::duration after,
                                       Clock::time_point deadline) {
  auto timer = std::make_shared<asio::steady_timer>(io, after);
  timer->async_wait([this, knock, timer, deadline](const asio::error_code& e) {
    if (e || stopping_all) return;
    const auto holder = current.lock();
    if (!(holder && holder->open() && !holder->replaceable())) {
      take(std::move(*knock));
    } else if (const auto wait = holder->until_stuck(); wait > Clock::duration::zero() && Clock::now() < deadline) {
      // The holder is in the middle of a message: the knock waits until it finishes it (then
      // refused) or has held it kStuckAfter (then served), so a launch monitor that knocks
      // while a client trickles is served within kStuckAfter instead of sent away. Looked
      // at again every 100 ms, so a refusal comes soon after the message is whole. A holder
      // that finishes each message and at once starts the next is sending shots, not
      // stuck: past the deadline (one kStuckAfter) the knock is refused, not kept waiting.
      decide_knock(knock, std::min<Clock::duration>(wait + std::chrono::milliseconds(10), std::chrono::milliseconds(100)),
                   deadline);
    } else {
      refuse(std::move(*knock));
    }
  });
}

void ConnectServer::Impl::take(tcp::socket socket) {
  // A half-closed holder keeps its socket until its last replies are out; it closes itself.
  if (const auto live = current.lock(); live && live->open() && !live->half_closed())
    live->close("replaced: another launch monitor connected while this one sent no whole message");
  auto session = std::make_shared<Session>(std::move(socket), *this);
  current = session;
  session->start();
}

void ConnectServer::Impl::refuse(tcp::socket socket) {
  // GSPro serves one launch monitor; tell the second why before closing.
  auto s = std::make_shared<tcp::socket>(std::move(socket));
  auto text = std::make_shared<std::string>(reply_status(503, "Another launch monitor is connected"));
  log << "sweetspot connect: " << endpoint_text(*s) << " refused: another launch monitor is connected\n";
  asio::async_write(*s, asio::buffer(*text), [s, text](const asio::error_code&, std::size_t) {
    asio::error_code ignored;
    s->shutdown(tcp::socket::shutdown_both, ignored);
    s->close(ignored);
  });
}

void ConnectServer::Impl::shutdown() {
  stopping_all = true;
  asio::error_code ec;
  acceptor.close(ec);
  if (signals) signals->cancel(ec);
  if (const auto live = current.lock()) live->close("closed by the server");
  io.stop();
}

ConnectServer::ConnectServer(const Assets& assets, const ConnectOptions& o, std::ostream& out, std::ostream& log) {
  if (!(o.idle_timeout >= ConnectOptions::kMinIdle && o.idle_timeout <= ConnectOptions::kMaxIdle))
    throw InputError("--idle-timeout " + std::to_string(o.idle_timeout) + " s is out of range (allowed [1, 86400] s)");
  impl_ = std::make_shared<Impl>(assets, o, out, log);
  impl_->listen();  // first: a port that cannot be bound leaves no record file behind
  if (!o.record.empty()) {
    // Appending to a file that is not a session would mix shots into someone's data.
    read_session_file(o.record, "--record appends only to files of JSON objects, one per line");
    std::error_code ec;
    impl_->record_bytes = std::filesystem::exists(o.record, ec) ? std::filesystem::file_size(o.record, ec) : 0;
    impl_->record.open(o.record, std::ios::binary | std::ios::app);
    if (!impl_->record) {
      std::error_code ec;
      const std::filesystem::path dir = std::filesystem::path(o.record).parent_path();
      const std::string why = !dir.empty() && !std::filesystem::is_directory(dir, ec)
                                  ? "the folder '" + dir.string() + "' does not exist"
                                  : std::string(std::strerror(errno));
      throw InputError("--record " + o.record + ": cannot open for writing (" + why + ")");
    }
  }
  impl_->accept();
}

ConnectServer::~ConnectServer() {
  if (impl_) {
    impl_->shutdown();
    // Let the closed sockets' handlers run so that nothing outlives the server.
    impl_->io.restart();
    impl_->io.poll();
  }
}

int ConnectServer::port() const { return impl_->acceptor.is_open() ? impl_->acceptor.local_endpoint().port() : 0; }

int ConnectServer::run() {
  impl_->log << "sweetspot connect: listening on " << impl_->options.bind << ":" << port() << "; "
             << impl_->table.where() << "\n";
  impl_->io.run();
  return impl_->record_failed ? 2 : 0;
}

void ConnectServer::poll() { impl_->io.poll(); }

void ConnectServer::stop() {
  asio::post(impl_->io, [impl = impl_] { impl->shutdown(); });
}

bool ConnectServer::stopped() const { return impl_->io.stopped(); }
int ConnectServer::shots() const { return impl_->shots; }
const ShotTable& ConnectServer::table() const { return impl_->table; }
void ConnectServer::on_shot(std::function<void(const ShotTable::Played&)> f) { impl_->shot_hook = std::move(f); }

}  // namespace sweetspot
