// A game of baseball (ball_game.hpp): the box score adds up, nine innings make 27 outs a
// side, the same seed plays the same game, and the league's hitter against the league's
// pitcher bats as MLB's hitters do (2023-24 league rates, Baseball-Reference / FanGraphs:
// K% 22.7 / 22.6, BB% 8.6 / 8.2, BABIP .297 / .291, HR per PA 3.2 % / 3.0 %, SLG .414 / .399;
// Statcast: ~25 % whiffs per swing, ~17 % of pitches fouled).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "game/modes/baseball/ball_game.hpp"
#include "game/modes/baseball/pitcher.hpp"
#include "game/report/box_score.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

// Outs a side made, from the plate appearances.
int outs_of(const GameRecord& g, bool bottom) {
  int outs = 0;
  for (const PlateAppearance& pa : g.plate_appearances)
    if (pa.bottom == bottom) outs += pa.outs_made;
  return outs;
}

std::vector<PlateAppearance> games(const std::string& skill, int count, std::uint64_t first_seed, int* innings) {
  std::vector<PlateAppearance> all;
  for (int i = 0; i < count; ++i) {
    GameOptions o;
    o.away = o.home = skill;
    o.seed = first_seed + static_cast<std::uint64_t>(i);
    const GameRecord g = play_game(test::assets(), o);
    *innings += g.innings_played;
    all.insert(all.end(), g.plate_appearances.begin(), g.plate_appearances.end());
  }
  return all;
}

}  // namespace

TEST_CASE("a nine-inning game: the box score adds up, 27 outs a side unless the home team need not bat or walks off",
          "[baseball][game]") {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    GameOptions o;
    o.seed = seed;
    const GameRecord g = play_game(test::assets(), o);
    INFO("seed " << seed << "\n" << box_score_text(g));
    CHECK(box_score_mismatch(g.away, g.home) == "");
    CHECK(box_score_mismatch(g.home, g.away) == "");
    CHECK(decisions_mismatch(g.away, g.home) == "");  // a W, an L, at most one S; ER among R
    CHECK(g.away.runs != g.home.runs);  // no ties
    CHECK_FALSE(g.stopped_tied);
    CHECK(g.innings_played >= 9);
    const int innings = g.innings_played;
    CHECK(outs_of(g, false) == 3 * innings);
    CHECK(g.away.pitching.outs == outs_of(g, true));
    CHECK(g.home.pitching.outs == 3 * innings);
    if (g.walk_off) {
      CHECK(g.home.runs > g.away.runs);
      CHECK(outs_of(g, true) < 3 * innings);
      CHECK(outs_of(g, true) >= 3 * (innings - 1));
    } else if (g.home.runs > g.away.runs) {
      CHECK(outs_of(g, true) == 3 * (innings - 1));  // the home team did not bat in the last
    } else {
      CHECK(outs_of(g, true) == 3 * innings);
    }
    // The starter gives way to the bullpen: nobody throws a hundred and fifty pitches.
    for (const TeamBox* t : {&g.away, &g.home}) {
      CHECK(t->pitchers.size() >= 2);
      for (const PitchingLine& p : t->pitchers) CHECK(p.pitches <= 135);
    }
    // Runs by inning: one entry a half played.
    CHECK(g.away.runs_by_inning.size() == static_cast<std::size_t>(innings));
    // Every plate appearance ends in one of the documented results.
    for (const PlateAppearance& pa : g.plate_appearances) {
      const std::string& r = pa.result;
      CHECK((r == "strikeout" || r == "walk" || r == "hit_by_pitch" || r == "out" || r == "single" || r == "double" ||
             r == "triple" || r == "home_run" || r == "error"));
      CHECK_FALSE(pa.description.empty());
      CHECK_FALSE(pa.pitches.empty());
    }
  }
}

TEST_CASE("earned runs: each error counts as the out it should have been (Rule 9.16(a))", "[baseball][game]") {
  // Rebuilt half-inning by half-inning from the plate appearances: no run is earned once the
  // outs and the errors that put batters aboard make three (or on the play whose out makes
  // them three), and the pitchers' earned runs are the plate appearances' own.
  // Games are played seed by seed until one of them holds such a run (seed 1 today): every
  // game checks the sums, and the rule is seen to act without playing a dozen games under
  // the sanitizers (a game there takes ~20 s).
  int with_unearned = 0;
  for (std::uint64_t seed = 1; seed <= 24 && with_unearned < 1; ++seed) {
    GameOptions o;
    o.seed = seed;
    const GameRecord g = play_game(test::assets(), o);
    int earned[2] = {0, 0}, errors = 0, half = -1, unearned = 0;
    for (const PlateAppearance& pa : g.plate_appearances) {
      if (2 * pa.inning + pa.bottom != half) {
        half = 2 * pa.inning + pa.bottom;
        errors = 0;
      }
      CHECK(pa.earned_runs >= 0);
      CHECK(pa.earned_runs <= pa.runs);
      const bool past = pa.outs_before + errors + (pa.result == "error") >= 3 ||
                        (pa.outs_made > 0 && errors > 0 && pa.outs_before + pa.outs_made + errors >= 3);
      if (past) {
        INFO("seed " << seed << ", inning " << pa.inning << ": " << pa.description);
        CHECK(pa.earned_runs == 0);
        unearned += pa.runs > 0;
      }
      if (pa.result == "error") ++errors;
      earned[pa.bottom ? 1 : 0] += pa.earned_runs;
    }
    CHECK(earned[0] == g.home.pitching.er);
    CHECK(earned[1] == g.away.pitching.er);
    with_unearned += unearned > 0;
  }
  CHECK(with_unearned > 0);  // games with runs the errors made unearned
  // With two out the error itself is the third out it should have been: seed 173's first
  // inning, "Reached on an error by 2B", a run scores, unearned.
  GameOptions o;
  o.seed = 173;
  int two_out_errors = 0;
  for (const PlateAppearance& pa : play_game(test::assets(), o).plate_appearances)
    if (pa.result == "error" && pa.outs_before == 2 && pa.runs > 0) {
      ++two_out_errors;
      CHECK(pa.earned_runs == 0);
    }
  CHECK(two_out_errors > 0);
}

