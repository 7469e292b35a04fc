// A round of golf (DESIGN §9): the ball played where it lies, stroke by stroke, from each
// hole's tee to the cup, under the Rules of Golf's penalties: out of bounds costs stroke and
// distance (Rule 18.2), water a penalty stroke and a drop back on the line (Rule 17.1d), and
// a hole ends in the cup or at a 10-stroke pick-up. The physics decides every outcome: a
// stroke is a ShotSpec run through the same resolve()/run_shot() as every other shot.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "game/content/course_file.hpp"
#include "game/rules/run_shot.hpp"
#include "game/modes/golf/golfer.hpp"
#include "game/core/stroke_input.hpp"
#include "game/modes/golf/swing_meter.hpp"

namespace sweetspot {


enum class StrokeEnd { Rest, Holed, Water, OutOfBounds };
const char* to_string(StrokeEnd e);

/// Where a par 4's or par 5's tee shot finished, as the statistics keep it (PGA TOUR's
/// "fairways hit"; missed left or right of the hole's line from the tee). A par 3 has none.
enum class TeeShot { None, Fairway, Left, Right };
/// "hit", "left", "right"; "" for None.
const char* to_string(TeeShot t);

struct StrokeRecord {
  std::string club;
  std::string lie;            ///< "tee", "fairway", "rough", "sand", "green"
  Vec3 start = Vec3::Zero();  ///< m, the ball's centre when struck
  Vec3 rest = Vec3::Zero();   ///< m, where it came to rest (in the water or out of bounds: there)
  StrokeEnd end = StrokeEnd::Rest;
  double to_pin_m = 0.0;      ///< m from the rest position to the cup (0 when holed)
  /// m the ball stopped beyond the cup along the line from where it was struck (a putt's
  /// "2 ft past"), negative short of it; 0 when holed.
  double past_m = 0.0;
  /// m the ball stopped right (+) or left (-) of that line; 0 when holed.
  double right_m = 0.0;
  double carry_m = 0.0;       ///< m to the first landing
  double side_m = 0.0;        ///< m right (+) of the stroke's aim line at landing (TrackMan's Side)
  int penalty = 0;            ///< penalty strokes this shot incurred
  double power = 1.0;         ///< the meter's power (1 a full swing; a launch monitor's shot counts as full)
  /// The stroke was conceded, not played (a gimme; in match play Rule 3.2b(1)): the ball is
  /// holed with it, and it counts as a putt.
  bool conceded = false;
  /// It came to rest on a cart path and was moved off it without penalty (Rule 16.1b).
  bool relief = false;
  /// It came to rest on another hole's green and was moved off it without penalty (Rule 13.1f).
  bool wrong_green = false;
  /// It lodged in a tree, off the ground: unplayable, one penalty stroke, and played from the
  /// spot on the ground directly below it (Rule 19.2c, lateral relief's reference point).
  bool unplayable = false;
};

struct HoleCard {
  int number = 0, par = 0;
  int strokes = 0;            ///< shots played + penalty strokes
  int putts = 0;              ///< strokes with the putter from the green (a chip off the green is not a putt)
  int penalties = 0;
  bool holed = false;         ///< false: picked up at 10, or the hole conceded
  bool picked_up = false;     ///< the ball was picked up at the stroke limit
  bool conceded = false;      ///< the player conceded the hole (match play, Rule 3.2b(1))
  /// A par 4's or 5's first stroke at rest on the fairway (or holed), else the side of the
  /// hole's line it missed on (a ball in water, out of bounds, in a tree or short on the tee
  /// is a miss too). None on a par 3.
  TeeShot tee_shot = TeeShot::None;
  /// On this hole's green, or holed, in par − 2 strokes or fewer, penalty strokes counted
  /// (a green "in regulation", as PGA TOUR and every stats app count it).
  bool green_in_regulation = false;
  std::vector<StrokeRecord> shots;
};

/// A hole's wind: speed at 10 m and the direction it blows toward (Environment's fields).
struct HoleWind {
  double speed = 0.0;   ///< m/s
  double toward = 0.0;  ///< rad right of the world's +x
};

class GolfRound {
 public:
  /// Holes at most this many strokes, then the ball is picked up (DESIGN §9).
  static constexpr int kPickUp = 10;

  /// `winds`: one per hole (none: calm everywhere).
  GolfRound(const Assets& assets, Course course, const GolferSkill& golfer, std::vector<HoleWind> winds = {});

