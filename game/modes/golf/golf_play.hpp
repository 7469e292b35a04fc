// The golf game as a headless model (DESIGN §1, §9): a round for one to four players (the
// humans at the keys, the bots taking their own turns), the club and aim the player picks,
// the three-click meter judged from each click's own time, the flyover that opens a hole,
// the flight's time in the air, the result told once the ball stops, the hole's and the
// round's end. The window's view draws it and turns keys into intents; the tests drive it
// with scripted ones.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/golf_group.hpp"
#include "game/modes/golf/meter_clock.hpp"
#include "game/modes/golf/round.hpp"
#include "game/modes/intent.hpp"

namespace sweetspot {

struct GolfSetup {
  std::vector<GolfPlayer> players;  ///< 1-4, in the order they tee off on the first hole
  GolfOptions options;
  bool flyover = true;              ///< each hole opens with a flyover (skippable)
  /// The meter's timing windows, widened or narrowed (difficulty; see MeterClock).
  MeterDifficulty difficulty = MeterDifficulty::Standard;
  /// s: the calibrated delay from seeing the meter to the key arriving; the power and
  /// accuracy clicks (aimed at the marker) are judged that much earlier.
  double input_latency = 0.0;
  /// A saved round's turns, replayed before play goes on (resume), and what the window
  /// kept of it besides (SavedRound): each hole's restarts and the swings cancelled.
  std::vector<GolfEvent> resume;
  std::vector<int> resume_restarts;
  int resume_cancelled = 0;
};

/// You against a bot of your skill in stroke play: the game's default round.
GolfSetup default_golf_setup(const GolferSkill& skill, std::uint64_t seed = 7);

class GolfPlay {
 public:
  enum class Stage { Flyover, Aiming, Swinging, Flying, HoleOver, RoundOver };

  GolfPlay(const Assets& assets, Course course, GolfSetup setup);
  /// default_golf_setup(skill, seed), without the flyover (the tests' round).
  GolfPlay(const Assets& assets, Course course, const GolferSkill& skill, std::uint64_t seed = 7);

  /// Applies `intents` in time order and advances to `now` (s, the mode's clock): a meter
  /// finishes itself at its end, a bot plays its turn, a flight lands, the hole ends.
  void update(const Intents& intents, double now);

