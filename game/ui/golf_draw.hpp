// The golf view's 2-D layer over the 3-D hole: the HUD, the meter with its click marks and
// the putt preview, the launch-monitor panel, the scorecard, and the marks drawn on the
// course (cup and flag at any distance, the aim line, the green's slopes, the map's rings).
// Distances in the player's unit system, words a golfer uses.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "game/content/tree_crowns.hpp"
#include "game/modes/golf/golf_play.hpp"
#include "game/render/camera.hpp"
#include "game/render/shot_scene.hpp"

namespace sweetspot {

/// One unit system for everything a player reads: metres (putts in metres too) or yards
/// (putts in feet).
struct GolfUnits {
  bool imperial = true;
  std::string distance(double m) const;  ///< "154 m" / "168 yd"
  std::string putt(double m) const;      ///< "2.4 m" / "8 ft"
  std::string speed(double mps) const;   ///< "5 m/s" / "11 mph"
  /// A distance on the course: short of kNear in the putt's units ("56 ft"), else as
  /// distance(); every label of a carry or a distance to the pin reads through it, so the
  /// picture and the panels give one number in one unit.
  std::string course(double m) const;
  /// `m` in the unit course(`longest`) reads in: two figures of one sentence ("carries 43 ft,
  /// stops 23 yd") in one unit, the longer one's.
  std::string course(double m, double longest) const;
  static constexpr double kNear = 20.0;  ///< m: ~22 yd, a chip's length, where golfers count feet
};

/// Downhill arrows on the green: where the ground tilts and how much (rise over run), and
/// the room the arrow has (m, the spacing of its neighbours: it is drawn shorter than that).
struct SlopeArrow {
  Vec3 at, downhill;
  double room = 1.0;
};
/// The green's slope where a golfer reads it: along the line from the ball to a little past
/// the cup, as wide as a putt of that length can break, on a grid that grows with the putt.
std::vector<SlopeArrow> green_slopes(const WorldAsset& w, const Vec3& ball, const Vec3& pin);

/// `flight_t`: seconds into the last stroke's flight (the HUD says in the air or running out).
/// `all_keys`: every key the round takes, four lines; else the few a stroke needs, in one.
/// Returns the panel's box (x0, y0, x1, y1 px): the next frame's scene labels keep clear of it.
Eigen::Vector4f draw_golf_hud(const GolfPlay& play, const GolfUnits& units, int camera_mode, bool settling, double flight_t,
                              bool all_keys = true);
/// The meter bar, bottom centre: −15 % to 110 %, the accuracy mark as wide as the perfect
/// window, the marker, and where the last swing's clicks landed.
struct MeterBar {
  /// The meter's fractions the bar spans: 15 % past the accuracy mark to 110 % power.
  static constexpr double kLow = -0.15, kHigh = 1.1;
  float x0 = 0.0f, y0 = 0.0f, bw = 560.0f, bh = 26.0f;
  /// The fractions this bar spans: kLow..kHigh, or for a chip zoomed to its top (zoomed_top).
  double low = kLow, high = kHigh;
  double shown = 0.0;  ///< the marker's position now
  /// x of fraction `f`, held at the bar's ends.
  float at(double f) const { return x0 + static_cast<float>((std::clamp(f, low, high) - low) * (bw / (high - low))); }
  bool zoomed() const { return high < kHigh; }
};
/// `meter`: the swing under way, if any; `next`: the meter a press would start (its pace and
/// perfect window are the idle bar's). `last`: the last swing's clicks, marked where they
/// show what they would on this bar (last_click_marks).
/// `top`: the power at the bar's right end (kHigh; less zooms the bar on a chip's few per
/// cent, the accuracy's stretch scaled with it so it keeps its share of the bar).
/// The box (x0, y0, x1, y1 px) the meter takes at the bottom of a `w` x `h` window: its
/// caption above, the bar, its power figure to the right and its scale below. Labels on the
/// course step aside from it.
Eigen::Vector4f meter_area(int w, int h);
MeterBar draw_meter_bar(const std::optional<MeterClock>& meter, const MeterClock& next, const std::optional<MeterClock>& last,
                        int w, int h, double now, double top = MeterBar::kHigh);
/// Which of the last swing's click marks read true on the bar for `next`, a bar whose
/// right end is `top`: its power where the bar reaches it (a 95 % drive's mark held at a
/// chip's 40 % end would read as a 40 % swing); its accuracy only for a swing at the same
/// pace, as a click's place on the bar is its timing error at the pace it was made (a
/// 10 ms late click is twice as far along at the full tempo as on a bar slowed to half).
struct ClickMarks {
  bool power = false, accuracy = false;
};
ClickMarks last_click_marks(const MeterClock& last, const MeterClock& next, double top);
/// The bar's top for a swing whose pin mark is at `pin_power` (none: the pin beyond reach):
/// the whole bar while the mark sits past MeterBar's middle, else zoomed so it sits near
/// 60 % of the way along, in steps of 10 % of power (an aim's step does not jump the scale),
/// never under 30 %.
double zoomed_top(std::optional<double> pin_power);
/// The words over a full swing's meter: the power as the marker climbs, the accuracy's cue
/// on its way back, and `before` until the first click.
std::string full_swing_caption(const std::optional<MeterClock>& meter, double now, const std::string& before);
/// `text` over the bar on a dark band, so the view behind never runs through it.
void draw_meter_caption(const MeterBar& bar, const std::string& text);
/// The meter, bottom centre; on a putt the flat-green distances along it.
void draw_golf_meter(const GolfPlay& play, const GolfUnits& units, int w, int h, double now);
/// Ball data at launch, carry once the ball has landed (as a launch monitor shows them).
/// `hit_tree`: its first touch was a tree, so the carry reads as where it struck it.
/// `top`: its top edge (px); below another panel where the window is too narrow for both.
void draw_launch_panel(const ShotResult& r, const GolfUnits& units, int w, double flight_t, bool hit_tree = false,
                       float top = 10.0f);
void draw_golf_card(const GolfPlay& play, int w, bool final);
/// Whether the card (600 px, centred) reaches the wind dial (right edge, 94 px): in a window
/// narrower than ~790 px, where the dial would stand over the card's right column.
bool golf_card_covers_wind(int w);
/// The cup and flagstick, never smaller than a few pixels however far. `scene_has_flag`: the
/// 3-D scene draws this pin's own flag (a course's), so near enough only the cup (and the
/// label) is added.
/// `label`, when not empty, is written beside the flag's cloth (a range's yardage, a far
/// pin's distance), or where that would cover one of `clear_of` (the image's own labels,
/// Scene::label_boxes: a shot's carry reads first; a panel over the scene) beside the cup,
/// else not at all. The drawn pole leaves gaps over `clear_of`, and its cloth gives way
/// to a box it would cover.
void draw_cup_and_flag(const Camera& cam, const Vec3& pin, int w, int h, bool scene_has_flag = true, const std::string& label = {},
                       const std::vector<Eigen::Vector4f>& clear_of = {});
/// The aim line from the ball (to the cup's distance and a metre on for a putt).
void draw_aim(const GolfPlay& play, const Camera& cam, int w, int h);
/// The other players' balls on this hole, each with its player's name, where `cam` sees them
/// (the map draws its own): on a green a partner's ball is part of the read. Not drawn
/// where one of `clear_of` (the play panel) would cover its name.
void draw_other_balls(const GolfPlay& play, const Camera& cam, int w, int h, const std::vector<Eigen::Vector4f>& clear_of);
/// The caddie's read of the putt (GolfPlay::putt_read), dotted along the green where his
/// putt rolls.
void draw_putt_read(const GolfPlay& play, const Camera& cam, int w, int h);
/// The read in a golfer's words: which way it breaks and where to aim, in cups and the
/// player's units, and how hard ("uphill: play it as 16 ft on the flat"). Empty without a read.
std::string putt_read_words(const GolfPlay::PuttRead& read, const GolfUnits& units);
/// Why a club's carry from here (m) differs from the bag's `stock`: the wind's share (`here`
/// less the same swing's in still air, `calm`) and the ground's (the lie, a landing above or
/// below the ball: the rest), each when it is worth naming (~3 yd) — ": wind +9 yd, lie and
/// slope -12 yd"; "" when neither is. A bag the player measured on the range (`measured`)
/// holds his own strikes as well: no ground's share then. `calm` NaN (the still-air flight
/// ends in a tree): the wind's and the ground's shares together, ": wind, lie and slope -10 yd".
/// `ground`: the ground's share in words, ground_share_words().
std::string why_from_here(double stock, bool measured, double here, double calm, const GolfUnits& units,
                          const char* ground = "lie and slope");
/// The ground's share of a carry in a golfer's words: from a clean lie (tee, fairway, green)
/// only the landing's height changes it, "uphill" (landing `rise` m above the ball) or
/// "downhill"; from the rough or sand the lie and the slope together; a splash (`splash`: the
/// club enters the sand first) by its name.
const char* ground_share_words(const std::string& lie, double rise, bool splash = false);
/// A putt's break or aim beside the cup: inches (centimetres) inside a yard (a metre), then
/// the putt's units.
std::string break_length(double m, const GolfUnits& units);
/// The green's slopes as arrows on the ground for the scene (ShotScene::set_ground_arrows),
/// so the golfer and the meter are never drawn under them.
std::vector<GroundArrow> slope_arrows(const std::vector<SlopeArrow>& slopes);
/// The map's marks: the ball, the selected club's carry ring and the player's dispersion
/// ellipse for it (from this round's shots with it, else their bag's measured spread).
/// `crowns`: the hole's trees (game/content/tree_crowns), each drawn as a dark disc;
/// `clear_of`: the image's own labels (Scene::label_boxes), which the marks' words step aside from.
void draw_map_marks(const GolfPlay& play, const GolfUnits& units, const Camera& cam, int w, int h,
                    const std::vector<TreeCrown>& crowns, const std::vector<Eigen::Vector4f>& clear_of);
/// The hole's wind as an arrow turned as the view is: `screen_up` is the heading (rad, as a
/// hole's line) of the ground direction that points up the screen (screen_up_heading).
void draw_wind(const GolfPlay& play, const GolfUnits& units, int w, double screen_up);
/// The box (x0, y0, x1, y1 px) the wind dial and its label take in a window `w` wide.
Eigen::Vector4f wind_area(int w);
/// The heading of the ground direction up `cam`'s image: its forward along the ground for a
/// view along it, its up for a view from above (both lie in the same vertical plane).
double screen_up_heading(const Camera& cam);

}  // namespace sweetspot