TEST_CASE("earned runs: a run that beats the third out on its play counts and is earned when no error came first",
          "[baseball][game]") {
  // A time play (Rule 5.08(a)): a hit with two out scores a runner before another is put out
  // for the third out. With no error in the half the inning is as it went, and the run is
  // earned (Rule 9.16(a)); it was charged unearned. Games seed by seed until one is seen.
  int time_plays = 0;
  for (std::uint64_t seed = 1; seed <= 40 && time_plays == 0; ++seed) {
    GameOptions o;
    o.seed = seed;
    int errors = 0, half = -1;
    for (const PlateAppearance& pa : play_game(test::assets(), o).plate_appearances) {
      if (2 * pa.inning + pa.bottom != half) {
        half = 2 * pa.inning + pa.bottom;
        errors = 0;
      }
      if (pa.result == "error") ++errors;
      if (errors == 0 && pa.inning <= 9 && pa.outs_made > 0 && pa.outs_before + pa.outs_made >= 3 && pa.runs > 0) {
        INFO("seed " << seed << ", inning " << pa.inning << ": " << pa.description);
        CHECK(pa.earned_runs == pa.runs);
        ++time_plays;
      }
    }
  }
  CHECK(time_plays > 0);
}

TEST_CASE("the play-by-play reads as a scorer's: sacrifice flies named, infield flies popped up", "[baseball][game]") {
  // Game by game (pros, from seed 40) until both have been seen, at most twelve games.
  int innings = 0, sac = 0, pops = 0;
  for (int game = 0; game < 12 && (sac == 0 || pops == 0); ++game) {
    for (const PlateAppearance& pa : games("pro", 1, 40 + static_cast<std::uint64_t>(game), &innings)) {
      INFO(pa.description);
      const bool named = pa.description.rfind("Sacrifice fly to ", 0) == 0;
      CHECK(named == pa.sacrifice_fly);
      sac += pa.sacrifice_fly;
      if (pa.result != "out" || pa.pitches.empty() || !pa.pitches.back().result.play.caught) continue;
      const FieldingPlay& f = pa.pitches.back().result.play;
      if (f.foul || named) continue;
      // An infielder's catch of a fly is a pop out; an outfielder's never is.
      const bool popped = pa.description.rfind("Pop out to ", 0) == 0;
      if (f.fielder < 6 && (f.type == BattedBallType::FlyBall || f.type == BattedBallType::PopUp)) CHECK(popped);
      if (f.fielder >= 6) CHECK_FALSE(popped);
      pops += popped;
    }
  }
  CHECK(sac > 0);
  CHECK(pops > 0);
}

TEST_CASE("the same seed plays the same game; bad options are refused", "[baseball][game]") {
  GameOptions o;
  o.innings = 3;
  o.seed = 9;
  CHECK(game_json(play_game(test::assets(), o)) == game_json(play_game(test::assets(), o)));
  o.innings = 0;
  CHECK_THROWS_AS(play_game(test::assets(), o), InputError);
  o.innings = 3;
  o.home = "legend";
  CHECK_THROWS_AS(play_game(test::assets(), o), InputError);
}

namespace {
const std::vector<GameRecord>& league_games();  // below: a hundred league games

// The league's hitter against the league's pitcher: forty seeded games, both lineups batting
// (360 innings, ~3000 plate appearances). Each game draws its teams' fielders and its pitchers
// afresh, so games differ by more than their plate appearances' chance: twelve games' BABIP
// ranged .29-.38 between seed sets.
const std::vector<PlateAppearance>& pro_games() {
  static const std::vector<PlateAppearance> pas = [] {
    int innings = 0;
    std::vector<PlateAppearance> v = games("pro", 40, 101, &innings);
    REQUIRE(innings >= 60);
    return v;
  }();
  return pas;
}
const BattingRates& pro_rates() {
  static const BattingRates r = batting_rates(pro_games(), 2);
  return r;
}
}  // namespace

