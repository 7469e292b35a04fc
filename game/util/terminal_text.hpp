// Text from outside (a client's bytes, a server's reply, a user's argument) made safe to
// print on a terminal: nothing in it can move the cursor, change colours or retitle the
// window, and it stays on one line.
#pragma once

#include <string>
#include <string_view>

namespace sweetspot {

/// `text` with every byte a terminal could act on shown escaped: C0 controls and DEL as
/// "\xNN" ("\n" and "\t" as themselves escaped), the C1 controls U+0080..U+009F (in UTF-8)
/// as "\u00NN", the bidirectional controls (U+202A..U+202E, U+2066..U+2069, U+200E/F,
/// U+061C) and the line and paragraph separators as "\uNNNN", and bytes that are not UTF-8
/// as "\xNN" (a lone 0x9B is CSI to an 8-bit terminal). Valid UTF-8 text otherwise passes
/// unchanged.
std::string terminal_safe(std::string_view text);

/// Why `name` cannot stand as a player's or a course's name on a card, a panel or a
/// terminal: empty, longer than `max_chars` characters, not UTF-8, or holding a byte
/// terminal_safe() would escape (a control, a bidirectional mark). "" when it can.
std::string name_problem(std::string_view name, std::size_t max_chars);

}  // namespace sweetspot
