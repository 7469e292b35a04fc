// `sweetspot send FILE`: plays a recorded launch-monitor session back to an Open Connect
// server (ours, or GSPro itself): the file's JSON objects, one after another (JSON lines,
// `shot --gspro` output or a `connect --record` file), each sent in its own write; every
// reply the server gives is printed as one line. Each message waits for its reply (or
// --timeout) before the next goes, as a connector does.
#include <chrono>
#include <iostream>
#include <memory>

#include <asio.hpp>

#include "game/cli/command.hpp"
#include "game/content/quantity_text.hpp"
#include "game/content/toml_file.hpp"
#include "game/net/message_framer.hpp"
#include "game/net/open_connect.hpp"
#include "game/util/terminal_text.hpp"
#include "physics/error.hpp"

namespace sweetspot::cli {
namespace {

using asio::ip::tcp;

struct SendOptions {
  std::string file;
  std::string host = "127.0.0.1";
  int port = 921;
  std::string timeout = "5s";
  std::string pause = "0s";
};

struct Outgoing {
  std::string text;
  bool expects_reply = true;  ///< shots; GSPro itself does not answer heartbeats or status messages
};

// Every object of the file, checked before anything is sent (a bad file sends nothing).
std::vector<Outgoing> read_session(const std::string& path) {
  // A session of 10 000 shots is ~10 MB; 256 MB bounds what a typo (or /dev/zero) can cost.
  const std::string text = read_data_file(path, "session", 256u << 20);
  MessageFramer framer(64 * 1024);
  std::vector<Outgoing> out;
  // Line numbers for messages: count newlines up to each message's end.
  std::size_t line = 1;
  std::size_t begun = 1;  // the line the object being read began on
  for (const char ch : text) {
    if (ch == '\n') ++line;
    const bool between = framer.pending() == 0;
    const auto pieces = framer.feed(std::string_view(&ch, 1));
    if (between && framer.pending() > 0) begun = line;
    for (const auto& piece : pieces) {
      const std::string where = path + ":" + std::to_string(line);
      if (piece.kind == MessageFramer::Piece::Kind::Oversized)
        throw InputError(where + ": an object longer than 65536 bytes (no launch monitor sends one)");
      if (piece.kind == MessageFramer::Piece::Kind::TooDeep)
        throw InputError(where + ": objects nested deeper than " + std::to_string(MessageFramer::kMaxDepth));
      if (piece.kind == MessageFramer::Piece::Kind::Broken)
        throw InputError(where + ": malformed JSON: " + piece.reason + " (near '" + piece.text.substr(0, 24) + "')");
      if (piece.kind != MessageFramer::Piece::Kind::Message)
        throw InputError(where + ": not a JSON object (near '" + piece.text.substr(0, 24) + "')");
      OcMessage m;
      try {
        m = parse_open_connect(piece.text);
      } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
      }
      out.push_back({piece.text, m.kind == OcMessage::Kind::Shot});
    }
  }
  // Named where it began: a message cut off on line 2 ran on to the end of the file.
  if (framer.pending() > 0)
    throw InputError(path + ":" + std::to_string(begun) + ": this object is not closed (it runs on to the end of the file, line " +
                     std::to_string(line) + "); nothing was sent");
  if (out.empty()) throw InputError(path + ": no JSON object in the file");
  return out;
}

RunFn setup_send(CLI::App& sub) {
  auto o = std::make_shared<SendOptions>();
  sub.add_option("file", o->file, "the session: JSON objects (JSON lines, `shot --gspro` output, a `connect --record` file)")
      ->required();
  sub.add_option("--host", o->host, "the server's address")->capture_default_str();
  sub.add_option("--port", o->port, "the server's port, 1..65535")->check(int_range<int>(1, 65535))->capture_default_str();
  sub.add_option("--timeout", o->timeout, "how long to wait for each reply, 10ms..60s")->capture_default_str();
  sub.add_option("--pause", o->pause, "time between shots, 0s..60s (a player's pace)")->capture_default_str();
  return [o](const Assets&) -> int {
    const Range timeout_range{0.01, 60.0}, pause_range{0.0, 60.0};
    const double timeout = flag_quantity("--timeout", o->timeout, Dimension::Time, &timeout_range);
    const double pause = flag_quantity("--pause", o->pause, Dimension::Time, &pause_range);
    const std::vector<Outgoing> session = read_session(o->file);

    asio::io_context io;
    tcp::socket socket(io);
    asio::error_code ec;
    const auto endpoints = tcp::resolver(io).resolve(o->host, std::to_string(o->port), ec);
    if (ec) throw InputError("--host " + o->host + ": " + ec.message());
    const auto wait = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(timeout));
    bool connected = false;
    asio::async_connect(socket, endpoints, [&](const asio::error_code& e, const tcp::endpoint&) {
      ec = e;
      connected = !e;
    });
    io.run_for(wait);
    if (!connected) {
      std::cerr << "sweetspot send: cannot connect to " << o->host << ":" << o->port << ": "
                << (ec ? ec.message() : std::string("timed out")) << "\n";
      return 1;
    }
    socket.set_option(tcp::no_delay(true), ec);

    MessageFramer replies(64 * 1024);
    std::array<char, 4096> buf{};
    std::size_t unanswered = 0;
    bool closed = false;
    // Reads replies for up to `how_long`; stops early once `want` replies have come.
    const auto collect = [&](int want, std::chrono::steady_clock::duration how_long) {
      int got = 0;
      const auto deadline = std::chrono::steady_clock::now() + how_long;
      while (!closed && (want == 0 || got < want) && std::chrono::steady_clock::now() < deadline) {
        bool done = false;
        socket.async_read_some(asio::buffer(buf), [&](const asio::error_code& e, std::size_t n) {
          done = true;
          if (e) {
            closed = true;
            return;
          }
          for (const auto& piece : replies.feed(std::string_view(buf.data(), n))) {
            // A server's bytes are printed escaped: an escape sequence in a reply must not
            // reach the operator's terminal.
            std::cout << terminal_safe(piece.text) << "\n";
            // The answer to a message is a 200 or an error; 201-203 come unasked.
            const auto reply = nlohmann::json::parse(piece.text, nullptr, false);
            const int code = reply.is_object() && reply.contains("Code") && reply["Code"].is_number_integer()
                                 ? reply["Code"].get<int>() : 0;
            if (code == 200 || code >= 400) ++got;
          }
        });
        io.restart();
        io.run_until(deadline);
        if (!done) {
          socket.cancel(ec);
          io.restart();
          io.run();  // let the cancelled read finish
        }
      }
      std::cout << std::flush;
      return got;
    };

    std::size_t sent = 0;
    for (const Outgoing& m : session) {
      if (closed) break;
      ++sent;
      asio::write(socket, asio::buffer(m.text), ec);
      if (ec) {
        std::cerr << "sweetspot send: the server closed the connection: " << ec.message() << "\n";
        return 1;
      }
      if (m.expects_reply) {
        if (collect(1, wait) == 0) ++unanswered;
      } else {
        collect(1, std::min<std::chrono::steady_clock::duration>(wait, std::chrono::milliseconds(100)));
      }
      if (pause > 0.0) collect(0, std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(pause)));
    }
    collect(0, std::chrono::milliseconds(100));  // a 201 or 203 that follows the last 200
    socket.shutdown(tcp::socket::shutdown_both, ec);
    const bool cut_short = sent < session.size();
    std::cerr << "sweetspot send: " << sent << " of " << session.size() << " messages sent, " << (sent - unanswered)
              << " answered" << (cut_short ? "; the server closed the connection" : "") << "\n";
    return unanswered > 0 || cut_short ? 1 : 0;
  };
}

const CommandRegistrar send_command{38, "send", "play a recorded launch-monitor session back to an Open Connect server", setup_send};

}  // namespace
}  // namespace sweetspot::cli