TEST_CASE("over 60+ innings the league's hitter strikes out, walks and hits balls in play as MLB's do; the amateur "
          "clearly below",
          "[baseball][game][reference][statistics]") {
  const BattingRates& pro = pro_rates();
  INFO(rates_text(pro, "pro"));
  CHECK(pro.k_rate >= 0.18);
  CHECK(pro.k_rate <= 0.27);
  CHECK(pro.bb_rate >= 0.06);
  CHECK(pro.bb_rate <= 0.11);
  CHECK(pro.hbp_rate >= 0.004);
  CHECK(pro.hbp_rate <= 0.02);
  CHECK(pro.babip >= 0.267);
  CHECK(pro.babip <= 0.327);
  // Per pitch: whiffs per swing near Statcast's league (~25 %), fouls at least near its ~17.5 %
  // of pitches (the published band is checked below), and the league's swing rate (~47 %).
  CHECK(pro.whiff_per_swing >= 0.20);
  CHECK(pro.whiff_per_swing <= 0.32);
  CHECK(pro.foul_per_pitch >= 0.12);
  CHECK(pro.swing_rate >= 0.40);
  CHECK(pro.swing_rate <= 0.55);
  int amateur_innings = 0;
  const BattingRates amateur = batting_rates(games("amateur", 2, 201, &amateur_innings), 2);
  INFO(rates_text(amateur, "amateur"));
  CHECK(amateur.k_rate > pro.k_rate + 0.08);
  CHECK(amateur.slg < pro.slg - 0.10);
  CHECK(amateur.whiff_per_swing > pro.whiff_per_swing);
}

// Power comes from the swing's arc: the hitter meets the ball on a path that climbs the more
// the earlier he is (attack_angle_at), so his fly balls come from the path as well as from
// under the ball's centre, and leave the bat with less backspin than an undercut alone gives.
TEST_CASE("over 60+ innings the league's hitter hits for MLB's power", "[baseball][game][reference][statistics]") {
  const BattingRates& pro = pro_rates();
  INFO(rates_text(pro, "pro"));
  CHECK(pro.hr_rate >= 0.020);
  CHECK(pro.hr_rate <= 0.045);
  CHECK(pro.slg >= 0.360);
  CHECK(pro.slg <= 0.460);
}

// Infield hits: a grounder the infielder reaches only on the run away from first, or with a
// dive, leaves the batter time to beat the throw. FanGraphs' league infield-hit rate (IFH%,
// infield hits per ground ball) runs ~6-8 %, its leaders ~13 % (FanGraphs, "Rhys Hoskins'
// Secret to Infield Hit Immortality", 2024: 13.2 % third best), and the league's BABIP on
// ground balls ~.24 (FanGraphs' batted-ball splits). Bands: IFH% 4-11 %, ground-ball BABIP
// .20-.28 over the ~1500 grounders here.
TEST_CASE("over 60+ innings grounders become infield hits and singles as MLB's do", "[baseball][game][reference][statistics]") {
  int grounders = 0, infield_hits = 0, hits = 0;
  for (const PlateAppearance& pa : pro_games()) {
    const PitchRecord& last = pa.pitches.back();
    if (!last.swung || !last.result.contact) continue;
    const SwingResult& r = last.result;
    if (r.outcome == BattedOutcome::Foul || r.outcome == BattedOutcome::HomeRun) continue;
    const bool hit = r.outcome == BattedOutcome::Single || r.outcome == BattedOutcome::Double || r.outcome == BattedOutcome::Triple;
    infield_hits += hit && r.play.fielder >= 0 && r.play.fielder < 6 ? 1 : 0;  // of any kind, as FanGraphs counts them
    if (r.play.type != BattedBallType::GroundBall) continue;
    ++grounders;
    hits += hit ? 1 : 0;
  }
  REQUIRE(grounders >= 800);
  const double ifh = static_cast<double>(infield_hits) / grounders, babip = static_cast<double>(hits) / grounders;
  INFO(grounders << " ground balls: " << infield_hits << " infield hits (" << ifh << "), BABIP " << babip);
  CHECK(ifh >= 0.04);
  CHECK(ifh <= 0.11);
  CHECK(babip >= 0.20);
  CHECK(babip <= 0.28);
}

// Behind the plate there is the backstop, 60 ft out (Rule 2.01): a foul back is dead there,
// into it or over it; along the lines the stands' front wall keeps the rest in foul ground.
// Over the statistics tests' shared 60+ innings (the Release suite); the sanitizer stage
// meets stop_at_backstop in the short games above.
TEST_CASE("over 60+ innings no foul ball comes to rest beyond the backstop", "[baseball][game][statistics]") {
  int behind = 0;
  for (const PlateAppearance& pa : pro_games())
    for (const PitchRecord& p : pa.pitches) {
      if (!p.swung || !p.result.contact || p.result.outcome != BattedOutcome::Foul) continue;
      const Vec3& r = p.result.shot.trajectory.summary.rest_position;
      if (!(std::abs(r.z()) < -r.x())) continue;  // behind the plate, between the two lines of stands
      ++behind;
      INFO("a foul back rests at " << r.transpose());
      CHECK(std::hypot(r.x(), r.z()) <= kFoulGround + 1e-6);
    }
  CHECK(behind >= 100);  // it saw foul backs (a third of fouls, as 538's foul-ball study)
}

