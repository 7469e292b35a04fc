// Errors for bad input. Physics validates parameters once, at the edge, and throws
// InputError with a message that names the offending field and its allowed range; the
// hot paths (impact solve, flight step) assume validated input and never throw.
#pragma once

#include <stdexcept>
#include <string>

namespace sweetspot {

class InputError : public std::runtime_error {
 public:
  /// Control bytes from the input quoted in the message (a NUL in a file's string, an
  /// escape sequence) are written as \xNN: a NUL would end the message where a reader
  /// stops at it, and an escape would talk to the terminal.
  explicit InputError(const std::string& what) : std::runtime_error(visible(what)) {}
  explicit InputError(const char* what) : InputError(std::string(what)) {}

 private:
  static std::string visible(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (const char c : s) {
      const auto u = static_cast<unsigned char>(c);
      if (u >= 0x20 && u != 0x7f) {
        out += c;
      } else if (c == '\n' || c == '\t') {
        out += c;
      } else {
        static const char* hex = "0123456789ABCDEF";
        out += "\\x";
        out += hex[u >> 4];
        out += hex[u & 15];
      }
    }
    return out;
  }
};

}  // namespace sweetspot
