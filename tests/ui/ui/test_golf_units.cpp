// The golf HUD's distances in player words.
#include <catch2/catch.hpp>

#include <limits>

#include "game/ui/golf_draw.hpp"

using namespace sweetspot;

TEST_CASE("a ball a few inches from the cup reads in inches, never 0 ft", "[ui][golf]") {
  const GolfUnits feet{true}, metres{false};
  CHECK(feet.putt(0.10) == "4 in");
  CHECK(feet.putt(0.001) == "1 in");  // not holed: at least an inch
  CHECK(feet.putt(0.30) == "1 ft");
  CHECK(feet.putt(2.44) == "8 ft");
  CHECK(metres.putt(0.10) == "10 cm");
  CHECK(metres.putt(0.001) == "1 cm");
  CHECK(metres.putt(2.44) == "2.4 m");
}

TEST_CASE("the caddie's read in a golfer's words: the break in inches and cups, the pace for the slope", "[ui][golf]") {
  const GolfUnits feet{true}, metres{false};
  GolfPlay::PuttRead r;
  r.to_cup = 4.0;
  r.holes = true;
  r.aim_off = -0.23;  // aimed left: it curls back right
  r.plays_as = 4.9;
  CHECK(putt_read_words(r, feet) == "breaks left to right: aim 9 in left (2 cups), uphill: play it as 16 ft on the flat (blue mark)");
  CHECK(putt_read_words(r, metres) == "breaks left to right: aim 23 cm left (2 cups), uphill: play it as 4.9 m on the flat (blue mark)");
  r.aim_off = 0.06;
  r.plays_as = 3.2;
  CHECK(putt_read_words(r, feet) == "breaks right to left: aim 2 in right (0.5 cup), downhill: play it as 10 ft on the flat (blue mark)");
  r.aim_off = 0.01;
  r.plays_as = 4.1;
  r.holes = false;
  CHECK(putt_read_words(r, feet) == "straight: at the cup, level: play it as 13 ft on the flat (blue mark); the caddie's best line, it may not drop");
  // Past the putter's full stroke the mark sits at the meter's end: said.
  r.power = 1.1;
  r.plays_as = 20.4;
  r.to_cup = 17.0;
  CHECK(putt_read_words(r, feet) ==
        "straight: at the cup, uphill: play it as 67 ft on the flat (beyond a full putt: the blue mark at the end); the caddie's best line, it may not drop");
  // A short putt's pace: half a foot more than its length is uphill, as its words show it.
  r.power = 0.3;
  r.holes = true;
  r.to_cup = 0.61;
  r.plays_as = 0.9;
  CHECK(putt_read_words(r, feet) == "straight: at the cup, uphill: play it as 3 ft on the flat (blue mark)");
  r.plays_as = 0.66;
  CHECK(putt_read_words(r, feet) == "straight: at the cup, level: play it as 2 ft on the flat (blue mark)");
  // Inside the cup but off its centre: which side of it, as a golfer says it.
  r.to_cup = 0.91;
  r.plays_as = 0.91;
  r.aim_off = -0.021;
  CHECK(putt_read_words(r, feet) == "barely breaks left to right: aim inside left, level: play it as 3 ft on the flat (blue mark)");
  r.aim_off = 0.02;
  CHECK(putt_read_words(r, feet).starts_with("barely breaks right to left: aim inside right"));
  CHECK(break_length(0.30, feet) == "12 in");
  CHECK(break_length(1.20, feet) == "4 ft");
  CHECK(break_length(0.30, metres) == "30 cm");
}

TEST_CASE("the club line says why its carry from here is not the bag's: the wind's share and the ground's", "[ui][golf]") {
  const GolfUnits yards{true};
  // 200 m in the bag, 195 m in still air from this lie (5 m to the ground), 205 m with the wind:
  // shown as 219 yd and 224 yd, the shares of the shown figures (213 yd in still air), so
  // they add up (a share of its own metres rounded would say -5).
  CHECK(why_from_here(200.0, false, 205.0, 195.0, yards) == ": wind +11 yd, lie and slope -6 yd");
  // The play-test's 3-wood: stock 226 yd, 191 from here, which the shares must make.
  const double y = 0.9144;
  CHECK(why_from_here(226.4 * y, false, 190.6 * y, 212.3 * y, yards) == ": wind -21 yd, lie and slope -14 yd");
  const GolfUnits metres{false};
  CHECK(why_from_here(155.4, false, 149.6, 153.4, metres) == ": wind -3 m, lie and slope -2 m");  // 155 - 3 - 2 = 150
  // Into the wind from a perfect lie: only the wind's share.
  CHECK(why_from_here(200.0, false, 190.0, 200.5, yards) == ": wind -11 yd");
  // Once one share is named the other is too from a yard up, so the figures add up: 78 yd in
  // the bag, 6 yd to the lie, 2.4 yd to the wind, 68 from here.
  const double yd = 0.9144;
  CHECK(why_from_here(78 * yd, false, 69.6 * yd, 72 * yd, yards) == ": wind -2 yd, lie and slope -6 yd");
  CHECK(why_from_here(78 * yd, false, 71.6 * yd, 72 * yd, yards) == ": lie and slope -6 yd");  // under a yard
  // Shares under ~3 yd are a good player's own spread: nothing said.
  CHECK(why_from_here(200.0, false, 201.0, 199.0, yards).empty());
  // A measured bag holds the player's own strikes: the ground's share is not claimed.
  CHECK(why_from_here(200.0, true, 205.0, 195.0, yards) == ": wind +11 yd");
  // Held out over trees for the wind to bring back, the still-air flight ends in them: no
  // split of the two shares ("wind +143 yd, lie and slope -153 yd"), their sum.
  const double in_trees = std::numeric_limits<double>::quiet_NaN();
  CHECK(why_from_here(200.0, false, 190.0, in_trees, yards) == ": wind, lie and slope -11 yd");
  CHECK(why_from_here(200.0, true, 190.0, in_trees, yards).empty());
  // From the tee or the fairway only the landing's height moves the carry: said so.
  CHECK(why_from_here(200.0, false, 190.0, 190.0, yards, ground_share_words("tee", 5.0)) == ": uphill -11 yd");
  CHECK(why_from_here(200.0, false, 210.0, 210.0, yards, ground_share_words("fairway", -4.0)) == ": downhill +11 yd");
  CHECK(std::string(ground_share_words("fairway", 0.3)) == "lie and slope");  // no rise to name
  CHECK(std::string(ground_share_words("rough", 5.0)) == "lie and slope");    // the lie's share too
  CHECK(std::string(ground_share_words("sand", 0.0, true)) == "splash and slope");  // a splash by name
}

