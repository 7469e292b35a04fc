// The practice range's bag gapping: each club's mean and spread from its shots, a bag file
// that reads back to the same numbers, and a caddie who then picks clubs by them.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "game/content/bag_file.hpp"
#include "game/modes/golf/range_play.hpp"
#include "game/modes/golf/range_session.hpp"
#include "game/modes/golf/swing_meter.hpp"
#include "game/modes/replay.hpp"
#include "physics/error.hpp"
#include "support/intent_at.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

TEST_CASE("a bag-gapping session: per club mean and spread, longest first, the gaps positive", "[modes][golf][range]") {
  const Bag bag = gap_bag(test::assets(), golfer_skill("amateur"), 6, 3);
  REQUIRE(bag.clubs.size() == 13);  // every club but the putter
  for (std::size_t k = 0; k < bag.clubs.size(); ++k) {
    const BagClub& c = bag.clubs[k];
    CHECK(c.shots == 6);
    CHECK(c.total >= c.carry);
    CHECK(c.carry_sd > 0.0);  // the bot's errors spread the carries
    if (k > 0) CHECK(c.carry <= bag.clubs[k - 1].carry);
  }
  // The mean and spread are those of the shots: a session of the same seed, by hand.
  RangeSession range(test::assets(), golfer_skill("amateur"));
  range.hit("7-iron", MeterInput{1.0, 0.0});
  range.hit("7-iron", MeterInput{0.9, 0.0});
  const Bag two = range.bag("you");
  REQUIRE(two.clubs.size() == 1);
  const double a = range.shots()[0].carry, b = range.shots()[1].carry;
  CHECK(two.clubs[0].carry == Approx(0.5 * (a + b)));
  CHECK(two.clubs[0].carry_sd == Approx(std::abs(a - b) / std::sqrt(2.0)));
  // Which way it misses: a late third click pushes right, an early one pulls left; the mean
  // side and the spread about it are the shots', the first one alone has no spread.
  range.hit("6-iron", MeterInput{1.0, 40.0});
  range.hit("6-iron", MeterInput{1.0, -10.0});
  const double l = range.shots()[2].side, m = range.shots()[3].side;
  const RangeSession::SideMiss miss = range.side_miss("6-iron");
  CHECK(miss.shots == 2);
  CHECK(miss.mean == Approx(0.5 * (l + m)));
  CHECK(miss.sd == Approx(std::abs(l - m) / std::sqrt(2.0)));
  CHECK(range.side_miss("6-iron", 3).sd == 0.0);
  CHECK(range.side_miss("6-iron", 3).mean == Approx(l));
  CHECK(range.side_miss("driver").shots == 0);
  CHECK_THROWS_AS(range.hit("putter", MeterInput{}), InputError);
}

