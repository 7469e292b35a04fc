// Rounds of two to four golfers through the group model: turn order, handicap strokes, the
// formats' results from the cards (stableford by Rule 21.1b, match play with its status and
// concessions, skins), gimmes and auto-putt, and a saved round that resumes bit for bit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>

#include "game/content/course_file.hpp"
#include "game/modes/golf/golf_group.hpp"
#include "game/modes/golf/standings.hpp"
#include "game/report/report.hpp"
#include "game/report/round_json.hpp"
#include "game/report/round_save.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

GolfPlayer bot(const std::string& skill, int handicap = 0) { return {skill + " bot", skill, false, handicap, {}}; }

void play_out(GolfGroup& g) {
  int turns = 0;
  while (!g.finished()) {
    g.play_bot();
    REQUIRE(++turns < 200);
  }
}

// Each hole's words name its winner (or a half) and end on the match's status after it; a
// hole not finished has none.
void check_match_hole_words(const GolfGroup& g, const Standings& s) {
  for (std::size_t h = 0; h < s.match->holes.size(); ++h) {
    const MatchHole& mh = s.match->holes[h];
    const std::string words = g.match_hole_words(h), number = std::to_string(g.course().holes[h].number);
    CHECK(words.starts_with(mh.winner < 0 ? "Hole " + number + " halved: "
                                          : g.players()[static_cast<std::size_t>(mh.winner)].name + " wins hole " + number + ": "));
    CHECK(words.ends_with(": " + mh.status));
  }
  CHECK(g.match_hole_words(s.match->holes.size()).empty());
}

}  // namespace

TEST_CASE("a 3-player stableford round: points from net strokes by Rule 21.1b, strokes by stroke index", "[modes][golf][formats]") {
  GolfOptions o;
  o.format = GolfFormat::Stableford;
  o.seed = 11;
  GolfGroup g(test::assets(), test::links(), {bot("tour", 0), bot("amateur", 15), bot("beginner", 28)}, o);
  play_out(g);
  const Standings s = standings(g);
  REQUIRE(s.holes == 3);
  // links: hole 1 (154 m) index 3, hole 2 (369 m) index 1, hole 3 (483 m) index 2. A 15
  // plays off 15·3/18 = 2.5 -> 3 strokes, one a hole; a 28 off 4.67 -> 5: two on the holes
  // of index 1 and 2, one on index 3.
  CHECK(g.strokes_received(0) == std::vector<int>{0, 0, 0});
  CHECK(g.strokes_received(1) == std::vector<int>{1, 1, 1});
  CHECK(g.strokes_received(2) == std::vector<int>{1, 2, 2});
  for (int p = 0; p < 3; ++p) {
    const PlayerStanding& ps = s.players[static_cast<std::size_t>(p)];
    int total = 0;
    for (std::size_t h = 0; h < 3; ++h) {
      const HoleCard& c = g.round(p).card()[h];
      const int net = c.strokes - g.strokes_received(p)[h];
      // The table: 2 for net par, one more per stroke under, one less per stroke over, never below 0.
      // A hole picked up has no score: 0 points.
      const int expected = !c.holed || net >= c.par + 2 ? 0 : c.par + 2 - net;
      CHECK(ps.points[h] == expected);
      total += expected;
    }
    CHECK(ps.total_points == total);
  }
  // Ranked by points, most first.
  for (std::size_t k = 1; k < s.ranking.size(); ++k)
    CHECK(s.players[static_cast<std::size_t>(s.ranking[k - 1])].total_points >=
          s.players[static_cast<std::size_t>(s.ranking[k])].total_points);
  // Those tied for the most points are all leaders, and only they.
  for (int p = 0; p < 3; ++p) {
    const bool top = s.players[static_cast<std::size_t>(p)].total_points == s.players[static_cast<std::size_t>(s.ranking.front())].total_points;
    CHECK((std::find(s.leaders.begin(), s.leaders.end(), p) != s.leaders.end()) == top);
  }
  // The JSON carries the same points and each hole's wind.
  const nlohmann::json j = group_json(g);
  CHECK(j["format"] == "stableford");
  REQUIRE(j["players"].size() == 3);
  for (const auto& p : j["players"])
    for (const auto& h : p["holes"]) CHECK((h.contains("points") && h.contains("wind_mps") && h.contains("wind_toward_deg")));
}

