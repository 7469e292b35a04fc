// The formats' scoring against the Rules of Golf and the World Handicap System: the
// stableford points table (Rule 21.1b), strokes received by stroke index (WHS Appendix E),
// match status and concessions (Rule 3.2), skins carry-overs.
#include <catch2/catch.hpp>

#include <numeric>

#include "game/rules/golf_scoring.hpp"
#include "physics/error.hpp"

using namespace sweetspot;

TEST_CASE("stableford points follow Rule 21.1b's table", "[rules][golf][formats]") {
  // Rule 21.1b(1): more than one over the fixed score 0, one over 1, fixed score 2, one under
  // 3, two under 4, three under 5, four under 6.
  const int par = 4;
  CHECK(stableford_points(par, 8) == 0);
  CHECK(stableford_points(par, 6) == 0);
  CHECK(stableford_points(par, 5) == 1);
  CHECK(stableford_points(par, 4) == 2);
  CHECK(stableford_points(par, 3) == 3);
  CHECK(stableford_points(par, 2) == 4);
  CHECK(stableford_points(par, 1) == 5);
  CHECK(stableford_points(5, 1) == 6);
}

TEST_CASE("handicap strokes go by stroke index, the remainder to the hardest holes", "[rules][golf][formats]") {
  std::vector<int> index(18);
  std::iota(index.begin(), index.end(), 1);
  // WHS Appendix E: a course handicap of 20 receives one stroke on every hole and a second on
  // the holes of stroke index 1 and 2.
  const std::vector<int> s20 = strokes_received(20, index);
  for (int i = 0; i < 18; ++i) CHECK(s20[static_cast<std::size_t>(i)] == (i < 2 ? 2 : 1));
  CHECK(std::accumulate(s20.begin(), s20.end(), 0) == 20);
  // 7 strokes: the holes of index 1..7 once.
  const std::vector<int> s7 = strokes_received(7, index);
  for (int i = 0; i < 18; ++i) CHECK(s7[static_cast<std::size_t>(i)] == (i < 7 ? 1 : 0));
  // A 3-hole round plays off 3/18 of the handicap, rounded half up (WHS Rule 6.1's 9-hole
  // half, in proportion): 18 -> 3, 10 -> 1.67 -> 2, 9 -> 1.5 -> 2, 8 -> 1.33 -> 1.
  CHECK(strokes_for_round(18, 3) == 3);
  CHECK(strokes_for_round(10, 3) == 2);
  CHECK(strokes_for_round(9, 3) == 2);
  CHECK(strokes_for_round(8, 3) == 1);
  CHECK(strokes_for_round(18, 9) == 9);
  CHECK(strokes_for_round(17, 9) == 9);  // 8.5 rounds up
  const std::vector<int> three = strokes_received(10, {3, 1, 2});  // the second hole is the hardest
  CHECK(three == std::vector<int>{0, 1, 1});
  CHECK_THROWS_AS(strokes_received(55, index), InputError);
  CHECK_THROWS_AS(strokes_received(10, {1, 4, 2}), InputError);
}

TEST_CASE("match play: holes up, dormie, the match decided early, a conceded hole", "[rules][golf][formats]") {
  // Five holes. A wins 1 and 2, B wins 3, 4 halved; A leads 1 with 1 to play: dormie.
  const std::vector<int> a{4, 3, 6, 4, 5}, b{5, 4, 4, 4, 5};
  const MatchResult m = score_match(a, b, {-1, -1, -1, -1, -1}, 5, "Ann", "Bob");
  REQUIRE(m.holes.size() == 5);
  CHECK(m.holes[0].status == "Ann 1 up");
  CHECK(m.holes[1].status == "Ann 2 up");
  CHECK(m.holes[2].status == "Ann 1 up");
  CHECK(m.holes[3].status == "Ann 1 up (dormie)");
  CHECK(m.holes[4].winner == -1);
  CHECK(m.result == "Ann wins 1 up");
  // Decided with holes to play: 3 up with 2 left is "3&2" and the later holes change nothing.
  const MatchResult early = score_match({3, 3, 3, 9, 9}, {4, 4, 4, 3, 3}, {}, 5, "Ann", "Bob");
  CHECK(early.decided_after == 2);
  CHECK(early.result == "Ann wins 3&2");
  CHECK(early.lead == 3);
  // A conceded hole is lost whatever the strokes (Rule 3.2b(1)): Ann concedes the first with
  // the fewer strokes; the match ends level.
  const MatchResult conceded = score_match({3, 5}, {6, 4}, {0, -1}, 2, "Ann", "Bob");
  CHECK(conceded.holes[0].winner == 1);
  CHECK(conceded.holes[1].winner == 1);
  CHECK(conceded.result == "Bob wins 2 up");
  CHECK(score_match({4, 4}, {4, 4}, {}, 2, "Ann", "Bob").result == "halved");
  CHECK(score_match({4}, {5}, {}, 3, "Ann", "Bob").result == "Ann 1 up after 1");
  // The human's card name is "You": the verb agrees.
  CHECK(score_match({3, 3, 3, 9, 9}, {4, 4, 4, 3, 3}, {}, 5, "You", "Bob").result == "You win 3&2");
  CHECK(score_match({3, 3, 3, 9, 9}, {4, 4, 4, 3, 3}, {}, 5, "Bob", "You").result == "Bob wins 3&2");
}

TEST_CASE("skins: the lone lowest net takes the hole's skin and those carried to it", "[rules][golf][formats]") {
  // Hole 1 tied (carried), hole 2 B alone (2 skins), hole 3 tied, hole 4 C alone (2), hole 5 tied: 1 unwon.
  const SkinsResult s = score_skins({{4, 5, 3, 5, 4}, {4, 3, 3, 5, 4}, {5, 4, 4, 4, 5}});
  CHECK(s.winner == std::vector<int>{-1, 1, -1, 2, -1});
  CHECK(s.value == std::vector<int>{0, 2, 0, 2, 0});
  CHECK(s.skins == std::vector<int>{0, 2, 2});
  CHECK(s.unwon == 1);
  CHECK(std::accumulate(s.skins.begin(), s.skins.end(), 0) + s.unwon == 5);
}

TEST_CASE("a format by name, or the names allowed", "[rules][golf][formats]") {
  CHECK(golf_format("skins") == GolfFormat::Skins);
  try {
    golf_format("foursomes");
    FAIL("accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("allowed: stroke, match, stableford, skins") != std::string::npos);
  }
}

TEST_CASE("a hole's score in golfers' words", "[rules][golf][formats]") {
  CHECK(score_name(1, 3) == "hole in one");
  CHECK(score_name(1, 4) == "hole in one");  // an ace on a par 4 is also an albatross; the ace is what is said
  CHECK(score_name(2, 5) == "albatross");
  CHECK(score_name(3, 5) == "eagle");
  CHECK(score_name(3, 4) == "birdie");
  CHECK(score_name(4, 4).empty());
  CHECK(score_name(5, 4) == "bogey");
  CHECK(score_name(6, 4) == "double bogey");
  CHECK(score_name(7, 4) == "triple bogey");
  CHECK(score_name(9, 4) == "+5");
}
