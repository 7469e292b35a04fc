// Cuts a TCP byte stream of JSON objects into messages (Open Connect has no delimiter
// between them: DESIGN §10), and recovers every whole message that follows a broken one.
//
// Each candidate message starts at a '{' and is checked byte by byte against the JSON
// grammar (JsonScanner): it is a message when its braces close, broken at the first byte
// that cannot continue it. A message cut short and followed by the next one breaks at the
// latest a few bytes into that next message, since no JSON value continues with `}{` or
// with a key outside its quotes. The next candidates are then the '{' bytes inside the broken
// span, in order. The one the writer meant as the next message is among them, so no whole
// message after a broken part is lost, whatever the broken part held, strings included, as
// long as the message opens with a key that does not itself begin with a quote or a brace
// (`{"}":1}` after an open string reads as that string's end; Open Connect's keys are words).
//
// Each broken part is reported once: a candidate that starts inside an earlier broken part
// and breaks too is part of it, and so is an object nested in it (or found after it, before
// any message) that a ',', ':', '}' or ']' follows: no message is followed by more of a
// structure; and so is one that names no sender (no DeviceID, APIversion or ShotNumber key:
// a cut message's ShotDataOptions). One the stream ends after, or a '{' follows, that names
// its sender is taken as a message, even where the broken part's grammar had room for it as
// a value: `{"Wrapper":` and a shot cannot be told from a shot cut after a colon and the
// next one, and no whole message after garbage is lost. Bytes outside any object are one Garbage piece per run.
// Memory is bounded: a candidate longer than `max_bytes` is refused as Oversized and the
// search resumes inside it; one nested deeper than kMaxDepth is broken (TooDeep).
//
// A candidate that never completes would hide the whole messages inside it: finish() (the
// stream ended) cuts every unfinished candidate; flush_stalled() (the sender went quiet)
// cuts one only when a whole message that stands alone (nothing but a '{' or the end after
// it) can be found inside it, so a slow but sound message is left to finish.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sweetspot {

/// An incremental check of one JSON object against RFC 8259's grammar, a byte at a time.
class JsonScanner {
 public:
  enum class Status { More, Complete, Invalid };
  explicit JsonScanner(int max_depth);
  /// Feeds one byte. After Complete or Invalid the scanner must be reset before reuse.
  Status feed(char c);
  void reset();
  /// Why the last byte was refused (after Invalid).
  const char* reason() const { return reason_; }
  bool too_deep() const { return too_deep_; }

 private:
  enum class State : std::uint8_t {
    Start, ObjectKeyOrEnd, ObjectKey, Colon, Value, ArrayValueOrEnd, AfterValue,
    String, Escape, Hex, NumberMinus, NumberZero, NumberInt, NumberDot, NumberFrac, NumberE,
    NumberESign, NumberExp, Literal,
  };
  Status fail(const char* why);
  Status value_done();
  Status end_number(char c);
  Status after_value(char c);
  int max_depth_;
  State state_ = State::Start;
  std::vector<bool> stack_;  ///< true: an object, false: an array
  bool key_ = false;         ///< the string being read is a key
  int hex_left_ = 0;
  const char* literal_ = nullptr;  ///< the rest of true/false/null still expected
  const char* reason_ = "";
  bool too_deep_ = false;
};

class MessageFramer {
 public:
  static constexpr int kMaxDepth = 32;  ///< Open Connect messages nest 2 deep
  explicit MessageFramer(std::size_t max_bytes = 64 * 1024);
  struct Piece {
    enum class Kind { Message, Garbage, Broken, Oversized, TooDeep } kind;
    std::string text;    ///< the message (Message); a short excerpt of the bad bytes otherwise
    std::string reason;  ///< Broken: what the grammar refused, and where
  };
  /// Feeds received bytes; returns what became whole or broken.
  std::vector<Piece> feed(std::string_view bytes);
  /// The stream ended: an unfinished candidate is cut off (Broken) and the whole messages
  /// inside it are still found.
  std::vector<Piece> finish();
  /// The sender went quiet: an unfinished candidate that holds a whole message further on
  /// is cut off there. Nothing happens when no whole message can be found inside it.
  std::vector<Piece> flush_stalled();
  /// Bytes held for an unfinished candidate.
  std::size_t pending() const { return scanning_ ? buf_.size() - head_ : 0; }
  /// Candidates begun so far: a change means the unfinished one (if any) is a new one.
  std::uint64_t candidates() const { return candidates_; }

 private:
  void resolve(std::vector<Piece>& out);
  void start_candidate(std::size_t at);
  void broken(std::vector<Piece>& out, Piece::Kind kind, std::size_t end, const std::string& reason);
  /// " (the value of \"Speed\")" when the bytes [from, bad) end in a key and its ':' (so the
  /// refused byte is that key's value: "Speed":NaN), else "": the message names the field.
  std::string value_of(std::size_t from, std::size_t bad) const;
  void resume_inside(std::size_t end);
  void flush_garbage(std::vector<Piece>& out);
  /// Whether a whole object starts at `at` (then `*end` is one past it).
  bool whole_message_at(std::size_t at, std::size_t* end) const;
  /// Whether the object [from, to) has a key only a whole message has (DeviceID, ...).
  bool names_a_sender(std::size_t from, std::size_t to) const;
  /// Whether the next byte after `at` that is not whitespace goes on with a structure.
  bool inside_structure(std::size_t at) const;
  std::string excerpt(std::size_t from, std::size_t to) const;
  void compact();

  std::size_t max_;
  std::string buf_;
  std::size_t head_ = 0;     ///< start of the current candidate (or of unread bytes)
  std::size_t scanned_ = 0;  ///< bytes of buf_ the current candidate's scanner has seen
  bool scanning_ = false;
  JsonScanner scanner_;
  /// End (in buf_) of the last broken part: candidates that start before it belong to it.
  std::size_t broken_end_ = 0;
  bool in_broken_ = false;   ///< skipping the rest of a broken part up to the next '{'
  /// Since the last broken part no message has been found: an object found now that more
  /// of a structure follows (',', ':', '}' or ']') is a piece of that part, wherever the
  /// grammar first refused it (a bad value early on leaves its nested objects after it).
  bool recovering_ = false;
  std::string garbage_;      ///< excerpt of the current run of bytes outside any object
  bool garbage_seen_ = false;
  std::uint64_t candidates_ = 0;
};

}  // namespace sweetspot
