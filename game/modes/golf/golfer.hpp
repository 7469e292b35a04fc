// Golfers: a skill level sets how fast a player swings and how far their three-click meter
// inputs stray (DESIGN §9: tour, scratch, amateur, beginner). The bots draw their errors from
// these; a human's errors are their own.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "game/content/equipment_file.hpp"
#include "game/core/stroke_input.hpp"
#include "physics/delivery.hpp"
#include "physics/range.hpp"

namespace sweetspot {

struct GolferSkill {
  std::string name;           ///< "tour", "scratch", "amateur", "beginner"
  double driver_speed = 50.5; ///< m/s, full swing with the driver; every club scales with it
  /// Standard deviations of the bot's meter errors and putting: the third click's timing
  /// (ms), the power click (fraction of the chosen power), and on the green the speed (fraction)
  /// and start line (rad).
  double accuracy_sd_ms = 10.0;
  double power_sd = 0.02;
  double putt_speed_sd = 0.05;
  double putt_aim_sd = 0.012;
  /// The driver as this golfer delivers it: attack angle and the loft where the face meets
  /// the ball (rad; TrackMan's "dynamic loft"). NaN: the club's own (tour) delivery. Slower
  /// golfers deliver more loft: a tour driver's loft at their speed spins too little and
  /// lands too flat, so their drives would roll like a tour player's.
  double driver_attack = std::numeric_limits<double>::quiet_NaN();
  double driver_strike_loft = std::numeric_limits<double>::quiet_NaN();
  /// Extra power spread of a partial swing per unit of power it leaves out: a chip or a
  /// pitch is judged by feel (and struck fat or thin), and strays more the shorter the swing.
  /// scratch 0.18: its pitches from 25-50 yd finish ~20 ft away as Arccos's scratch golfers'
  /// do (test_bot_putting.cpp). tour 0.13: its chips from the rough within 30 yd finish 7.8 ft
  /// away on average and it gets up and down 65 % of the time (the day's cups, 40 calm
  /// rounds, 280 chips; the test's 24 rounds 7.5 ft), as PGA TOUR players do (2017: proximity
  /// from the rough 7'10" for the 75th of the list, 6'3" to 8'6" from 1st to 150th;
  /// scrambling ~58-60 %). amateur 0.35, beginner
  /// 0.45: ESTIMATES spaced like the full-swing errors, checked through the rounds' scores and
  /// putts there. A partial swing is also aimed by eye, with the putts' start-line spread.
  double partial_feel_sd = 0.08;
};

/// The four skills. Driver deliveries (attack, dynamic loft), TrackMan Combine averages for
/// the driver by handicap (trackman.com, "What is dynamic loft" / "Attack angle", Combine
/// blocks, 2024): scratch or better −0.9° / 13.0°, the average golfer (14.5 handicap, 94 mph)
/// −1.8° / 15.1°; the beginner takes the Combine's column at his speed (79 mph, the women's
/// 15 handicap) −2.3° / 16.5°. The tour skill keeps the club's delivery (fitted to TrackMan's
/// PGA row: 12.5° at its strike, TrackMan's 2023 PGA average 12.8°). Driver speeds: tour
/// 113 mph (TrackMan PGA average), scratch 105, a 15-handicap amateur 93, a beginner 80
/// (TrackMan's published handicap averages put the scratch and 15-handicap male golfer near
/// 105 and 93 mph). Errors: the timing spreads are set against published rates, over 24
/// National rounds each (the day's cups, the seeds' wind; docs/courses.md). The tour bot's
/// 12 ms scatters its drives ~±20 yd sideways: 60 % of fairways and 65 % of greens in
/// regulation (PGA TOUR ~60 % and ~66 %). The scratch bot's 18 ms: 46 % of fairways, 56 % of
/// greens, 75.1 strokes and 30.4 putts (calm: 47 %, 54 %, 75.5, 29.8), against Arccos's
/// scratch golfers' 51 %, 56 % and ~76 (2.2 birdies, 4.6 bogeys and 0.7 doubles or worse a
/// round; Golf Monthly, "Scratch vs 10 vs 20 handicap", 2023) and Shot Scope's 29.9 putts; at
/// 20 ms (calm) 43 %, 50 %, 77.0. The amateur's 25 ms timing spread (with a part swing's 0.35
/// feel): over 48 calm National rounds (`sweetspot round --bot amateur --calm`, seeds 1-48)
/// 43.8 % of fairways, 20.7 % of greens, 89.1 strokes and 32.8 putts, where Arccos's golfers
/// of 12-20 hit 41-45 % and ~20-31 % (12 handicaps 31 %) and a 15 handicap averages ~85-93;
/// at 36 ms he hit 30 % of fairways for 91.1 strokes (24 rounds: his misses cost little more
/// in the rough than on the fairway), at 30 ms 38 %.
/// The tour bot's
/// power spread, 3.5 %, leaves its
/// approaches as near the hole as PGA TOUR players' by distance (ShotLink's proximity from
/// the fairway, about 16, 18, 20, 23, 27, 33, 39 and 48 ft from 50-75 ... 225-250 yd; the bot
/// over 50 National rounds: 13, 14, 22, 25, 22, 36, 46, 44 ft). The tour bot's putts miss by a speed (6 %) and a
/// start-line (1.15°) spread that hole as many as PGA Tour players do from every distance
/// (Broadie 2014, Every Shot Counts: 3 ft 96 %, 5 ft 77 %, 8 ft 50 %, 10 ft 40 %, 20 ft 15 %;
/// the bot on the national course's greens: 95, 79, 51, 41, 13 %). The others hole what Shot
/// Scope's players of their handicap hole (MyGolfSpy, "How putting miss patterns change from
/// scratch to 25 handicap": 0-3 ft / 6-9 ft, scratch 98 / 49 %, 15 handicap 93 / 36 %, 25
/// handicap 88 / 30 %): scratch 1.1° and 8 %, amateur 1.6° and 8 %, beginner 2.1° and 11 %.
/// The bot reads greens perfectly; its start-line spread stands for misreads too, and its
/// chips and pitches start off line by the same spread: read to the hole's exact middle, a
/// tour chip from a few yards off the green drops whenever its pace is right (1.1 chip-ins
/// and 25.9 putts a round on the day's cups; with the spread 0.25 and 27.5, PGA TOUR ~29).
const std::vector<GolferSkill>& golfer_skills();
/// The skill by name; InputError listing the names.
const GolferSkill& golfer_skill(std::string_view name);
/// The skills' names, in golfer_skills() order.
std::vector<std::string> golfer_skill_names();

/// The swing a golfer's meter result delivers with `club` of `eq`: meter_swing at the
/// golfer's full-swing speed; with the driver the golfer's own attack and loft at the club's
/// usual strike (an over-swing still thins the strike without turning the face). Every other
/// full-swing club takes the tour's loft plus the same extra loft the golfer adds to the
/// driver: the extra is the golfer's shaft lean at impact (hands less far ahead), which
/// tilts every face alike. TrackMan's measured lofts agree: the LPGA adds 2.7° to the PGA's
/// driver and 3.4° to its 6-iron (2023 averages: 15.5 / 12.8°, 23.6 / 20.2°).
GolfSwing golfer_swing(const GolferSkill& g, const MeterInput& m, const EquipmentCatalog& eq, const std::string& club);
/// rad, the loft a golfer adds to the tour's delivery of every full-swing club (0 for the
/// tour skill): their driver's loft at the strike less the driver's own.
double added_loft(const GolferSkill& g, const EquipmentCatalog& eq);

/// m the bottom of the swing's arc moves back (toward the golfer) per ms of early timing
/// error as the driver feels it (timing_error_ms; a late release moves it forward): an early
/// release bottoms out behind the ball (fat), a late one ahead of it (thin), as teaching pairs
/// them. Like the meter's other mappings this is the game's feel, set against Shot Scope's
/// greenside bunker rates (MyGolfSpy, "Shot Scope case study: greenside bunker play"): a
/// 2-handicap misses the green from the sand 10 % of the time and leaves it in 1 %, a
/// 26-handicap 50 % and 21 %. At 1 mm the sand wedge (35.25 in) moves its arc 0.78 mm per ms:
/// the tour bot's 12 ms spread enters within ±9 mm of the taught inch and catches 0.3 % of its
/// splashes clean; the beginner's 55 ms ±43 mm, a quarter of them met ball first (clean, and long).
/// Over 120 National rounds each the bots' greenside bunker shots finish off the green 16 %
/// (tour), 18 % (scratch), 38 % (amateur) and 46 % (beginner) of the time; without it 22 % and
/// 18 % for the amateur and the beginner (the beginner better than the amateur). Few stay
/// in: the worlds' bunkers are 0.35 m deep with a 0.6 face, no lip that a fat splash fails.
inline constexpr double kLowPointPerMs = 0.0010;
/// m past the ball where a fairway-bunker pick is meant to bottom out: the splash's inch
/// mirrored (ESTIMATE of "ball first, then the sand"). The amateur's 5-iron (its arc's
/// spread 21 mm) then takes sand first on ~1 pick in 9, mostly a few millimetres.
inline constexpr double kPickBeyond = 0.0254;

/// m behind the ball where a golfer's `club` enters the sand from a ball lying on `lie`, for
/// a swing whose timing error is `timing_ms` (timing_error_ms; 0: as meant). From a bunker
/// the sand and lob wedges (lofted 54° or more, the soles made to skim sand) splash, meant to
/// enter the taught inch behind the ball (kSplashEntry) and moved by the timing error through
/// kLowPointPerMs (0 when the arc bottoms out at or past the ball: it is struck clean);
/// every other club picks the ball clean, as fairway bunkers are taught, its arc meant to
/// bottom out kPickBeyond past the ball ("ball, then sand", the ball back in the stance), so
/// only a timing that moves it back farther than that takes sand first (a heavy pick). 0
/// off sand.
double sand_entry_for(const ClubSpec& club, const std::string& lie, double timing_ms = 0.0);

/// How a stroke from sand met it, in a golfer's words, from where the club entered it
/// (`entry`, sand_entry_for with the swing's timing). A splash: "caught clean, no sand before
/// the ball" where the arc bottomed out at or past the ball (the face meets the ball as from a
/// tight lie: long and spinning, not the skull of a leading edge, which an arc too high would
/// give and this does not model), "heavy, deep in the sand behind it" from twice the taught
/// inch. A pick: "heavy, sand before the ball" when it took any. Else, and off sand, empty.
std::string splash_words(const ClubSpec& club, const std::string& lie, double entry);

/// A golfer's full-swing club speed (m/s) with `club`: the club's tour speed scaled by the
/// golfer's driver speed over the tour's. The putter's is the same for everyone.
double full_swing_speed(const GolferSkill& g, const ClubInfo& club);

/// The 14-club bag every golfer carries (Rule 4.2): driver, 3- and 5-wood, hybrid, 4- to
/// 9-iron, PW, SW, LW, putter, in order from longest to shortest.
const std::vector<std::string>& golf_bag();

/// A club of the bag in a golfer's words: the wedges by name ("pitching wedge" for "pw"), the
/// others as the bag names them ("7-iron").
std::string club_name(const std::string& club);

}  // namespace sweetspot
