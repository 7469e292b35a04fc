#include <catch2/catch.hpp>

#include "game/util/terminal_text.hpp"

using namespace sweetspot;

TEST_CASE("text from outside prints on a terminal with nothing a terminal acts on", "[util][hostile]") {
  // C0 controls and DEL: an escape sequence (clear the screen, retitle the window) shows as text.
  CHECK(terminal_safe("\x1b[2J\x1b]0;owned\x07") == "\\x1b[2J\\x1b]0;owned\\x07");
  CHECK(terminal_safe("a\nb\tc\x7f") == "a\\nb\\tc\\x7f");
  // C1 controls in UTF-8 (U+009B is CSI) and bytes that are not UTF-8 (a lone 0x9B).
  CHECK(terminal_safe("\xc2\x9b" "31m") == "\\u009b31m");
  CHECK(terminal_safe("\x9b" "31m") == "\\x9b31m");
  CHECK(terminal_safe("\xc0\xaf") == "\\xc0\\xaf");  // an overlong '/'
  CHECK(terminal_safe("\xed\xa0\x80") == "\\xed\\xa0\\x80");  // a surrogate
  // Text passes unchanged: ASCII, accents, CJK, emoji.
  CHECK(terminal_safe("Caf\xc3\xa9 \xe6\x97\xa5 \xf0\x9f\x8f\x8c") == "Caf\xc3\xa9 \xe6\x97\xa5 \xf0\x9f\x8f\x8c");
  CHECK(terminal_safe("\xc2\xa0") == "\xc2\xa0");  // U+00A0 is not a control
}

TEST_CASE("text from outside cannot reorder or break the line a terminal shows", "[util][hostile]") {
  // A right-to-left override shows a name reversed ("Trojan Source"); isolates and marks too.
  CHECK(terminal_safe("dr\xc3\xafver\xe2\x80\xae" "exe") == "dr\xc3\xafver\\u202e" "exe");
  CHECK(terminal_safe("\xe2\x81\xa6x\xe2\x81\xa9") == "\\u2066x\\u2069");
  CHECK(terminal_safe("\xe2\x80\x8f\xd8\x9c") == "\\u200f\\u061c");
  // The line and paragraph separators start a new line on some terminals.
  CHECK(terminal_safe("a\xe2\x80\xa8" "b\xe2\x80\xa9") == "a\\u2028b\\u2029");
  // Their neighbours are text: an en dash, a zero-width joiner in an emoji.
  CHECK(terminal_safe("1\xe2\x80\x93" "2") == "1\xe2\x80\x93" "2");
  CHECK(terminal_safe("\xe2\x80\x8d") == "\xe2\x80\x8d");
}