  Stage stage() const { return stage_; }
  const GolfGroup& group() const { return group_; }
  /// The player at the ball: the one to play, or in the air the one who struck it.
  int player() const { return player_; }
  const GolfPlayer& player_info() const { return group_.players()[static_cast<std::size_t>(player_)]; }
  /// That player's round (their ball, their card).
  const GolfRound& round() const { return group_.round(player_); }
  /// Who struck the last stroke (the ball in the air, or just stopped).
  int shooter() const { return shooter_; }
  /// A human plays the next stroke at the keys (not a bot, not an auto-putt).
  bool human_turn() const;
  const GolferSkill& skill() const { return golfer_skill(player_info().skill); }
  const GolfBot& caddie() const { return group_.caddie(player_); }
  /// The caddie's stroke from here as he chose the club at the turn's start (C chooses
  /// again): its club and, for a part swing, its power. None on the green or once over.
  const std::optional<StrokeInput>& caddie_plan() const { return caddie_plan_; }
  /// The power of the caddie's part swing when he plans one with `club` (under
  /// kPartSwingShown of a full swing), else none: what the panel, the meter's blue mark and
  /// the map's ring show as his part swing.
  std::optional<double> caddie_part_swing(const std::string& club) const {
    if (caddie_plan_ && caddie_plan_->club == club && caddie_plan_->meter.power < kPartSwingShown) return caddie_plan_->meter.power;
    return std::nullopt;
  }
  static constexpr double kPartSwingShown = 0.97;
  /// The club the caddie would have given but for a tree in its way or in its misses' ("5-iron"
  /// where he hands the 7-iron), empty when the trees changed no club.
  const std::string& caddie_passed_over() const { return caddie_passed_over_; }
  /// The caddie's read of a putt (G on the green): the line and pace he would putt it on,
  /// error-free, rolled on the same green as the putt. It lines the player up along that line;
  /// the pace (the blue mark) is still the player's to strike.
  struct PuttRead {
    double aim = 0.0;       ///< rad right of the line to the pin
    double power = 0.0;     ///< the meter's power for his pace
    double aim_off = 0.0;   ///< m right (+) or left (-) of the cup's centre the aim points, at the cup's distance
    double plays_as = 0.0;  ///< m: the flat-green roll his pace gives (holes 0.43 m past on flat)
    double to_cup = 0.0;    ///< m, the putt's length
    bool holes = false;     ///< his putt, rolled, drops
    std::vector<Vec3> line; ///< the ball's centre along his putt, to where it drops or stops
  };
  const std::optional<PuttRead>& putt_read() const { return putt_read_; }
  const std::string& club() const;
  double aim() const { return aim_; }              ///< rad right of the line to the pin
  /// Why the aim points off the pin, as the caddie set it: the dogleg's corner, a bend in the
  /// line too slight to call a dogleg (Bend), the way out past a tree, the crosswind's drift
  /// held off, or his line (a slope, a bank, the curve: where his tries finished nearest the
  /// pin). Pin once the player has moved the aim: then it is his own, and no reason is told.
  enum class AimWhy { Pin, Corner, Bend, WayOut, Wind, Slope, Line };
  /// A hole's line that turns by this much or more at a bend is a dogleg: a turn a player sees
  /// from the tee (the fairway's edges leave the straight line by tens of metres at a drive's
  /// length). The words a golfer uses, not a rule of the game.
  static constexpr double kDoglegTurn = 0.26;  // rad (15 deg)
  AimWhy aim_why() const;
  const std::optional<MeterClock>& meter() const { return meter_; }
  /// The meter a swing press would start now, before its first click: its tempo (a short
  /// putt's and a part swing's slowed to their mark) and perfect window, which the idle bar
  /// draws so it shows the swing about to be made.
  MeterClock next_meter() const;
  /// The last stroke's physics and the time it was struck (its flight runs from then).
  const ShotResult& last_shot() const { return last_; }
  double struck_at() const { return struck_at_; }
  /// When the last ball stopped (s; the view holds on it a moment).
  double landed_at() const { return landed_at_; }
  const GolfSetup& setup() const { return setup_; }
  /// A new calibration's latency (s), from the next click on.
  void set_input_latency(double seconds) { setup_.input_latency = seconds; }
  /// The last stroke's meter result (none for the bots' and the caddie's strokes).
  const std::optional<MeterInput>& last_meter() const { return last_meter_; }
  /// The meter as the player to play's own last stroke left it: where his clicks landed
  /// (the view marks them). Each player's own: at a hot seat a friend's clicks are no guide.
  const std::optional<MeterClock>& last_click() const;
  /// That last stroke was on this hole: its putt's power is a guide to this putt's (one on
  /// another green is another length).
  bool last_click_here() const;
  /// What the last stroke did, in player words; set when the ball stops, not before.
  const std::string& message() const { return message_; }
  /// The message is the last stroke's result (last_record() is that stroke), not a note of
  /// the game's own (a cancelled swing, a restarted hole, a match decided).
  bool message_is_result() const { return message_is_result_; }
  /// The last stroke's record (where it started and stopped) and the lie it stopped on.
  const StrokeRecord& last_record() const { return last_record_; }
  const std::string& last_rest_lie() const { return last_rest_lie_; }
  /// The last stroke's flight first touched a tree, not the ground: its "carry" is where it
  /// struck the tree.
  bool last_hit_tree() const { return last_hit_tree_; }
  /// A player's own last stroke on the hole being played: what it did and where it stopped.
  /// The HUD shows it on their turn, when somebody else has played since.
  struct OwnLast {
    std::string message;   ///< as message() told it
    StrokeRecord record;
    std::string rest_lie;  ///< the lie it stopped on ("holed" when it went in)
    std::size_t hole = 0;  ///< the group's hole it was played on
  };
  /// `player`'s last stroke on the current hole; null before their first on it.
  const OwnLast* own_last(int player) const;
  /// Strokes cancelled with Esc this round (none of them counted).
  int cancelled() const { return cancelled_; }
  /// The last swing was cancelled or abandoned, and nothing has been said or swung since:
  /// the meter's caption says so where the player is looking.
  bool swing_undone() const { return swing_undone_; }
  /// The flyover's progress, 0 at the tee... 1 done (the view flies the camera with it).
  double flyover_progress(double now) const;