TEST_CASE("turn order: honours on the tee, then the ball farthest from the hole", "[modes][golf][formats]") {
  GolfGroup g(test::assets(), test::links(), {bot("beginner"), bot("tour"), bot("amateur")}, {});
  // Hole 1: everyone tees off in the order given.
  for (int p = 0; p < 3; ++p) {
    REQUIRE(g.to_play() == p);
    g.play_bot();
  }
  int turns = 0;
  while (g.hole_index() == 0) {
    // The player to play lies farthest from the cup among those still on the hole.
    const int next = g.to_play();
    for (int p = 0; p < 3; ++p)
      if (g.round(p).hole_index() == 0) CHECK(g.round(p).to_pin() <= g.round(next).to_pin());
    g.play_bot();
    REQUIRE(++turns < 60);
  }
  // Hole 2: the lowest score on hole 1 has the honour (ties in the order they teed off).
  std::vector<int> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return g.round(a).card()[0].strokes < g.round(b).card()[0].strokes; });
  for (int p : order) {
    REQUIRE(g.to_play() == p);
    g.play_bot();
  }
}

TEST_CASE("a player who has holed out while the group plays on counts that hole in his running total", "[modes][golf][formats]") {
  GolfGroup g(test::assets(), test::links(), {bot("tour"), bot("beginner")}, {});
  // Play hole 1 out, then hole 2 until one player has finished it and the other has not.
  int turns = 0;
  const auto finished_2 = [&](int p) { return g.round(p).hole_index() > 1; };
  while (!(g.hole_index() == 1 && (finished_2(0) != finished_2(1)))) {
    g.play_bot();
    REQUIRE(++turns < 80);
  }
  const Standings s = standings(g);
  REQUIRE(s.holes == 1);  // the standings hold hole 1 only: the group is still on hole 2
  const int done = finished_2(0) ? 0 : 1, playing = 1 - done;
  const HoleCard& h1 = g.round(done).card()[0];
  const HoleCard& h2 = g.round(done).card()[1];
  const RunningTotal t = running_total(g, s, done, 1);
  CHECK(t.holes == 2);
  CHECK(t.strokes == h1.strokes + h2.strokes);
  CHECK(t.par == h1.par + h2.par);
  // The one still playing it stands on hole 1's score.
  const RunningTotal u = running_total(g, s, playing, 1);
  CHECK(u.holes == 1);
  CHECK(u.strokes == g.round(playing).card()[0].strokes);
  CHECK(u.par == g.round(playing).card()[0].par);
  // Once the group is off the hole, the standings hold it and nothing is counted twice.
  while (g.hole_index() == 1) {
    g.play_bot();
    REQUIRE(++turns < 160);
  }
  const Standings after = standings(g);
  CHECK(running_total(g, after, done, 1).strokes == after.players[static_cast<std::size_t>(done)].total_strokes);
  CHECK(running_total(g, after, done, 1).strokes == t.strokes);
  // The stroke that finished the hole for the last of them still in the air: not his yet.
  const RunningTotal untold = running_total(g, after, playing, 1, true);
  CHECK(untold.holes == 1);
  CHECK(untold.strokes == g.round(playing).card()[0].strokes);
  CHECK(running_total(g, after, playing, 1).strokes == after.players[static_cast<std::size_t>(playing)].total_strokes);
}