// The batted ball's backspin against Statcast's average by launch angle. A. M. Nathan's
// trajectory calculator (TrajectoryCalculator-new-3D, fitted to Statcast) gives the average
// backspin of a ball hit straightaway as -763 + 120·LA rpm (LA in degrees): 1937 rpm at
// 22.5°, 2537 at 27.5°, 3137 at 32.5°. Band: 25 % of it. Single balls scatter by ~700 rpm, so
// the game's average is the least-squares line through every straightaway ball from 20° to
// 35° (~180 balls here: ~60 rpm at the ends of the range; a median of one 5° bin, ~60 balls,
// would scatter by ~120). It holds because the contact's tangential rebound is the
// laboratories' single e_x at every angle (balls.toml, test_delivery.cpp).
TEST_CASE("batted backspin by launch angle follows Statcast's average (Nathan's calculator)",
          "[baseball][game][reference][statistics]") {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const PlateAppearance& pa : pro_games()) {
    const PitchRecord& last = pa.pitches.back();
    if (!last.swung || !last.result.contact || last.result.outcome == BattedOutcome::Foul) continue;
    const LaunchMetrics& L = last.result.shot.launch;
    const double la = rad_to_deg(L.vertical_angle);
    if (std::abs(rad_to_deg(L.horizontal_angle)) > 15.0 || la < 20.0 || la >= 35.0) continue;  // straightaway fly balls
    const double spin = radps_to_rpm(L.spin.backspin);
    n += 1.0;
    sx += la;
    sy += spin;
    sxx += la * la;
    sxy += la * spin;
  }
  REQUIRE(n >= 100.0);
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), intercept = (sy - slope * sx) / n;
  for (double la : {22.5, 27.5, 32.5}) {
    const double got = intercept + slope * la, nathan = -763.0 + 120.0 * la;
    INFO("launch " << la << " deg: backspin " << got << " rpm on the line through " << n
                   << " balls (slope " << slope << " rpm/deg); Statcast average " << nathan);
    CHECK(got == Approx(nathan).epsilon(0.25));
  }
}

namespace {
// Whiffs per swing by pitch type over the league hitter's games.
std::map<std::string, double> whiffs_by_type() {
  std::map<std::string, std::pair<int, int>> by_type;  // swings, whiffs
  for (const PlateAppearance& pa : pro_games())
    for (const PitchRecord& p : pa.pitches) {
      if (!p.swung) continue;
      auto& t = by_type[p.planned.call.type.type];
      ++t.first;
      t.second += p.result.contact ? 0 : 1;
    }
  std::map<std::string, double> rate;
  for (const auto& [type, t] : by_type) {
    REQUIRE(t.first >= 200);
    rate[type] = static_cast<double>(t.second) / t.first;
  }
  return rate;
}
// FanGraphs' "Know Your Averages 2024" (Statcast): whiffs per swing (swinging strikes / swings).
const std::map<std::string, double> kStatcastWhiffs{{"four-seam", 0.209}, {"sinker", 0.131}, {"cutter", 0.214},
                                                    {"slider", 0.315},    {"curveball", 0.288}, {"changeup", 0.262}};
}  // namespace

// Whiffs come from the bat's path missing the ball's, and a hitter sits on the fastball: the
// pitch that beats him unread is the slower one he is early on and over. Band: each type within
// 10 points of Statcast's; both fastballs below every breaking and off-speed type.
TEST_CASE("over 60+ innings whiffs per swing by pitch type follow Statcast's", "[baseball][game][reference][statistics]") {
  const std::map<std::string, double> rate = whiffs_by_type();
  for (const auto& [type, published] : kStatcastWhiffs) {
    INFO(type << ": " << rate.at(type) << " of swings; Statcast " << published);
    CHECK(rate.at(type) == Approx(published).margin(0.10));
  }
  for (const char* fast : {"four-seam", "sinker"})
    for (const char* soft : {"slider", "curveball", "changeup"}) {
      INFO(fast << " " << rate.at(fast) << " against " << soft << " " << rate.at(soft));
      CHECK(rate.at(fast) < rate.at(soft));
    }
}