  bool finished() const { return hole_ >= course_.holes.size(); }
  const Course& course() const { return course_; }
  const GolferSkill& golfer() const { return golfer_; }
  std::size_t hole_index() const { return hole_; }
  const CourseHole& hole() const { return course_.holes.at(hole_); }
  /// The ground point the ball lies on (for the first stroke of a hole: the tee spot).
  const Vec3& ball() const { return ball_; }
  bool teed() const { return teed_; }
  /// The surface under the ball ("tee", "fairway", "rough", "sand", "green").
  std::string lie() const;
  /// m before the ball where `club` enters the sand from here: a splash with the sand and lob
  /// wedges from a bunker (sand_entry_for), else 0.
  double sand_entry(const std::string& club) const;
  double to_pin() const;
  /// World direction from the ball to the cup, rad right of +x.
  double line_to_pin() const;
  /// The next bend of the hole's line still ahead of the ball (CourseHole::bends): nearer the
  /// cup than the ball is and more than kBendReached from it. None on a straight hole or
  /// once the ball is past the last bend.
  std::optional<Vec3> next_bend() const;
  static constexpr double kBendReached = 25.0;  ///< m: a ball this near a bend has turned it
  const std::vector<HoleCard>& card() const { return card_; }
  int total_strokes() const;
  int total_par() const { return course_.par(); }

  /// The shot the stroke would play, as every other shot is specified.
  ShotSpec spec_for(const StrokeInput& in) const;
  /// Plays the stroke at the current hole: the shot, the rules, the score. Throws InputError
  /// (naming the field) for a club not in the bag or a meter input out of range.
  /// `shot`, when given, receives the physics result (for drawing it). The record stays
  /// valid until the next play().
  const StrokeRecord& play(const StrokeInput& in, ShotResult* shot = nullptr);
  /// Plays a stroke a launch monitor measured: its launch numbers fly from where the ball
  /// lies (on the tee, teed up), `club` is what the player holds (for the card).
  const StrokeRecord& play_launch(const std::string& club, const LaunchNumbers& numbers, ShotResult* shot = nullptr);
  /// The next stroke conceded: counted, the ball holed with it (a gimme, a conceded putt).
  const StrokeRecord& concede_stroke();
  /// The hole given up: it ends with the strokes played so far, not holed (match play).
  void concede_hole();
  /// The hole ends here, not holed and not given up: the opponent conceded it.
  void leave_hole();
  /// The current hole's wind (calm when the round was given none).
  HoleWind wind() const;
  const std::vector<HoleWind>& winds() const { return winds_; }
  /// The shot without playing it (bots plan with it). Deterministic.
  ShotResult simulate(const StrokeInput& in, bool record_samples = false) const;
  /// simulate() in still air: the hole's wind's share in a stroke is what it adds to this.
  ShotResult simulate_calm(const StrokeInput& in) const;
  /// Where a ball at rest on a cart path (Rule 16.1b) or on another hole's green (Rule 13.1f)
  /// is moved to, free: the nearest spot of playable ground (not a path, water, out of bounds
  /// or a green), no nearer the hole; `spot` itself when none lies within kMaxRelief.
  Vec3 free_relief(const Vec3& spot) const;
  static constexpr double kMaxRelief = 15.0;  ///< m searched for ground off the path or green
  /// `p` lies on a green that is not this hole's: no stretch of green joins it to the cup's
  /// (a double green shared with another hole is this hole's too).
  bool on_another_green(const Vec3& p) const;
  /// The ground straight below (x, z) on this hole's world; none off its ground.
  std::optional<SurfaceContact> ground_at(double x, double z) const;
  /// The flight's first touch was well above the ground under it: a tree's crown or trunk
  /// stopped it, not the turf.
  bool first_touch_in_a_tree(const FlightSummary& f) const;
  /// A point more than half a metre above the ground under it: a ball there is in a tree.
  bool lodged_off_the_ground(const Vec3& p) const;
  /// The straight line from the ball to the cup cut into equal stretches of at most `step`
  /// m: each stretch's length and the ground under its middle (none off the world's ground).
  /// What a putt along it rolls over.
  struct LineStretch {
    double length = 0.0;
    std::optional<SurfaceContact> ground;
  };
  std::vector<LineStretch> ground_to_pin(double step) const;
  /// The surface at `p` on this hole ("fairway", "rough", ...), as lie() names the ball's.
  std::string surface_at(const Vec3& p) const;

 private:
  const StrokeRecord& play_spec(const ShotSpec& spec, const std::string& club, double power, ShotResult* shot);
  Vec3 drop_back_on_line(const Vec3& in_water, const Vec3& from) const;
  void finish_hole();
  HoleCard new_card() const;

  const Assets* assets_;  // a pointer, so a round can be assigned (a restarted hole replays into a new one)
  Course course_;
  GolferSkill golfer_;
  std::size_t hole_ = 0;
  Vec3 ball_ = Vec3::Zero();
  bool teed_ = true;
  std::vector<HoleCard> card_;
  std::vector<HoleWind> winds_;
};

}  // namespace sweetspot