  /// The hole on screen (the group's index): during a flight and on the card after it, the
  /// hole of the last stroke (or the hole just conceded), though the group may already be on
  /// the next.
  std::size_t hole_shown() const { return after_stroke() ? round_hole_ : group_.hole_index(); }
  /// last_shot() was struck on hole_shown(): not so for a hole given up before a ball was
  /// struck on it, whose card must not replay the previous hole's last stroke.
  bool last_shot_on_hole_shown() const { return struck_hole_ == hole_shown(); }
  /// A stroke is in the air, or its hole or round has just ended on it.
  bool after_stroke() const { return stage_ == Stage::Flying || stage_ == Stage::HoleOver || stage_ == Stage::RoundOver; }
  /// How many times the hole at group index `hole` was started again from the pause menu
  /// this round: a mulligan the card shows (R), since the strokes it threw away are gone.
  int restarts(std::size_t hole) const { return hole < restarts_.size() ? restarts_[hole] : 0; }
  /// restarts(hole) for every hole begun: the printed card's R marks (group_table).
  const std::vector<int>& restarts() const { return restarts_; }
  /// The strokes (all players', conceded ones included) played on the hole a restart would
  /// start again: what the pause menu's restart throws away. 0 once the round is over (a
  /// new round keeps the finished card's result).
  int strokes_a_restart_loses() const;
  /// The ball's centre where it lies (teed up on a tee).
  Vec3 ball_centre() const;
  /// World direction of the aim, horizontal unit.
  Vec3 aim_direction() const;
  /// Within kPuttGuideReach of the cup: how far a putt of `power` rolls on a flat green of
  /// this hole's speed (m), from the same physics as the putt. 0 farther out.
  double flat_roll(double power) const;
  /// The power that rolls `distance` m on that flat green (the preview's marks).
  double power_for_roll(double distance) const;
  /// The putt to the cup as the preview reads it (m of green): the distance, with each stretch
  /// of the line off the green (fringe, fairway, rough) counted as the length of green that
  /// takes as much out of a roll. On the green, the distance. 0 beyond kPuttGuideReach.
  double putt_plays_as() const { return putt_plays_as_; }
  /// The power the preview marks at the cup: it rolls the putt as it plays and
  /// GolfBot::kPuttPast on (Pelz's 17 in), so a ball stopped on the mark arrives at the cup
  /// still rolling, as a holed putt must; the caddie paces his putts the same.
  double cup_mark_power() const;
  /// The surface a putt from off the green meets first ("fairway"); empty on the green.
  const std::string& putt_crosses() const { return putt_crosses_; }
  /// The preview is offered this near the cup (m): past it nobody putts.
  static constexpr double kPuttGuideReach = 40.0;
  /// The putt preview (flat_roll and its marks) is offered for this turn: a human's, with the
  /// ball within kPuttGuideReach of the cup.
  bool putt_guide() const { return !roll_table_.empty(); }
  /// A square swing of `club` at `power` (full by default) along the aim from where the ball
  /// lies, in this hole's wind and off this lie: its carry (m), from the same physics as the
  /// stroke; the bag's carries are calm air on flat fairway.
  double carry_here(const std::string& club, double power = 1.0) const;
  /// The same swing's distance to where it stops (m): the caddie picks a club by where it
  /// finishes, so a club that flies short of the pin and runs up to it is said both ways.
  double stops_here(const std::string& club, double power = 1.0) const;
  /// Where the same swing first comes down (world m): the wind's drift and the curve in it,
  /// which the map centres the landing spread on. The ball's centre when there is no stroke.
  Vec3 landing_here(const std::string& club, double power = 1.0) const;
  /// The same swing's carry from here in still air (m): the wind's share in carry_here() is
  /// the difference, the rest of its difference from the bag's stock carry is the ground's
  /// (the lie, and the landing above or below the ball). NaN when the still-air flight ends
  /// in a tree: held off a row of trees for the wind to bring back, it says nothing of the
  /// wind's share.
  double calm_carry_here(const std::string& club, double power = 1.0) const;
  /// How far above the ball (m, − below) the same stroke in still air first lands: what
  /// makes its carry from a clean lie differ from the bag's.
  double landing_rise_here(const std::string& club, double power = 1.0) const;
  /// Where the stroke the player would play with `club` along the aim (the caddie's part
  /// swing when he planned one with it, else a full swing) ends its flight against something
  /// standing above the ground, a tree: its carry (m) to it. None when it lands on the ground.
  std::optional<double> tree_in_the_way(const std::string& club) const;