// The pitcher means each type for the zone as Statcast's pitchers do (PitchType::zone_share,
// FanGraphs' "Know Your Averages 2024"), by the count's odds: the changeup he throws to be
// chased, the sinker for the zone, each meant as often as his command (which scatters some
// pitches meant for an edge out of the zone and some meant to be chased into it) requires.
// Band: each type within 4 points, ~2.5 standard errors of the fewest (~1,000 curveballs);
// changeup lowest, both fastballs above every breaking and off-speed type.
TEST_CASE("over 100 games each pitch type crosses the zone as often as Statcast's", "[baseball][game][reference][statistics]") {
  // The hundred games of the bullpen test (~2,000 of the rarest type, a cutter: one binomial
  // standard deviation ~0.011 against the 0.04 band; forty games left it ~0.017).
  std::map<std::string, std::pair<int, int>> by_type;  // pitches, in the zone
  for (const GameRecord& g : league_games())
    for (const PlateAppearance& pa : g.plate_appearances)
      for (const PitchRecord& p : pa.pitches) {
        auto& t = by_type[p.planned.call.type.type];
        ++t.first;
        t.second += StrikeZone::contains(p.flight.plate, 0.0369) ? 1 : 0;
      }
  const std::map<std::string, double> published{{"four-seam", 0.544}, {"sinker", 0.563}, {"cutter", 0.511},
                                                {"slider", 0.457},    {"curveball", 0.439}, {"changeup", 0.388}};
  std::map<std::string, double> rate;
  for (const auto& [type, share] : published) {
    const auto& t = by_type.at(type);
    REQUIRE(t.first >= 300);
    rate[type] = static_cast<double>(t.second) / t.first;
    INFO(type << ": " << rate[type] << " of " << t.first << " pitches in the zone; Statcast " << share);
    CHECK(rate[type] == Approx(share).margin(0.04));
  }
  for (const auto& [type, r] : rate)
    if (type != "changeup") CHECK(rate.at("changeup") < r);
  for (const char* fast : {"four-seam", "sinker"})
    for (const char* soft : {"slider", "curveball", "changeup"}) CHECK(rate.at(fast) > rate.at(soft));
}

// Fouls: MLB's hitters have fouled off 16.3 % (1998) to 18.3 % (2023) of pitches (theScore,
// "The quiet scourge of the foul ball", from Statcast and Retrosheet; P. Berryman, "A Spotlight
// on Foul Balls": 18 % in 2023): the band. A swing off time meets the ball where the turned
// bat crosses its line, farther out along the bat (meet_ball): early or late it is pulled or
// pushed foul, a little more and it passes beyond the end. A hitter who aimed at the sweet
// spot itself would miss past the end on most of those; he aims inside it by what his scatter
// makes worth it (aim.hpp), so they come off the end of the bat, foul.
TEST_CASE("over 60+ innings fouls per pitch sit near Statcast's league", "[baseball][game][reference][statistics]") {
  const BattingRates& pro = pro_rates();
  INFO(rates_text(pro, "pro"));
  CHECK(pro.foul_per_pitch >= 0.163);
  CHECK(pro.foul_per_pitch <= 0.185);
}

namespace {

// A hundred league games, played once for the tests of the game's flow (bullpen, base running).
const std::vector<GameRecord>& league_games() {
  static const std::vector<GameRecord> games = [] {
    std::vector<GameRecord> all;
    for (std::uint64_t seed = 101; seed <= 200; ++seed) {
      GameOptions o;
      o.seed = seed;
      all.push_back(play_game(test::assets(), o));
    }
    return all;
  }();
  return games;
}

}  // namespace

