#include "game/net/message_framer.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>

namespace sweetspot {

// ---- JsonScanner ---------------------------------------------------------------------

JsonScanner::JsonScanner(int max_depth) : max_depth_(max_depth) {}

void JsonScanner::reset() {
  state_ = State::Start;
  stack_.clear();
  key_ = false;
  hex_left_ = 0;
  literal_ = nullptr;
  reason_ = "";
  too_deep_ = false;
}

JsonScanner::Status JsonScanner::fail(const char* why) {
  reason_ = why;
  return Status::Invalid;
}

JsonScanner::Status JsonScanner::value_done() {
  state_ = State::AfterValue;
  return Status::More;
}

namespace {
bool json_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool digit(char c) { return c >= '0' && c <= '9'; }
bool hex(char c) { return digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }
}  // namespace

// A number ends at the first byte that cannot continue it, which then follows the value
// (whitespace included: "1 2" is two values, not one).
JsonScanner::Status JsonScanner::end_number(char c) {
  state_ = State::AfterValue;
  return after_value(c);
}

JsonScanner::Status JsonScanner::after_value(char c) {
  if (json_space(c)) return Status::More;
  const bool object = stack_.back();
  if (c == ',') {
    state_ = object ? State::ObjectKey : State::Value;
    return Status::More;
  }
  if (c == (object ? '}' : ']')) {
    stack_.pop_back();
    return stack_.empty() ? Status::Complete : value_done();
  }
  return fail(object ? "expected ',' or '}' after a value" : "expected ',' or ']' after a value");
}

JsonScanner::Status JsonScanner::feed(char c) {
  const auto open = [&](bool object) {
    if (static_cast<int>(stack_.size()) >= max_depth_) {
      too_deep_ = true;
      return fail("objects nested too deep");
    }
    stack_.push_back(object);
    state_ = object ? State::ObjectKeyOrEnd : State::ArrayValueOrEnd;
    return Status::More;
  };
  const auto begin_value = [&](char v) {
    switch (v) {
      case '"': key_ = false; state_ = State::String; return Status::More;
      case '{': return open(true);
      case '[': return open(false);
      case '-': state_ = State::NumberMinus; return Status::More;
      case '0': state_ = State::NumberZero; return Status::More;
      case 't': literal_ = "rue"; state_ = State::Literal; return Status::More;
      case 'f': literal_ = "alse"; state_ = State::Literal; return Status::More;
      case 'n': literal_ = "ull"; state_ = State::Literal; return Status::More;
      default:
        if (digit(v)) {
          state_ = State::NumberInt;
          return Status::More;
        }
        return fail("expected a value");
    }
  };
  switch (state_) {
    case State::Start:
      return c == '{' ? open(true) : fail("a message starts with '{'");
    case State::ObjectKeyOrEnd:
      if (json_space(c)) return Status::More;
      if (c == '}') return after_value(c);
      [[fallthrough]];
    case State::ObjectKey:
      if (json_space(c)) return Status::More;
      if (c != '"') return fail("expected a key in quotes");
      key_ = true;
      state_ = State::String;
      return Status::More;
    case State::Colon:
      if (json_space(c)) return Status::More;
      if (c != ':') return fail("expected ':' after a key");
      state_ = State::Value;
      return Status::More;
    case State::ArrayValueOrEnd:
      if (json_space(c)) return Status::More;
      if (c == ']') return after_value(c);
      return begin_value(c);
    case State::Value:
      return json_space(c) ? Status::More : begin_value(c);
    case State::AfterValue:
      return after_value(c);
    case State::String:
      if (c == '"') {
        if (key_) {
          key_ = false;
          state_ = State::Colon;
          return Status::More;
        }
        return value_done();
      }
      if (c == '\\') state_ = State::Escape;
      else if (static_cast<unsigned char>(c) < 0x20) return fail("a control byte inside a string");
      return Status::More;
    case State::Escape:
      if (c == 'u') {
        hex_left_ = 4;
        state_ = State::Hex;
        return Status::More;
      }
      if (c == '\0' || std::strchr("\"\\/bfnrt", c) == nullptr) return fail("a bad escape in a string");
      state_ = State::String;
      return Status::More;
    case State::Hex:
      if (!hex(c)) return fail("a bad \\u escape in a string");
      if (--hex_left_ == 0) state_ = State::String;
      return Status::More;
    case State::NumberMinus:
      if (c == '0') state_ = State::NumberZero;
      else if (digit(c)) state_ = State::NumberInt;
      else return fail("a digit must follow '-'");
      return Status::More;
    case State::NumberInt:
      if (digit(c)) return Status::More;
      [[fallthrough]];
    case State::NumberZero:
      if (c == '.') state_ = State::NumberDot;
      else if (c == 'e' || c == 'E') state_ = State::NumberE;
      else return end_number(c);
      return Status::More;
    case State::NumberDot:
      if (!digit(c)) return fail("a digit must follow '.'");
      state_ = State::NumberFrac;
      return Status::More;
    case State::NumberFrac:
      if (digit(c)) return Status::More;
      if (c == 'e' || c == 'E') {
        state_ = State::NumberE;
        return Status::More;
      }
      return end_number(c);
    case State::NumberE:
      if (c == '+' || c == '-') {
        state_ = State::NumberESign;
        return Status::More;
      }
      [[fallthrough]];
    case State::NumberESign:
      if (!digit(c)) return fail("a digit must follow the exponent");
      state_ = State::NumberExp;
      return Status::More;
    case State::NumberExp:
      return digit(c) ? Status::More : end_number(c);
    case State::Literal:
      if (c != *literal_) return fail("expected true, false or null");
      if (*++literal_ == '\0') return value_done();
      return Status::More;
  }
  return fail("scanner state");
}

// ---- MessageFramer -------------------------------------------------------------------

namespace {
// Between messages: JSON's whitespace, and NULs some serial bridges pad with.
bool gap_byte(char c) { return json_space(c) || c == '\0'; }
constexpr std::size_t kExcerpt = 64;
}  // namespace

MessageFramer::MessageFramer(std::size_t max_bytes) : max_(max_bytes), scanner_(kMaxDepth) {}

std::vector<MessageFramer::Piece> MessageFramer::feed(std::string_view bytes) {
  buf_.append(bytes);
  std::vector<Piece> out;
  resolve(out);
  return out;
}

void MessageFramer::start_candidate(std::size_t at) {
  head_ = scanned_ = at;
  scanner_.reset();
  scanning_ = true;
  ++candidates_;
}

std::string MessageFramer::excerpt(std::size_t from, std::size_t to) const {
  return buf_.substr(from, std::min(to, buf_.size()) - from).substr(0, kExcerpt);
}

void MessageFramer::flush_garbage(std::vector<Piece>& out) {
  if (!garbage_seen_) return;
  out.push_back({Piece::Kind::Garbage, garbage_, ""});
  garbage_.clear();
  garbage_seen_ = false;
  in_broken_ = true;  // the rest of this run, up to the next '{', was answered with it
}

void MessageFramer::broken(std::vector<Piece>& out, Piece::Kind kind, std::size_t end, const std::string& reason) {
  // A candidate that began inside an earlier broken part is a piece of that part.
  if (head_ >= broken_end_) out.push_back({kind, excerpt(head_, end), reason});
  broken_end_ = std::max(broken_end_, end);
  recovering_ = true;
}

void MessageFramer::resume_inside(std::size_t end) {
  const std::size_t next = buf_.find('{', head_ + 1);
  if (next != std::string::npos && next < end) {
    start_candidate(next);
    return;
  }
  // No '{' inside the broken span: it runs on, unanswered again, to the next '{'.
  head_ = end;
  scanning_ = false;
  in_broken_ = true;
}

void MessageFramer::resolve(std::vector<Piece>& out) {
  for (;;) {
    if (!scanning_) {
      while (head_ < buf_.size() && buf_[head_] != '{') {
        const char c = buf_[head_++];
        if (in_broken_ || gap_byte(c)) continue;
        garbage_seen_ = true;
        if (garbage_.size() < kExcerpt) garbage_ += c;
      }
      if (head_ == buf_.size()) {
        flush_garbage(out);  // answered now, not when the next '{' comes
        compact();
        return;
      }
      flush_garbage(out);
      start_candidate(head_);
    }
    JsonScanner::Status status = JsonScanner::Status::More;
    while (scanned_ < buf_.size() && scanned_ - head_ <= max_) {
      status = scanner_.feed(buf_[scanned_++]);
      if (status != JsonScanner::Status::More) break;
    }
    if (status == JsonScanner::Status::Complete && scanned_ - head_ <= max_) {
      if ((head_ < broken_end_ || recovering_) && (inside_structure(scanned_) || !names_a_sender(head_, scanned_))) {
        // An object nested in the broken part (a ',', ':', '}' or ']' goes on after it), or
        // one that names no sender (a cut message's last BallData or ShotDataOptions): a
        // piece of what was answered already, not a message.
        broken_end_ = std::max(broken_end_, scanned_);
        head_ = scanned_;
        scanning_ = false;
        in_broken_ = true;
        continue;
      }
      out.push_back({Piece::Kind::Message, buf_.substr(head_, scanned_ - head_), ""});
      recovering_ = false;
      // A message found inside a broken part may be a piece of it (an object nested in the
      // broken one): the bytes after it, up to the next '{', are that part's, not new garbage.
      in_broken_ = head_ < broken_end_;
      head_ = scanned_;
      scanning_ = false;
      continue;
    }
    if (status == JsonScanner::Status::Invalid) {
      const std::size_t bad = scanned_ - 1;
      broken(out, scanner_.too_deep() ? Piece::Kind::TooDeep : Piece::Kind::Broken, bad + 1,
             std::string(scanner_.reason()) + " at byte " + std::to_string(bad - head_ + 1) + value_of(head_, bad));
      resume_inside(bad + 1);  // the refused byte may itself begin the next message
      continue;
    }
    if (scanned_ - head_ > max_) {
      broken(out, Piece::Kind::Oversized, scanned_, "longer than " + std::to_string(max_) + " bytes");
      resume_inside(scanned_);
      continue;
    }
    compact();
    return;  // unfinished: wait for more bytes
  }
}

std::string MessageFramer::value_of(std::size_t from, std::size_t bad) const {
  constexpr std::size_t kLongestKey = 64;  // Open Connect's keys are a few words
  std::size_t i = bad;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (i > from && blank(buf_[i - 1])) --i;
  if (i <= from || buf_[i - 1] != ':') return "";
  --i;
  while (i > from && blank(buf_[i - 1])) --i;
  if (i <= from || buf_[i - 1] != '"') return "";
  const std::size_t end = --i;
  while (i > from && buf_[i - 1] != '"' && end - i < kLongestKey) --i;
  if (i <= from || buf_[i - 1] != '"' || i == end) return "";
  const std::string key = buf_.substr(i, end - i);
  // Said only when it can be printed as it is (a key of control bytes names nothing).
  if (!std::all_of(key.begin(), key.end(), [](char c) { return c >= 0x20 && c <= 0x7e; })) return "";
  return " (the value of \"" + key + "\")";
}

std::vector<MessageFramer::Piece> MessageFramer::finish() {
  std::vector<Piece> out;
  resolve(out);
  while (scanning_) {
    broken(out, Piece::Kind::Broken, buf_.size(), "cut off: the stream ended inside it");
    resume_inside(buf_.size());
    resolve(out);
  }
  flush_garbage(out);
  buf_.clear();
  head_ = scanned_ = broken_end_ = 0;
  in_broken_ = recovering_ = false;
  return out;
}

bool MessageFramer::names_a_sender(std::size_t from, std::size_t to) const {
  // Every Open Connect message, shot or heartbeat, carries its DeviceID, APIversion or
  // ShotNumber (DESIGN §10); the objects nested in one (BallData, ClubData, ShotDataOptions)
  // carry none of them. Read as keys, in any letter case, as the protocol's keys are.
  static constexpr std::array<std::string_view, 3> kKeys{"\"deviceid\"", "\"apiversion\"", "\"shotnumber\""};
  std::string lower = buf_.substr(from, to - from);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  for (const std::string_view k : kKeys)
    for (std::size_t at = lower.find(k); at != std::string::npos; at = lower.find(k, at + 1)) {
      std::size_t i = at + k.size();
      while (i < lower.size() && json_space(lower[i])) ++i;
      if (i < lower.size() && lower[i] == ':') return true;
    }
  return false;
}

bool MessageFramer::inside_structure(std::size_t at) const {
  for (std::size_t i = at; i < buf_.size(); ++i) {
    const char c = buf_[i];
    if (gap_byte(c)) continue;
    return c == ',' || c == ':' || c == '}' || c == ']';
  }
  return false;  // nothing after it yet: it may well be the last message
}

bool MessageFramer::whole_message_at(std::size_t at, std::size_t* end) const {
  JsonScanner scanner(kMaxDepth);
  for (std::size_t i = at; i < buf_.size() && i - at < max_; ++i) {
    const JsonScanner::Status status = scanner.feed(buf_[i]);
    if (status == JsonScanner::Status::Complete) {
      *end = i + 1;
      return true;
    }
    if (status == JsonScanner::Status::Invalid) return false;
  }
  return false;
}

std::vector<MessageFramer::Piece> MessageFramer::flush_stalled() {
  std::vector<Piece> out;
  // Each cut may leave another unfinished candidate holding a whole message: go on.
  for (bool cut = true; cut && scanning_;) {
    cut = false;
    for (std::size_t s = buf_.find('{', head_ + 1); s != std::string::npos; s = buf_.find('{', s + 1)) {
      // A whole object followed by more of a structure (',' or '}' after it) is a part of
      // a sound message that is merely slow (its BallData); only one the stream leaves
      // standing alone can be a message that the stuck one hides.
      std::size_t end = 0;
      if (!whole_message_at(s, &end) || inside_structure(end) || !names_a_sender(s, end)) continue;
      broken(out, Piece::Kind::Broken, s, "cut off: a whole message began inside it");
      start_candidate(s);
      resolve(out);
      cut = true;
      break;
    }
  }
  return out;
}

void MessageFramer::compact() {
  // Drop what is behind the current candidate once it is a good share of the buffer
  // (amortised O(1) a byte).
  if (head_ < 4096 && head_ * 2 < buf_.size()) return;
  buf_.erase(0, head_);
  scanned_ = scanned_ > head_ ? scanned_ - head_ : 0;
  broken_end_ = broken_end_ > head_ ? broken_end_ - head_ : 0;
  head_ = 0;
}

}  // namespace sweetspot