  /// The meter's distance scale for a swing, as a putt's roll scale: `club`'s carry from here
  /// (m) at `power`, and the power that carries `distance`, from carry_here at 5 %, 10 %, 15 %,
  /// 20 %, 30 % ... 110 % of the meter (the same physics as the stroke). The table is kept while the player,
  /// club, ball and hole stay: an aim's step barely turns the wind against the line, and ten
  /// flights per press of an arrow would stall the frame. Held at its longest past a tree
  /// that stops the flight.
  double carry_at_power(const std::string& club, double power) const;
  double power_for_carry(const std::string& club, double distance) const;
  /// The same table's distance to where the stroke stops (m), and the power that stops it
  /// `distance` away: a ball that runs on after landing is aimed by where it finishes.
  double stop_at_power(const std::string& club, double power) const;
  double power_for_stop(const std::string& club, double distance) const;
  /// The power whose stroke of `club` along the aim stops nearest the pin, found by flying
  /// it: the table brackets the pin, bisection on the stroke itself narrows the bracket to
  /// kPinPowerStep. Where the stop jumps across the pin (a pitch that lands short in the
  /// rough and stops, and with a touch more lands on the green and runs on) no power stops
  /// there, and `stops` says where the nearest one does. None when 5-110 % falls short of
  /// the pin or every power runs past it. Kept for the player, club, ball, hole and aim.
  struct PinPower {
    double power = 0.0;
    double stops = 0.0;  ///< m from the ball to where it stops
  };
  std::optional<PinPower> pin_power(const std::string& club) const;
  static constexpr double kPinPowerStep = 0.004;

  /// What a golfer of the player's skill (GolferSkill's meter errors) spreads a swing of
  /// `club` at `power` from here by, one standard deviation each way (m): along the line, a
  /// quarter of the carry between the power click's ±2 sd (a part swing's wider, by its
  /// partial_feel_sd, as the bots draw it); across it, a quarter of the landing's side between
  /// the third click's ±2 sd (four strokes flown: the wind and the lie in them). The map's
  /// prior for the player's dispersion until his own swings with the club give one. None for
  /// the putter. Kept for the player, club, ball, hole, aim and power.
  struct Spread {
    double carry_sd = 0.0;
    double side_sd = 0.0;
  };
  std::optional<Spread> skill_spread(const std::string& club, double power = 1.0) const;

  /// Water and bunkers the aim line crosses from the ball to a little past where the stroke
  /// the player would play with `club` stops (the caddie's part swing, else a full one): each
  /// stretch's kind ("water", "sand") and its near and far distance (m), nearest first. What a
  /// caddie says before the shot, and what the low view from behind the ball hides.
  struct Hazard {
    std::string kind;
    double from = 0.0, to = 0.0;
  };
  const std::vector<Hazard>& hazards_on_line(const std::string& club) const;

  /// Aim steps: a degree for a full shot, a quarter of one for a putt.
  static constexpr double kAimStep = 0.017453292519943295;   // rad (1°)
  static constexpr double kPuttAimStep = 0.004363323129985824; // rad (0.25°)
  /// A scorecard takes no Enter for this long after the ball stops: a press meant to skip a
  /// flight that had just ended does not skip the card too.
  static constexpr double kCardGrace = 0.5;  // s
  /// The last ball's rest stays on screen this long before the next player's view (the
  /// window holds it; a turn's clock runs from the rest).
  static constexpr double kRestShown = 1.2;  // s
  /// A bot swings this long after its turn begins: the rest shown, then its address for
  /// 1.2 s, so a player sees whose turn it is before the ball is in the air.
  static constexpr double kBotAddress = kRestShown + 1.2;  // s
  /// The flyover's length: tee to green and back (TV golf's hole flyovers run 5-10 s).
  static constexpr double kFlyover = 6.0;  // s

 private:
  void apply(const Intent& in);
  void advance(double t);
  void land(double t);
  /// The player to play gives up the hole at `t` (H twice, or a bot that can no longer halve
  /// it): the note said, on to the next turn, hole or the round's end.
  void concede_hole(double t);
  void strike(const StrokeInput& s, bool bot, double t);
  /// The player's own stroke as the meter gave it: its clicks kept (whose, on which hole) for
  /// the view's marks, then struck.
  void strike_from_meter(const MeterInput& m, double t);
  void begin_turn(double t);
  void choose_club();
  /// Why the aim just taken from the caddie points off the pin (`tree_at_flag`: his club
  /// aimed at the flag strikes a tree).
  AimWhy aim_why_for(const GolfRound& r, bool tree_at_flag) const;
  void new_round(double t);
  void restart_hole(double t);
  void build_roll_table();
  /// G: the caddie reads the putt (or the read is hidden again).
  void read_green();
  /// The HUD's message; `result`: it tells the last stroke's result (message_is_result()).
  void say(std::string text, bool result = false) {
    message_ = std::move(text);
    message_is_result_ = result;
    swing_undone_ = false;
  }