TEST_CASE("over 100 games starters and relievers work as MLB's do, relieved during innings with runners charged to them",
          "[baseball][game][reference][statistics]") {
  // MLB 2023 (Baseball-Reference league pitching): starters 5.3 innings and ~88 pitches a
  // start, ~4.4 pitchers a team a game, and about 30 % of the runners relievers inherit score.
  // Starts of 6 innings or more ~40 % (The Athletic, 2021-23), of 7 or more about half 2015's
  // ~21 % by 2022 (Verducci, SI 2024; NL 2016: 21.4 %): a cruising starter goes on.
  int six_plus = 0, seven_plus = 0;
  int starts = 0, starter_outs = 0, starter_pitches = 0, pitchers = 0, relieved_mid_inning = 0, inherited = 0, scored = 0;
  int left_starters = 0, relievers = 0, left_relievers = 0;
  int knockouts = 0, knockout_staff = 0, long_outings = 0, relief_outs = 0;
  for (const GameRecord& g : league_games()) {
    CHECK(box_score_mismatch(g.away, g.home) == "");
    CHECK(box_score_mismatch(g.home, g.away) == "");
    CHECK(decisions_mismatch(g.away, g.home) == "");
    for (const TeamBox* t : {&g.away, &g.home}) {
      ++starts;
      starter_outs += t->pitchers[0].outs;
      six_plus += t->pitchers[0].outs >= 18;
      seven_plus += t->pitchers[0].outs >= 21;
      starter_pitches += t->pitchers[0].pitches;
      pitchers += static_cast<int>(t->pitchers.size());
      relieved_mid_inning += t->pitchers[0].outs % 3 != 0;
      left_starters += t->pitchers[0].left_handed;
      for (std::size_t i = 1; i < t->pitchers.size(); ++i) {
        ++relievers;
        left_relievers += t->pitchers[i].left_handed;
        long_outings += t->pitchers[i].outs >= 7;
        relief_outs += t->pitchers[i].outs;
      }
      if (t->pitchers[0].outs < 12) ++knockouts, knockout_staff += static_cast<int>(t->pitchers.size());
      int runs = 0;
      for (const PitchingLine& p : t->pitchers) {
        CHECK(p.pitches <= 125);
        inherited += p.inherited;
        scored += p.inherited_scored;
        runs += p.r;
      }
      CHECK(runs == t->pitching.r);
    }
    // Each plate appearance names the pitcher who faced it; a change is his first batter.
    int last[2] = {0, 0};
    for (const PlateAppearance& pa : g.plate_appearances) {
      const int f = pa.bottom ? 0 : 1;
      CHECK(pa.pitcher == last[f] + (pa.pitching_change ? 1 : 0));
      last[f] = pa.pitcher;
    }
  }
  const double ip = starter_outs / 3.0 / starts, per_start = double(starter_pitches) / starts;
  const double staff = double(pitchers) / starts, share = double(scored) / inherited;
  INFO("starters " << ip << " IP, " << per_start << " pitches; " << staff << " pitchers a team; " << relieved_mid_inning
                   << " of " << starts << " starters relieved during an inning; inherited " << inherited << ", scored " << share);
  CHECK(ip > 4.8);
  CHECK(ip < 5.9);
  CHECK(per_start > 80.0);
  CHECK(per_start < 96.0);
  CHECK(staff > 3.8);
  CHECK(staff < 5.0);
  CHECK(relieved_mid_inning >= starts / 5);
  // A starter knocked out inside four innings is followed by long men (Team::to_the_bullpen),
  // as is a blowout, not by a reliever an inning until the 9th: the relief outings past two
  // innings are a rare few, the average outing about an inning (MLB 2016: 1.04 innings), and
  // such a game's staff stays near an ordinary one's (6.7 pitchers when each reliever went an
  // inning, 5.1 with one long man).
  const double relief_ip = relief_outs / 3.0 / relievers;
  INFO(knockouts << " starters out inside four innings, " << knockout_staff << " pitchers in those games; "
                 << long_outings << " of " << relievers << " relief outings of 7 outs or more; " << relief_ip
                 << " innings a relief outing");
  REQUIRE(knockouts >= 10);
  CHECK(double(knockout_staff) / knockouts < 5.5);
  CHECK(long_outings >= knockouts / 3);
  CHECK(long_outings < relievers / 15);
  CHECK(relief_ip > 0.9);
  CHECK(relief_ip < 1.25);
  INFO(six_plus << " starts of 6+ innings, " << seven_plus << " of 7+ in " << starts);
  CHECK(six_plus > starts * 30 / 100);
  CHECK(six_plus < starts * 55 / 100);
  CHECK(seven_plus > starts * 4 / 100);
  CHECK(seven_plus < starts * 18 / 100);
  CHECK(inherited >= 40);
  CHECK(share > 0.18);
  CHECK(share < 0.42);
  // Left-handers start and relieve as often as the league's (kLeftStarterShare 30.5 % of the
  // first three innings' pitches, kLeftRelieverShare 22.4 % of the 8th on; Lookout Landing
  // 2008): within three binomial standard deviations of those shares.
  const double left_start = double(left_starters) / starts, left_relief = double(left_relievers) / relievers;
  INFO("left-handed starters " << left_starters << " of " << starts << ", relievers " << left_relievers << " of " << relievers);
  CHECK(std::abs(left_start - kLeftStarterShare) < 3.0 * std::sqrt(kLeftStarterShare * (1.0 - kLeftStarterShare) / starts));
  CHECK(std::abs(left_relief - kLeftRelieverShare) < 3.0 * std::sqrt(kLeftRelieverShare * (1.0 - kLeftRelieverShare) / relievers));
}

