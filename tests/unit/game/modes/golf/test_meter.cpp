// The three-click meter (DESIGN §9): clicks in time become power and accuracy; the
// accuracy error becomes face, path and strike; over-swing thins the strike.
#include <catch2/catch.hpp>

#include "game/modes/golf/meter_clock.hpp"
#include "game/modes/golf/swing_meter.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

TEST_CASE("meter clicks: power where the second lands, accuracy against the mark", "[golf][meter]") {
  MeterClock m(1.0, false);  // 1 s from 0 to 100 %
  m.click(10.0);
  CHECK(m.position(10.5) == Approx(0.5));
  m.click(10.9);  // 90 %
  CHECK(m.power() == Approx(0.9));
  // Back down at 1.5x: the mark (0) is crossed 0.6 s later; clicking 20 ms after it is late.
  m.click(10.9 + 0.6 + 0.020);
  REQUIRE(m.result());
  CHECK(m.result()->power == Approx(0.9));
  CHECK(m.result()->accuracy_ms == Approx(20.0).margin(1e-6));
}

TEST_CASE("a stray click is abandoned at the top; a missing third click plays the latest miss", "[golf][meter]") {
  MeterClock stray(1.0, false);
  stray.click(0.0);
  stray.update(1.2);  // held at 110 % a moment for a late power click
  CHECK(stray.phase() == MeterClock::Phase::Backswing);
  CHECK(stray.position(1.2) == Approx(1.1));
  stray.update(5.0);
  CHECK(stray.phase() == MeterClock::Phase::Abandoned);
  CHECK_FALSE(stray.result());
  MeterClock m(1.0, false);
  m.click(0.0);
  m.click(0.8);
  m.update(10.0);
  REQUIRE(m.result());
  CHECK(m.result()->accuracy_ms == MeterInput::kAccuracy.max);
  MeterClock putt(1.2, true);
  putt.click(0.0);
  putt.click(0.6);
  REQUIRE(putt.result());
  CHECK(putt.result()->power == Approx(0.5));
  CHECK(putt.result()->accuracy_ms == 0.0);
}

TEST_CASE("difficulty: a click inside the perfect window plays as perfect, outside less the window", "[golf][meter]") {
  for (const MeterDifficulty d : {MeterDifficulty::Easy, MeterDifficulty::Standard, MeterDifficulty::Pro}) {
    const double w = perfect_window_ms(d);
    for (const double late : {-40.0, -8.0, 0.0, 5.0, 30.0}) {
      MeterClock m(1.0, false, w);
      m.click(0.0);
      m.click(1.0);
      m.click(1.0 + m.power() / 1.5 + late / 1000.0);
      REQUIRE(m.result());
      CHECK(m.click_error_ms() == Approx(late).margin(1e-6));
      const double played = std::abs(late) <= w ? 0.0 : (late > 0 ? late - w : late + w);
      CHECK(m.result()->accuracy_ms == Approx(played).margin(1e-6));
    }
  }
  CHECK(perfect_window_ms(MeterDifficulty::Easy) > perfect_window_ms(MeterDifficulty::Standard));
  CHECK(perfect_window_ms(MeterDifficulty::Pro) == 0.0);
  CHECK_THROWS_AS(meter_difficulty("legend"), InputError);
}

TEST_CASE("the accuracy error opens the face late and closes it early; a putter takes power only", "[golf][meter]") {
  const EquipmentCatalog& eq = test::assets().equipment();
  const ClubSpec& d = eq.club("driver");
  const ClubInfo& di = eq.club_info_of("driver");
  MeterInput late;
  late.accuracy_ms = 20.0;
  const GolfSwing s = meter_swing(late, d, di, 50.0);
  CHECK(rad_to_deg(s.face_angle) == Approx(1.6).epsilon(0.02));  // 0.08°/ms at the driver's tempo
  CHECK(s.club_path < 0.0);
  CHECK(s.impact_toe < 0.0);  // toward the heel
  MeterInput early = late;
  early.accuracy_ms = -20.0;
  CHECK(meter_swing(early, d, di, 50.0).face_angle < 0.0);
  MeterInput over;
  over.power = 1.1;
  const GolfSwing o = meter_swing(over, d, di, 50.0);
  CHECK(o.club_speed == Approx(55.0));
  CHECK(o.impact_up < d.strike_height);  // thinned
  const GolfSwing p = meter_swing(late, eq.club("putter"), eq.club_info_of("putter"), 3.0);
  CHECK(p.face_angle == 0.0);
  MeterInput bad;
  bad.power = 1.4;
  CHECK_THROWS_AS(validate_meter(bad), InputError);
}

TEST_CASE("a short putt's marker climbs slower: the cup's power is at least 0.6 s into the stroke", "[golf][meter]") {
  const double usual = MeterClock::tempo_for(true);
  // A 20 ft putt (cup at 57 %) keeps the putter's usual 1.2 s tempo.
  CHECK(MeterClock::putt_tempo(0.57) == usual);
  CHECK(MeterClock::putt_tempo(0.0) == usual);  // no cup to read: the usual
  for (const double cup : {0.02, 0.08, 0.25, 0.45}) {
    MeterClock m(MeterClock::putt_tempo(cup), true, 10.0);
    m.click(1.0);
    CHECK(m.position(1.0 + MeterClock::kLeastToCup) == Approx(cup).margin(1e-12));
    // 2 % of the meter either side of a tap-in's 8 % is now 150 ms of the press, not 24 ms.
    if (cup == 0.08) CHECK(m.position(1.15) - m.position(1.0) == Approx(0.02).margin(1e-12));
  }
}

TEST_CASE("a short part swing's marker climbs slower: the caddie's mark is at least 0.6 s into the swing", "[golf][meter]") {
  const double usual = MeterClock::tempo_for(false);
  // A 90 % swing keeps the full tempo (0.9 s to 100 %); with no mark, the usual.
  CHECK(MeterClock::part_swing_tempo(0.9) == usual);
  CHECK(MeterClock::part_swing_tempo(0.0) == usual);
  for (const double mark : {0.1, 0.14, 0.3, 0.5}) {
    MeterClock m(MeterClock::part_swing_tempo(mark), false, 10.0);
    m.click(1.0);
    CHECK(m.position(1.0 + MeterClock::kLeastToCup) == Approx(mark).margin(1e-12));
    // Power clicked on the mark: the fall to the accuracy mark is as long again at 1.5x the
    // climb's pace (0.4 s; the full tempo gives a 14 % chip 84 ms).
    m.click(1.0 + MeterClock::kLeastToCup);
    CHECK(m.mark_time() - (1.0 + MeterClock::kLeastToCup) == Approx(MeterClock::kLeastToCup / 1.5).margin(1e-12));
  }
}