TEST_CASE("a part swing's carry and run read in one unit, the longer one's", "[ui][golf]") {
  const GolfUnits yards{true}, metres{false};
  // 13 m of carry and 21 m to rest: "carries 14 yd, stops 23 yd", not "carries 43 ft, stops 23 yd".
  CHECK(yards.course(13.0, 21.0) == "14 yd");
  CHECK(yards.course(21.0, 21.0) == "23 yd");
  CHECK(yards.course(13.0, 15.0) == "43 ft");
  CHECK(metres.course(13.0, 21.0) == "13 m");
}

TEST_CASE("the last swing's click marks are drawn only where they read true on this bar", "[ui][golf]") {
  const double full = MeterClock::tempo_for(false);
  const auto clicked = [](double tempo, bool putting, double power) {
    MeterClock m(tempo, putting, 10.0);
    m.click(0.0);
    m.click(power * tempo);  // the power click where the marker reached `power`
    if (!putting) m.click(m.mark_time() + 0.02);  // 20 ms late
    return m;
  };
  const MeterClock drive = clicked(full, false, 0.95);
  REQUIRE(drive.power() == Approx(0.95));
  // Another full swing on the whole bar: both marks.
  ClickMarks m = last_click_marks(drive, MeterClock(full, false, 10.0), MeterBar::kHigh);
  CHECK(m.power);
  CHECK(m.accuracy);
  // A chip's part swing, slower and zoomed to 40 %: the drive's power is past the bar's end
  // and its click's place was at the full tempo's scale.
  m = last_click_marks(drive, MeterClock(2.0 * full, false, 10.0), 0.4);
  CHECK_FALSE(m.power);
  CHECK_FALSE(m.accuracy);
  // A chip after a chip at another pace: the power mark (a power is a power), not the click's.
  const MeterClock chip = clicked(2.0 * full, false, 0.3);
  m = last_click_marks(chip, MeterClock(1.5 * full, false, 10.0), 0.5);
  CHECK(m.power);
  CHECK_FALSE(m.accuracy);
  // A putt's power never on a swing's bar, nor a swing's on a putt's.
  const MeterClock putt = clicked(MeterClock::tempo_for(true), true, 0.4);
  CHECK_FALSE(last_click_marks(putt, MeterClock(full, false, 10.0), MeterBar::kHigh).power);
  CHECK_FALSE(last_click_marks(drive, MeterClock(MeterClock::tempo_for(true), true, 10.0), MeterBar::kHigh).power);
  m = last_click_marks(putt, MeterClock(MeterClock::tempo_for(true), true, 10.0), MeterBar::kHigh);
  CHECK(m.power);
  CHECK_FALSE(m.accuracy);  // a putt has no accuracy click
}

TEST_CASE("a chip's meter bar zooms on its few per cent, with the pin's mark ~60 % of the way along", "[ui][golf]") {
  // The whole bar while the pin's power is past half of it or beyond reach.
  CHECK(zoomed_top(std::nullopt) == MeterBar::kHigh);
  CHECK(zoomed_top(0.6) == MeterBar::kHigh);
  CHECK(zoomed_top(0.55) == MeterBar::kHigh);
  // A 22 % chip: the bar ends at 40 % (22 / 0.6 = 37 %, up to the next 10 %).
  CHECK(zoomed_top(0.22) == Approx(0.4));
  // Never narrower than 30 %, and a top at or past 100 % is the whole bar.
  CHECK(zoomed_top(0.03) == Approx(0.3));
  CHECK(zoomed_top(0.5) == Approx(0.9));  // 50 / 0.6 = 83 %
  // An aim's small step does not move the top: it moves in 10 % steps.
  CHECK(zoomed_top(0.200) == zoomed_top(0.205));
  // The zoomed bar keeps the accuracy's share and holds what runs past its ends at them.
  MeterBar bar;
  bar.high = 0.4;
  bar.low = MeterBar::kLow * bar.high / MeterBar::kHigh;
  CHECK(bar.zoomed());
  CHECK(bar.at(bar.low) == Approx(bar.x0));
  CHECK(bar.at(0.0) == Approx(bar.x0 + bar.bw * 0.15f / 1.25f));
  CHECK(bar.at(0.4) == Approx(bar.x0 + bar.bw));
  CHECK(bar.at(1.0) == Approx(bar.x0 + bar.bw));  // a marker run past the end stays at it
  CHECK(bar.at(-1.0) == Approx(bar.x0));
}

TEST_CASE("the wind dial gives way to the scorecard only where the card reaches it", "[ui][golf]") {
  // The card is 600 px wide and centred; the dial and its label take the right 96 px.
  CHECK(golf_card_covers_wind(640));
  CHECK(golf_card_covers_wind(780));
  CHECK_FALSE(golf_card_covers_wind(800));
  CHECK_FALSE(golf_card_covers_wind(1280));
}