TEST_CASE("over 100 games runners take extra bases and tag up about as MLB's do", "[baseball][game][reference][statistics]") {
  // Baseball-Reference's league baserunning (2023): a runner on second scores on a single
  // ~60 % of the time, one on first scores on a double ~40 %, goes first to third on a single
  // ~28 %; runs a team a game 4.62 (2023), 4.39 (2024). Runners on second tag up on outfield
  // flies, and on a ball in the air no one can reach they run once they have read it (before
  // either, from second on a single was ~25 %, first to third ~8-15 %, tags from second none).
  int r2_single = 0, r2_scored = 0, r1_double = 0, r1_scored = 0, r1_single = 0, r1_third = 0;
  int r3_fly = 0, r3_fly_scored = 0, r2_fly = 0, r2_tagged = 0, runs = 0, teams = 0;
  for (const GameRecord& g : league_games()) {
    runs += g.away.runs + g.home.runs;
    teams += 2;
    const auto& pas = g.plate_appearances;
    for (std::size_t i = 0; i + 1 < pas.size(); ++i) {
      const PlateAppearance& pa = pas[i];
      const PlateAppearance& next = pas[i + 1];
      if (next.inning != pa.inning || next.bottom != pa.bottom) continue;  // the half ended on it
      const Bases& before = pa.bases_before;
      const Bases& after = next.bases_before;
      const auto on = [&](int who) { return who >= 0 && std::find(after.begin(), after.end(), who) != after.end(); };
      const bool outfield_fly = pa.result == "out" && pa.pitches.back().result.play.caught &&
                                pa.pitches.back().result.play.fielder >= 6 && pa.outs_before < 2;
      if (pa.result == "single" && before[1] >= 0) {
        ++r2_single;
        r2_scored += !on(before[1]);
      }
      if (pa.result == "single" && before[0] >= 0 && before[2] < 0) {
        ++r1_single;
        r1_third += after[2] == before[0];
      }
      if (pa.result == "double" && before[0] >= 0) {
        ++r1_double;
        r1_scored += !on(before[0]);
      }
      if (outfield_fly && before[2] >= 0) {
        ++r3_fly;
        r3_fly_scored += !on(before[2]);
      }
      if (outfield_fly && before[1] >= 0 && before[2] < 0) {
        ++r2_fly;
        r2_tagged += after[2] == before[1];
      }
    }
  }
  const auto share = [](int a, int b) { return b > 0 ? double(a) / b : 0.0; };
  INFO("runs a team " << share(runs, teams) << "; from 2nd on a single " << share(r2_scored, r2_single) << " (" << r2_single
                      << "), from 1st on a double " << share(r1_scored, r1_double) << ", 1st to 3rd " << share(r1_third, r1_single)
                      << ", sacrifice flies " << share(r3_fly_scored, r3_fly) << " (" << r3_fly << "), 2nd to 3rd on a fly "
                      << share(r2_tagged, r2_fly) << " (" << r2_fly << ")");
  // The bands are about two sampling errors wide: 100 games hold ~200 team-games (±0.2 run),
  // ~200 singles with a man on second, ~100 doubles with one on first, ~40 sacrifice-fly chances.
  CHECK(share(runs, teams) > 3.8);
  CHECK(share(runs, teams) < 5.0);
  CHECK(share(r2_scored, r2_single) > 0.42);
  CHECK(share(r2_scored, r2_single) < 0.72);
  CHECK(share(r1_scored, r1_double) > 0.25);
  CHECK(share(r1_scored, r1_double) < 0.55);
  CHECK(share(r1_third, r1_single) > 0.18);
  CHECK(share(r1_third, r1_single) < 0.40);
  CHECK(share(r3_fly_scored, r3_fly) > 0.45);
  CHECK(share(r2_tagged, r2_fly) > 0.2);
  CHECK(share(r2_tagged, r2_fly) < 0.70);
}

TEST_CASE("over 100 games some runners who are sent are thrown out, and on a ground out only a ball hit behind a runner moves him up",
          "[baseball][game][reference][statistics]") {
  // Baseball-Reference: a runner on third with fewer than two out scores about half the time
  // (49-52 %, 2013-14; 51.7 % over 2003-04's 21,073 chances); its "outs on base" are 47 a team
  // in 2022 (0.29 a game), counting every out a runner makes advancing (this game's: on hits,
  // on tags, doubled off, the batter stretching a hit) and those on wild pitches and passed
  // balls, which it does not play. Within a half-inning, outs and runners carry over.
  int r3 = 0, r3_scored = 0, runner_outs = 0, teams = 0;
  int behind = 0, behind_moved = 0, in_front = 0, in_front_moved = 0;
  for (const GameRecord& g : league_games()) {
    teams += 2;
    const auto& pas = g.plate_appearances;
    for (std::size_t i = 0; i < pas.size(); ++i) {
      const PlateAppearance& pa = pas[i];
      const Bases& before = pa.bases_before;
      runner_outs += pa.description.find(", runner from") != std::string::npos ||
                     pa.description.find("doubled off") != std::string::npos ||
                     pa.description.find("out stretching") != std::string::npos;
      const bool same_half = i + 1 < pas.size() && pas[i + 1].inning == pa.inning && pas[i + 1].bottom == pa.bottom;
      if (same_half) {
        // Every man who was on or came up is on base after it, scored, or was put out.
        const auto count = [](const Bases& b) { return static_cast<int>(std::count_if(b.begin(), b.end(), [](int r) { return r >= 0; })); };
        CHECK(pas[i + 1].outs_before == pa.outs_before + pa.outs_made);
        CHECK(count(pas[i + 1].bases_before) == count(before) + 1 - pa.runs - pa.outs_made);
      }
      if (before[2] >= 0 && pa.outs_before < 2) {
        ++r3;
        const Bases* after = same_half ? &pas[i + 1].bases_before : nullptr;
        const bool still_on = after && std::find(after->begin(), after->end(), before[2]) != after->end();
        r3_scored += pa.runs > 0 && !still_on;
      }
      // A lone runner on second, a ground ball out at first: hit to the right side (1B, 2B) it
      // is behind him; to the pitcher, third or short it is in front of him.
      const FieldingPlay& play = pa.pitches.back().result.play;
      // A runner thrown out tagging up after the catch makes the play a double play, as the
      // scorer calls one turned by the infield ("Fly out to LF, runner from 2nd out at 3rd (LF
      // to 3B): double play").
      if (pa.result == "out" && play.caught && pa.outs_made == 2) {
        INFO(pa.description);
        CHECK(pa.description.find("double play") != std::string::npos);
      }
      if (same_half && pa.result == "out" && pa.outs_made == 1 && play.type == BattedBallType::GroundBall && !play.caught &&
          before[0] < 0 && before[1] >= 0 && before[2] < 0 && pa.outs_before < 2) {
        const bool moved = pas[i + 1].bases_before[2] == before[1];
        if (play.fielder == 2 || play.fielder == 3) {
          ++behind;
          behind_moved += moved;
        } else if (play.fielder == 0 || play.fielder == 4 || play.fielder == 5) {
          ++in_front;
          in_front_moved += moved;
        }
      }
    }
  }
  const auto share = [](int a, int b) { return b > 0 ? double(a) / b : 0.0; };
  INFO("from third with < 2 out " << share(r3_scored, r3) << " (" << r3 << "); runner outs a team " << share(runner_outs, teams)
                                  << "; from second on a ground out behind him " << share(behind_moved, behind) << " ("
                                  << behind << "), in front " << share(in_front_moved, in_front) << " (" << in_front << ")");
  // ~300 chances from third: two sampling errors are ±6 %.
  CHECK(share(r3_scored, r3) > 0.42);
  CHECK(share(r3_scored, r3) < 0.60);
  CHECK(share(runner_outs, teams) > 0.03);
  CHECK(share(runner_outs, teams) < 0.29);
  REQUIRE(behind >= 20);
  REQUIRE(in_front >= 20);
  CHECK(share(behind_moved, behind) > 0.6);
  CHECK(share(in_front_moved, in_front) < 0.5);
}

