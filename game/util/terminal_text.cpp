#include "game/util/terminal_text.hpp"

#include <cstdio>

namespace sweetspot {
namespace {

void escaped(std::string& out, const char* format, unsigned value) {
  char buf[8];
  std::snprintf(buf, sizeof buf, format, value);
  out += buf;
}

// Length of the UTF-8 sequence starting at text[i] (1..4), or 0 when it is not one
// (overlong forms, surrogates and values past U+10FFFF included).
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  std::size_t n = 0;
  unsigned min = 0, cp = 0;
  if (b >= 0xC2 && b <= 0xDF) n = 2, min = 0x80, cp = b & 0x1F;
  else if (b >= 0xE0 && b <= 0xEF) n = 3, min = 0x800, cp = b & 0x0F;
  else if (b >= 0xF0 && b <= 0xF4) n = 4, min = 0x10000, cp = b & 0x07;
  else return 0;
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

// The code point at text[i] (a valid n-byte sequence) when it reorders or breaks the text
// a terminal shows (the bidirectional embeddings, overrides, isolates and marks: a name
// with U+202E prints reversed, "Trojan Source"; the line and paragraph separators), else 0.
unsigned layout_control(std::string_view text, std::size_t i, std::size_t n) {
  if (n != 2 && n != 3) return 0;
  const auto byte = [&](std::size_t k) { return static_cast<unsigned>(static_cast<unsigned char>(text[i + k])); };
  const unsigned cp = n == 2 ? ((byte(0) & 0x1F) << 6) | (byte(1) & 0x3F)
                             : ((byte(0) & 0x0F) << 12) | ((byte(1) & 0x3F) << 6) | (byte(2) & 0x3F);
  const bool bidi = cp == 0x200E || cp == 0x200F || cp == 0x061C || (cp >= 0x202A && cp <= 0x202E) ||
                    (cp >= 0x2066 && cp <= 0x2069);
  return bidi || cp == 0x2028 || cp == 0x2029 ? cp : 0;
}

}  // namespace

std::string terminal_safe(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char b = static_cast<unsigned char>(text[i]);
    if (b >= 0x20 && b < 0x7f) {
      out += static_cast<char>(b);
      ++i;
    } else if (b == '\n' || b == '\t') {
      out += b == '\n' ? "\\n" : "\\t";
      ++i;
    } else if (b < 0x80) {
      escaped(out, "\\x%02x", b);
      ++i;
    } else if (const std::size_t n = utf8_length(text, i); n == 0) {
      escaped(out, "\\x%02x", b);
      ++i;
    } else if (n == 2 && b == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0) {
      escaped(out, "\\u%04x", static_cast<unsigned char>(text[i + 1]));  // a C1 control
      i += 2;
    } else if (const unsigned cp = layout_control(text, i, n); cp != 0) {
      escaped(out, "\\u%04x", cp);
      i += n;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

std::string name_problem(std::string_view name, std::size_t max_chars) {
  if (name.empty()) return "empty";
  std::size_t chars = 0;
  for (std::size_t i = 0; i < name.size(); ++chars) {
    const std::size_t n = static_cast<unsigned char>(name[i]) < 0x80 ? 1 : utf8_length(name, i);
    if (n == 0) return "not UTF-8 text";
    i += n;
  }
  if (chars > max_chars) return std::to_string(chars) + " characters long (at most " + std::to_string(max_chars) + ")";
  if (terminal_safe(name) != name) return "holds a control character (" + terminal_safe(name).substr(0, 60) + ")";
  return {};
}

}  // namespace sweetspot