TEST_CASE("match play: the status follows the holes won, a short putt is conceded, a conceded hole is lost", "[modes][golf][formats]") {
  GolfOptions o;
  o.format = GolfFormat::Match;
  o.gimme_m = kMatchGimme;
  o.seed = 4;
  GolfGroup g(test::assets(), test::links(), {bot("tour", 2), bot("amateur", 14)}, o);
  // Match play gives the difference: 12 over three holes is 2 strokes, on index 1 and 2.
  CHECK(g.strokes_received(0) == std::vector<int>{0, 0, 0});
  CHECK(g.strokes_received(1) == std::vector<int>{0, 1, 1});
  // The first player concedes hole 1 at their second turn.
  g.play_bot();
  g.play_bot();
  REQUIRE(g.to_play() >= 0);
  const int conceder = g.to_play();
  g.concede_hole();
  CHECK(g.hole_index() == 1);
  CHECK(g.round(conceder).card()[0].conceded);
  play_out(g);
  const Standings s = standings(g);
  REQUIRE(s.match);
  CHECK(s.match->holes[0].winner == 1 - conceder);
  // The match ends where it is decided (Rule 3.2a(3)): the holes left are not played.
  REQUIRE(g.finished());
  REQUIRE(s.holes == s.match->holes.size());
  if (s.match->decided_after >= 0) CHECK(s.holes == static_cast<std::size_t>(s.match->decided_after) + 1);
  else CHECK(s.holes == 3);
  int lead = 0;
  for (std::size_t h = 0; h < s.holes; ++h) {
    const int a = s.players[0].net[h], b = s.players[1].net[h];
    const int winner = h == 0 ? 1 - conceder : a < b ? 0 : b < a ? 1 : -1;
    CHECK(s.match->holes[h].winner == winner);
    lead += winner == 0 ? 1 : winner == 1 ? -1 : 0;
  }
  CHECK(s.match->lead == lead);
  // The conceded hole has no score for either side (the conceder's strokes so far, the other
  // side's left unfinished): the totals and "to par" are the holes played out only, so two
  // strokes on a par 4 never read as two under.
  for (std::size_t p = 0; p < 2; ++p) {
    const PlayerStanding& ps = s.players[p];
    CHECK_FALSE(ps.scored[0]);
    int strokes = 0, par = 0;
    for (std::size_t h = 1; h < s.holes; ++h) {
      CHECK(ps.scored[h]);
      strokes += ps.gross[h];
      par += g.course().holes[h].par;
    }
    CHECK(ps.total_strokes == strokes);
    CHECK(ps.total_par == par);
    // The card's total says over which holes and their par, beside the course's par column.
    CHECK(ps.total_text(s.holes) == std::to_string(strokes) + " in " + std::to_string(s.holes - 1) +
                                        (s.holes - 1 == 1 ? " hole" : " holes") + " (par " + std::to_string(par) + ")");
  }
  // Every conceded putt was inside the gimme; no putt was played from inside it.
  for (int p = 0; p < 2; ++p)
    for (const HoleCard& c : g.round(p).card())
      for (std::size_t k = 0; k < c.shots.size(); ++k) {
        const StrokeRecord& st = c.shots[k];
        if (st.lie != "green") continue;
        const double from = std::hypot(st.start.x() - g.course().holes[static_cast<std::size_t>(c.number - 1)].pin.x(),
                                       st.start.z() - g.course().holes[static_cast<std::size_t>(c.number - 1)].pin.z());
        if (st.conceded) CHECK(from <= kMatchGimme + 1e-9);
        else CHECK(from > kMatchGimme);
      }
  // Stroke play refuses a concession.
  GolfGroup stroke(test::assets(), test::links(), {bot("tour")}, {});
  CHECK_THROWS_AS(stroke.concede_hole(), InputError);
  // Skins alone would win every hole: refused as match play alone is.
  GolfOptions skins;
  skins.format = GolfFormat::Skins;
  CHECK_THROWS_WITH(GolfGroup(test::assets(), test::links(), {bot("tour")}, skins), Catch::Contains("skins is played by 2 to 4"));
}

TEST_CASE("a match decided with holes to play ends there; the card, the result and the JSON hold its holes only",
          "[modes][golf][formats]") {
  GolfOptions o;
  o.format = GolfFormat::Match;
  o.seed = 3;
  GolfGroup g(test::assets(), load_course(test::assets(), "national"), {bot("tour", 0), bot("beginner", 0)}, o);
  play_out(g);
  const Standings s = standings(g);
  REQUIRE(s.match);
  REQUIRE(s.match->decided_after >= 0);
  CHECK(s.holes == static_cast<std::size_t>(s.match->decided_after) + 1);
  CHECK(s.holes < 18);
  CHECK(s.match->result.find(" wins ") != std::string::npos);
  check_match_hole_words(g, s);
  CHECK(s.match->result.find('&') != std::string::npos);
  for (int p = 0; p < 2; ++p) {
    CHECK(s.players[static_cast<std::size_t>(p)].gross.size() == s.holes);
    int strokes = 0;
    for (std::size_t h = 0; h < s.holes; ++h) strokes += g.round(p).card()[h].strokes;
    CHECK(s.players[static_cast<std::size_t>(p)].total_strokes == strokes);
  }
  // A round replayed from its events ends at the same hole.
  GolfGroup again(test::assets(), load_course(test::assets(), "national"), {bot("tour", 0), bot("beginner", 0)}, o);
  again.replay(g.events());
  CHECK(again.finished());
  CHECK(again.hole_index() == g.hole_index());
}

