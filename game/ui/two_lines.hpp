// A one-line message too wide for its place, cut in two where a reader pauses.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>

namespace sweetspot {

/// `text` cut at the clause break (", ", "; ", ": " or " (") that leaves the wider of the
/// two lines narrowest by `width` (the px a string spans); the break's comma, semicolon or
/// colon ends the first line, the rest starts the second. {text, ""} when it has no break.
std::pair<std::string, std::string> split_in_two_lines(std::string_view text,
                                                       const std::function<float(std::string_view)>& width);

}  // namespace sweetspot
