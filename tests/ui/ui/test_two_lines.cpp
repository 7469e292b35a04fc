#include <catch2/catch.hpp>

#include "game/ui/two_lines.hpp"

using namespace sweetspot;

namespace {
float chars(std::string_view s) { return static_cast<float>(s.size()); }
}  // namespace

TEST_CASE("a long call is cut in two at the clause break that balances the lines", "[ui][unit]") {
  const auto [a, b] = split_in_two_lines(
      "Swinging strike: early by 33 ms, the ball went past the end of the bat (wait a touch longer)   (0-2)", chars);
  CHECK(a == "Swinging strike: early by 33 ms,");
  CHECK(b == "the ball went past the end of the bat (wait a touch longer)   (0-2)");
  const auto [c, d] = split_in_two_lines("Foul tip, strike three: out", chars);
  CHECK(c == "Foul tip,");
  CHECK(d == "strike three: out");
  // No break: the whole text on the first line.
  const auto [e, f] = split_in_two_lines("Ball four", chars);
  CHECK(e == "Ball four");
  CHECK(f.empty());
}