TEST_CASE("match play: a player who can no longer halve the hole picks it up instead of putting out", "[modes][golf][formats]") {
  // Tour against beginner, level: the beginner often lies more than the tour bot holed out in
  // before he reaches the green. Played as `round` and the window play a bot's turn.
  GolfOptions o;
  o.format = GolfFormat::Match;
  o.seed = 3;
  GolfGroup g(test::assets(), load_course(test::assets(), "national_3"), {bot("tour", 0), bot("beginner", 0)}, o);
  int turns = 0, conceded = 0;
  while (!g.finished()) {
    REQUIRE(++turns < 400);
    const int p = g.to_play();
    const std::size_t h = g.round(p).hole_index();
    const GolfRound& other = g.round(1 - p);
    // Lost: the opponent is done with the hole (holed, or picked up), in fewer strokes than
    // this player's next one would make his.
    const bool lost = other.hole_index() > h && !other.card()[h].conceded && other.card()[h].strokes < g.round(p).card()[h].strokes + 1;
    CHECK(g.hole_lost_for_next() == lost);
    if (g.hole_lost_for_next()) {
      g.concede_hole();
      ++conceded;
      CHECK(g.round(p).card()[h].conceded);
      // The opponent had holed out: conceding ends the hole, and the note says who won it.
      const std::string number = std::to_string(g.course().holes[h].number);
      CHECK(g.note().starts_with(g.players()[static_cast<std::size_t>(p)].name + " concedes hole " + number + ". " +
                                 g.players()[static_cast<std::size_t>(1 - p)].name + " wins hole " + number + ": "));
    } else {
      const std::size_t group_hole = g.hole_index();
      g.play_bot();
      // The turn that finishes a hole tells its result and the match's standing.
      if (g.hole_index() > group_hole) CHECK(g.note().ends_with(g.match_hole_words(group_hole)));
    }
  }
  CHECK(conceded > 0);
  // The match's result stands on its holes: a conceded hole is the opponent's.
  const Standings s = standings(g);
  REQUIRE(s.match);
  CHECK(s.match->result.find(" wins ") != std::string::npos);
  check_match_hole_words(g, s);
}

TEST_CASE("gimmes and auto-putt: conceded putts count one stroke, auto-putts count what the physics holes", "[modes][golf][formats]") {
  GolfOptions o;
  o.gimme_m = 2.0;
  o.seed = 3;
  GolfGroup g(test::assets(), test::links(), {bot("amateur")}, o);
  play_out(g);
  int conceded = 0;
  for (const HoleCard& c : g.round(0).card()) {
    CHECK(c.holed);
    CHECK(c.strokes == static_cast<int>(c.shots.size()) + c.penalties);
    for (const StrokeRecord& st : c.shots) conceded += st.conceded;
    if (c.shots.back().conceded) CHECK(c.shots.back().lie == "green");
  }
  // With a 2 m gimme an amateur's round has at least one conceded putt (never more than one a hole).
  CHECK(conceded >= 1);
  CHECK(conceded <= 3);

  // A human on auto-putt: their putts are the bot's turns, and the card counts every one.
  GolfOptions a;
  a.auto_putt = true;
  a.seed = 8;
  GolfGroup h(test::assets(), test::links(), {{"You", "amateur", true, 0, {}}}, a);
  int putts_auto = 0, turns = 0;
  while (!h.finished()) {
    const bool green = h.round(0).lie() == "green";
    CHECK(h.bot_turn() == green);
    if (green) ++putts_auto;
    h.play_bot();  // the test plays the human's long game with the caddie
    REQUIRE(++turns < 80);
  }
  int putts = 0;
  for (const HoleCard& c : h.round(0).card()) putts += c.putts;
  CHECK(putts == putts_auto);
}