TEST_CASE("the bag file reads back the same and the caddie chooses by it", "[modes][golf][range]") {
  const Bag measured = gap_bag(test::assets(), golfer_skill("beginner"), 4, 9);
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_bag_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / "bag.toml";
  std::ofstream(path) << bag_toml(measured);
  const Bag back = load_bag(test::assets(), path, golfer_skill_names());
  REQUIRE(back.clubs.size() == measured.clubs.size());
  for (std::size_t k = 0; k < back.clubs.size(); ++k) {
    CHECK(back.clubs[k].club == measured.clubs[k].club);
    CHECK(back.clubs[k].carry == measured.clubs[k].carry);
    CHECK(back.clubs[k].carry_sd == measured.clubs[k].carry_sd);
  }
  // A tour-speed caddie hits a wedge 110 m; with the beginner's measured bag it takes more
  // club: the caddie's choice follows the player's own carries.
  const GolfBot stock(test::assets(), golfer_skill("tour"), 1);
  const GolfBot mine(test::assets(), golfer_skill("tour"), 1, bag_stock(back));
  const std::string by_stock = stock.suggest(110.0, false), by_bag = mine.suggest(110.0, false);
  CHECK(by_stock != by_bag);
  double carry_stock = 0.0, carry_bag = 0.0;
  for (const auto& s : stock.stock()) if (s.club == by_bag) carry_stock = s.carry;
  for (const auto& s : mine.stock()) if (s.club == by_bag) carry_bag = s.carry;
  CHECK(carry_bag >= 110.0);
  CHECK(carry_bag < carry_stock);
  // Hostile bag files: named file:line and key.
  std::ofstream(dir / "bad.toml") << "skill = \"tour\"\n[[club]]\nname = \"putter\"\ncarry = \"10m\"\ntotal = \"12m\"\n";
  CHECK_THROWS_WITH(load_bag(test::assets(), dir / "bad.toml", golfer_skill_names()), Catch::Contains("bad.toml:3") && Catch::Contains("putter"));
  std::ofstream(dir / "bad2.toml") << "skill = \"tour\"\n[[club]]\nname = \"7-iron\"\ncarry = \"150m\"\ntotal = \"120m\"\n";
  CHECK_THROWS_WITH(load_bag(test::assets(), dir / "bad2.toml", golfer_skill_names()), Catch::Contains("bad2.toml:5") && Catch::Contains("total"));
  // A skill the game does not have was read and never used: a bag that meant nothing.
  std::ofstream(dir / "bad3.toml") << "player = \"me\"\nskill = \"god\"\n";
  CHECK_THROWS_WITH(load_bag(test::assets(), dir / "bad3.toml", golfer_skill_names()),
                    Catch::Contains("bad3.toml:2") && Catch::Contains("'god'") && Catch::Contains("tour, scratch"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("at the range the club keys and B work while the last ball flies and once it has stopped", "[modes][golf][range]") {
  // Choosing the next club, or B for the next swing, ends the last shot's view (as Enter and
  // Space do) instead of being ignored until the view is dismissed.
  RangePlay play(test::assets(), golfer_skill("amateur"));
  REQUIRE(play.club() == "driver");
  play.update({test::at(IntentKind::CaddiePlays, 1.0)}, 1.1);
  REQUIRE(play.stage() == RangePlay::Stage::Flying);
  play.update({test::at(IntentKind::ClubDown, 1.5)}, 1.6);  // the ball still in the air
  CHECK(play.stage() == RangePlay::Stage::Aiming);
  CHECK(play.club() == "3-wood");
  play.update({test::at(IntentKind::CaddiePlays, 2.0)}, 2.1);
  REQUIRE(play.stage() == RangePlay::Stage::Flying);
  const double rest = 2.0 + duration(play.last_shot().trajectory) + 0.5;
  play.update({test::at(IntentKind::ClubUp, rest)}, rest + 0.1);  // the ball at rest
  CHECK(play.stage() == RangePlay::Stage::Aiming);
  CHECK(play.club() == "driver");
  // B while a ball flies hits the next one: every press is a shot.
  for (int k = 0; k < 3; ++k) play.update({test::at(IntentKind::CaddiePlays, rest + 1.0 + 0.2 * k)}, rest + 1.1 + 0.2 * k);
  CHECK(play.stage() == RangePlay::Stage::Flying);
  CHECK(play.session().shots().size() == 5);
  // A new session: no shots, and no last ball left to show.
  play.update({test::at(IntentKind::Restart, rest + 2.0)}, rest + 2.1);
  CHECK(play.session().shots().empty());
  CHECK(play.struck_at() == 0.0);
  CHECK(play.last_shot().trajectory.samples.empty());
  CHECK(play.stage() == RangePlay::Stage::Aiming);
}

TEST_CASE("each golfer swings the driver as TrackMan measured golfers of that level: a slower drive spins more and rolls "
          "less",
          "[modes][golf][range]") {
  // TrackMan Combine driver averages (trackman.com Combine blocks, 2024): scratch or better
  // 110 mph, launch 11.2°, 2896 rpm; the average golfer (14.5 handicap) 94 mph, 12.6°, 3275
  // rpm. The game's golfers swing 105 and 93 mph with those lofts and attack angles; held to
  // the project's bands for launch-monitor averages (1.5°, 15 %).
  struct Row {
    const char* skill;
    double launch_deg, spin_rpm;
  };
  for (const Row& row : {Row{"scratch", 11.2, 2896.0}, Row{"amateur", 12.6, 3275.0}}) {
    INFO(row.skill);
    RangeSession range(test::assets(), golfer_skill(row.skill));
    ShotResult r;
    range.hit("driver", MeterInput{1.0, 0.0}, &r);
    CHECK(rad_to_deg(r.launch.vertical_angle) == Approx(row.launch_deg).margin(1.5));
    CHECK(radps_to_rpm(r.launch.spin.total) == Approx(row.spin_rpm).epsilon(0.15));
  }
  // Every golfer's drive rolls at most a third of its carry: the largest (total - carry) /
  // carry on TrackMan's 2010 driver optimizer charts is 0.33 (75 mph, 0° attack: 147 / 195
  // yd). With the tour's loft at 80 mph the beginner's drive rolled half its carry. And his
  // driver is still his longest club off the tee, past the 3-wood.
  for (const GolferSkill& g : golfer_skills()) {
    INFO(g.name);
    RangeSession range(test::assets(), g);
    const RangeShot drive = range.hit("driver", MeterInput{1.0, 0.0});
    const RangeShot wood = range.hit("3-wood", MeterInput{1.0, 0.0});
    CHECK(drive.total - drive.carry <= 0.33 * drive.carry);
    CHECK(drive.total > wood.total);
  }
  CHECK(added_loft(golfer_skill("tour"), test::assets().equipment()) == 0.0);
  CHECK(rad_to_deg(added_loft(golfer_skill("amateur"), test::assets().equipment())) == Approx(15.1 - 12.53).margin(0.05));
}

TEST_CASE("the range caddie's swings come from the session's seed", "[modes][golf][range]") {
  // A session's seed deals its caddie swings (B): the same seed the same swings, another
  // seed others, so the range does not repeat one sequence every time it opens.
  const auto caddie_carries = [](std::uint64_t seed) {
    RangePlay play(test::assets(), golfer_skill("amateur"), 5, MeterDifficulty::Standard, seed);
    std::vector<double> carries;
    for (int k = 0; k < 4; ++k) {
      play.update({test::at(IntentKind::CaddiePlays, 1.0 + k)}, 1.1 + k);
      carries.push_back(play.last_shot().trajectory.summary.carry_m);
    }
    return carries;
  };
  CHECK(caddie_carries(3) == caddie_carries(3));
  CHECK(caddie_carries(3) != caddie_carries(4));
}

TEST_CASE("the range's flags stand every 50 yd, or every 50 m for a metric golfer, as the stripes are marked", "[modes][golf]") {
  const std::vector<Vec3> yards = RangePlay::targets(true), metres = RangePlay::targets(false);
  REQUIRE(yards.size() == 5);
  REQUIRE(metres.size() == 5);
  for (std::size_t k = 0; k < 5; ++k) {
    CHECK(yards[k].x() == Approx(0.9144 * 50.0 * static_cast<double>(k + 1)));  // 1 yd = 0.9144 m exactly
    CHECK(metres[k].x() == Approx(50.0 * static_cast<double>(k + 1)));
    CHECK(metres[k].z() == yards[k].z());  // the same places off the line
  }
}

TEST_CASE("from a bunker the sand and lob wedges splash an inch behind the ball, every other club picks it clean",
          "[golfer][sand]") {
  const EquipmentCatalog& eq = test::assets().equipment();
  CHECK(sand_entry_for(eq.club("sw"), "sand") == kSplashEntry);
  CHECK(sand_entry_for(eq.club("lw"), "sand") == kSplashEntry);
  for (const char* club : {"pw", "9-iron", "5-iron", "hybrid", "3-wood"}) CHECK(sand_entry_for(eq.club(club), "sand") == 0.0);
  for (const char* lie : {"fairway", "rough", "tee", "green"}) CHECK(sand_entry_for(eq.club("sw"), lie) == 0.0);
}

TEST_CASE("a splash timed early enters the sand farther behind the ball, one timed late meets the ball first",
          "[golfer][sand]") {
  const EquipmentCatalog& eq = test::assets().equipment();
  const ClubSpec& sw = eq.club("sw");
  MeterInput m;
  m.accuracy_ms = -10.0;
  const double early = sand_entry_for(sw, "sand", timing_error_ms(m, sw));
  m.accuracy_ms = 10.0;
  const double late = sand_entry_for(sw, "sand", timing_error_ms(m, sw));
  // The sand wedge's 10 ms moves the arc's bottom ~8 mm (kLowPointPerMs by its length).
  CHECK(early - kSplashEntry == Approx(kSplashEntry - late));
  CHECK(early - kSplashEntry == Approx(10.0 * kLowPointPerMs * sw.length / kDriverLength));
  CHECK(early - kSplashEntry > 0.007);
  // 40 ms late bottoms out ahead of the ball: no sand before it, a clean strike.
  m.accuracy_ms = 40.0;
  CHECK(sand_entry_for(sw, "sand", timing_error_ms(m, sw)) == 0.0);
  // Far too early still meets the ball within the splash's range; a pick stays a pick.
  m.accuracy_ms = -200.0;
  CHECK(sand_entry_for(sw, "sand", timing_error_ms(m, sw)) == kSandEntry.max);
  CHECK(sand_entry_for(sw, "rough", timing_error_ms(m, sw)) == 0.0);
  // A pick is meant to bottom out an inch past the ball: a little early still takes no sand,
  // far early takes sand first (heavy), late never does.
  const ClubSpec& iron = eq.club("7-iron");
  for (double ms : {-10.0, 0.0, 60.0}) {
    m.accuracy_ms = ms;
    CHECK(sand_entry_for(iron, "sand", timing_error_ms(m, iron)) == 0.0);
    CHECK(splash_words(iron, "sand", sand_entry_for(iron, "sand", timing_error_ms(m, iron))).empty());
  }
  m.accuracy_ms = -60.0;
  const double heavy = sand_entry_for(iron, "sand", timing_error_ms(m, iron));
  CHECK(heavy == Approx(60.0 * kLowPointPerMs * iron.length / kDriverLength - kPickBeyond));
  CHECK(heavy > 0.01);
  CHECK(splash_words(iron, "sand", heavy) == "heavy, sand before the ball");
  CHECK(splash_words(iron, "fairway", heavy).empty());
}
