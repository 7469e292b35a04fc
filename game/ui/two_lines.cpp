#include "game/ui/two_lines.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace sweetspot {

std::pair<std::string, std::string> split_in_two_lines(std::string_view text,
                                                       const std::function<float(std::string_view)>& width) {
  std::pair<std::string, std::string> best{std::string(text), std::string()};
  float widest = std::numeric_limits<float>::infinity();
  // The first line keeps the punctuation (", " ends it with the comma); a " (" goes to the
  // second line with its bracket.
  constexpr std::array<std::string_view, 4> kBreaks{", ", "; ", ": ", " ("};
  for (std::size_t i = 1; i + 1 < text.size(); ++i) {
    for (const std::string_view b : kBreaks) {
      if (text.substr(i, b.size()) != b) continue;
      const std::size_t first_end = b.front() == ' ' ? i : i + 1;
      const std::size_t second_start = b.front() == ' ' ? i + 1 : i + b.size();
      const std::string_view first = text.substr(0, first_end), second = text.substr(second_start);
      const float w = std::max(width(first), width(second));
      if (w < widest) {
        widest = w;
        best = {std::string(first), std::string(second)};
      }
    }
  }
  return best;
}

}  // namespace sweetspot