TEST_CASE("a saved round resumes to the same state and finishes bit for bit the same", "[modes][golf][formats][save]") {
  GolfOptions o;
  o.format = GolfFormat::Skins;
  o.seed = 5;
  const std::vector<GolfPlayer> players{bot("tour", 0), bot("scratch", 2), bot("amateur", 15), {"You", "amateur", true, 18, {}}};
  GolfGroup whole(test::assets(), test::links(), players, o);
  play_out(whole);

  GolfGroup part(test::assets(), test::links(), players, o);
  for (int k = 0; k < 9; ++k) part.play_bot();
  const std::string text = json_text(round_save_json(part, test::links().source.string()));
  GolfGroup resumed = resume_round(test::assets(), parse_round_save(text, "save.json"));
  CHECK(resumed.to_play() == part.to_play());
  CHECK(resumed.hole_index() == part.hole_index());
  CHECK(json_text(group_json(resumed)) == json_text(group_json(part)));
  play_out(resumed);
  CHECK(json_text(group_json(resumed)) == json_text(group_json(whole)));
  // A save whose bot strokes this build would not play is refused, naming the event.
  nlohmann::json bad = nlohmann::json::parse(text);
  bad["events"][0]["power"] = 0.5;
  try {
    resume_round(test::assets(), parse_round_save(bad.dump(), "save.json"));
    FAIL("accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("event 1") != std::string::npos);
  }
  bad = nlohmann::json::parse(text);
  bad["players"][1]["handicap"] = 60;
  CHECK_THROWS_WITH(parse_round_save(bad.dump(), "save.json"), Catch::Contains("players[1].handicap") && Catch::Contains("54"));
  // A number beyond a double (1e999) is bad input naming the file, not an internal error.
  std::string huge = text;
  huge.replace(huge.find("\"sweetspot_round\""), 0, "\"gimme_m\": 1e999, ");
  CHECK_THROWS_AS(parse_round_save(huge, "save.json"), InputError);
  CHECK_THROWS_WITH(parse_round_save(huge, "save.json"), Catch::Contains("save.json"));
  // Keys the save does not have were dropped without a word; a key given twice was read as
  // one of them by guess.
  bad = nlohmann::json::parse(text);
  bad["sed"] = 3;
  CHECK_THROWS_WITH(parse_round_save(bad.dump(), "save.json"), Catch::Contains("save.json: sed: unknown key") && Catch::Contains("seed"));
  bad = nlohmann::json::parse(text);
  bad["players"][0]["skil"] = "tour";
  CHECK_THROWS_WITH(parse_round_save(bad.dump(), "save.json"), Catch::Contains("players[0].skil: unknown key"));
  bad = nlohmann::json::parse(text);
  bad["events"][0]["aim"] = 0.1;
  CHECK_THROWS_WITH(parse_round_save(bad.dump(), "save.json"), Catch::Contains("events[0].aim: unknown key") && Catch::Contains("aim_rad"));
  std::string twice = text;
  twice.replace(twice.find("\"sweetspot_round\""), 0, "\"seed\": 99, ");
  CHECK_THROWS_WITH(parse_round_save(twice, "save.json"), Catch::Contains("save.json") && Catch::Contains("round.seed is given twice"));
}

TEST_CASE("a save keeps the window's record of the round: each hole's restarts and the swings cancelled", "[modes][golf][save]") {
  GolfGroup g(test::assets(), test::links(), {bot("tour")}, {});
  for (int k = 0; k < 3; ++k) g.play_bot();
  const std::string text = json_text(round_save_json(g, test::links().source.string(), {0, 2}, 5));
  const SavedRound s = parse_round_save(text, "save.json");
  CHECK(s.restarts == std::vector<int>{0, 2});
  CHECK(s.cancelled == 5);
  // A headless round's save (and an older one) has neither: none read.
  nlohmann::json old = nlohmann::json::parse(text);
  old.erase("restarts");
  old.erase("cancelled");
  const SavedRound none = parse_round_save(old.dump(), "save.json");
  CHECK(none.restarts.empty());
  CHECK(none.cancelled == 0);
  // Bad values name the key and what is allowed.
  nlohmann::json bad = nlohmann::json::parse(text);
  bad["restarts"] = {0, 1, 0, 0};  // the links has 3 holes
  CHECK_THROWS_WITH(parse_round_save(bad.dump(), "save.json"), Catch::Contains("save.json") && Catch::Contains("restarts") && Catch::Contains("at most 3"));
  bad["restarts"] = {0, -1};
  CHECK_THROWS_WITH(parse_round_save(bad.dump(), "save.json"), Catch::Contains("restarts[1]") && Catch::Contains("whole number"));
  bad["restarts"] = {0, 1.5};
  CHECK_THROWS_WITH(parse_round_save(bad.dump(), "save.json"), Catch::Contains("restarts[1]"));
  bad = nlohmann::json::parse(text);
  bad["cancelled"] = -2;
  CHECK_THROWS_WITH(parse_round_save(bad.dump(), "save.json"), Catch::Contains("cancelled"));
}