TEST_CASE("over 100 games a hitter's bat speed varies from swing to swing as Statcast's does", "[baseball][game][reference][statistics]") {
  // Statcast's bat tracking (2024): the league's average swing 71.5 mph; its fast swings (75
  // mph or more) 65 % of J. Rodriguez's at a 76.2 mph average and ~10 % of M. Garver's at
  // 71.0, a normal spread of ~4.3 % of a hitter's average, so a 71.5 mph hitter swings 75+
  // on ~13 % of his full swings. Every hitter here is the league's; two-strike swings are
  // shortened (kTwoStrikeEffort) and left out.
  int swings = 0, fast = 0;
  double sum = 0.0, sum2 = 0.0;
  for (const GameRecord& g : league_games())
    for (const PlateAppearance& pa : g.plate_appearances)
      for (const PitchRecord& rec : pa.pitches) {
        if (!rec.swung || rec.count.strikes == 2) continue;
        const double mph = mps_to_mph(rec.result.tracking.bat_speed_mps);
        ++swings;
        fast += rec.result.tracking.fast_swing;
        sum += mph;
        sum2 += mph * mph;
      }
  REQUIRE(swings > 5000);
  const double mean = sum / swings, sd = std::sqrt(sum2 / swings - mean * mean);
  INFO(swings << " full swings: " << mean << " mph, sd " << sd << ", fast " << double(fast) / swings);
  CHECK(mean == Approx(71.5).margin(0.3));
  CHECK(sd > 2.6);
  CHECK(sd < 3.6);
  CHECK(double(fast) / swings > 0.09);
  CHECK(double(fast) / swings < 0.18);
}

TEST_CASE("a left-hander's pitches are a right-hander's mirrored: the same flight, the side break the other way",
          "[baseball][game]") {
  // The game's scouting report of a left-hander is the right-hander's mirrored (ball_game.cpp),
  // which holds because the flight is: thrown from the other side, every type's break turns.
  const std::vector<PitchType> types = load_pitch_types(test::assets());
  const ScoutingReport right = scout(test::assets(), league_average_pitcher(types, false));
  const ScoutingReport left = scout(test::assets(), league_average_pitcher(types, true));
  REQUIRE(right.types.size() == left.types.size());
  for (std::size_t i = 0; i < right.types.size(); ++i) {
    INFO(right.types[i].type);
    CHECK(left.types[i].flight_time == Approx(right.types[i].flight_time).epsilon(1e-9));
    CHECK(left.types[i].vertical_break == Approx(right.types[i].vertical_break).margin(1e-9));
    CHECK(left.types[i].horizontal_break == Approx(-right.types[i].horizontal_break).margin(1e-9));
    CHECK(std::abs(right.types[i].horizontal_break) > 0.01);  // every type breaks some way
  }
}

TEST_CASE("a walk-off hit counts the bases the winning run took and is told as that hit", "[modes][baseball]") {
  // Bottom of the 10th, tied, a runner (#3) on third: a ground-rule double scores him alone.
  GameSituation s;
  s.inning = 10;
  s.bottom = true;
  s.away_runs = s.home_runs = 4;
  PlateAppearance pa;
  pa.bases_before = {-1, -1, 3};
  pa.result = "double";
  pa.description = "Ground-rule double to RF";
  pa.rbi = 2;
  std::vector<int> scored{3, 7};
  walk_off_limit(pa, s, scored);
  CHECK(pa.result == "single");  // Rule 9.06(f): the winning runner took one base
  CHECK(pa.description == "Single to RF");
  CHECK(scored == std::vector<int>{3});
  CHECK(pa.rbi == 1);
  // From second on a triple: a double, its words kept after the hit's name.
  pa.bases_before = {-1, 5, -1};
  pa.result = "triple";
  pa.description = "Triple to LF";
  pa.rbi = 1;
  scored = {5};
  walk_off_limit(pa, s, scored);
  CHECK(pa.result == "double");
  CHECK(pa.description == "Double to LF");
}