  const Assets& assets_;
  Course course_;
  GolfSetup setup_;
  GolfGroup group_;
  int player_ = 0;
  int shooter_ = 0;
  Stage stage_ = Stage::Aiming;
  std::size_t club_ = 0;  ///< index in golf_bag()
  double aim_ = 0.0;
  std::optional<MeterClock> meter_;
  std::optional<MeterInput> last_meter_;
  /// Per player: the meter as his own last stroke left it, and on which hole (group index).
  std::vector<std::optional<MeterClock>> click_of_;
  std::vector<std::size_t> click_hole_;
  std::size_t round_hole_ = 0;            ///< the group's hole when the last stroke was struck, or the hole conceded
  std::optional<std::size_t> struck_hole_;  ///< the group's hole when last_ was struck; none before this round's first
  ShotResult last_;
  StrokeRecord last_record_;
  std::string last_rest_lie_;
  bool last_hit_tree_ = false;
  std::string pending_message_;  ///< the stroke's result, told when the ball stops
  std::vector<std::optional<OwnLast>> own_last_;  ///< per player, set when their ball stops
  std::vector<int> restarts_;                     ///< per hole: restart_hole() this round
  double struck_at_ = 0.0, landed_at_ = 0.0, turn_at_ = 0.0, flyover_at_ = 0.0;
  std::string message_;
  bool message_is_result_ = false;
  bool concede_asked_ = false;  ///< H once in match play: a second H gives up the hole
  int cancelled_ = 0;
  bool swing_undone_ = false;
  std::vector<std::pair<double, double>> roll_table_;  ///< (power, metres) on the flat green
  std::optional<StrokeInput> caddie_plan_;
  std::string caddie_passed_over_;
  AimWhy aim_why_ = AimWhy::Pin;  ///< why the caddie's aim points off the pin (aim_why())
  std::optional<PuttRead> putt_read_;
  double putt_plays_as_ = 0.0;
  std::string putt_crosses_;
  /// A stroke of `club` along the aim at `power`, flown from where the ball lies: its carry
  /// and whether a tree stopped it. Keyed by player too: players tee off from one spot with
  /// their own swings.
  /// What a kept answer about a stroke from here depends on: whose turn, which club, from
  /// where, on which hole, along which aim.
  struct StrokeKey {
    int player = 0;
    std::string club;
    Vec3 ball = Vec3::Zero();
    std::size_t hole = 0;
    double aim = 0.0;
    bool operator==(const StrokeKey& o) const {
      return player == o.player && club == o.club && ball == o.ball && hole == o.hole && aim == o.aim;
    }
  };
  /// The key of `club`'s stroke now; `along_aim` false leaves the aim out (a table kept
  /// whatever the aim).
  StrokeKey key_for(const std::string& club, bool along_aim = true) const;
  struct FlownHere {
    StrokeKey key;
    double power = 1.0;
    double carry = 0.0;
    double total = 0.0;
    double calm_carry = 0.0;      ///< the same swing's in still air (NaN: it ends in a tree)
    Vec3 landing = Vec3::Zero();  ///< where it first comes down
    Vec3 rest = Vec3::Zero();     ///< where it stops
    bool in_tree = false;
    Vec3 calm_landing = Vec3::Zero();  ///< where the still-air flight first comes down
  };
  /// The stroke flown (or the last answer for it, from `flown_` when it is the same stroke).
  const FlownHere& flown_here(const std::string& club, double power) const;
  /// The caddie's power for `club` when he planned a part swing with it, else 1 (a full swing).
  double part_swing_power(const std::string& club) const;
  /// The last full swing asked for and the last part swing: the HUD asks of both each frame.
  mutable std::optional<FlownHere> flown_[2];
  struct CarryTable {
    StrokeKey key;                                 ///< its aim left out
    std::vector<std::pair<double, double>> table;  ///< (power, carry m), the carry never falling
    std::vector<std::pair<double, double>> stops;  ///< (power, m to where it stops), never falling
  };
  const CarryTable& carry_table(const std::string& club) const;
  mutable std::optional<CarryTable> carry_table_;
  struct HazardsHere {
    StrokeKey key;
    std::vector<Hazard> hazards;
  };
  mutable std::optional<HazardsHere> hazards_;  ///< the last answer: the HUD asks each frame
  struct PinPowerHere {
    StrokeKey key;
    std::optional<PinPower> answer;
  };
  mutable std::optional<PinPowerHere> pin_power_;  ///< the last answer: the HUD asks each frame
  struct SpreadHere {
    StrokeKey key;
    double power = 1.0;
    Spread answer;
  };
  mutable std::optional<SpreadHere> skill_spread_;  ///< the last answer: the map asks each frame
};

const char* to_string(GolfPlay::Stage s);

}  // namespace sweetspot
