// The batting cage as a headless model (DESIGN §1, §9): batting-practice pitches on call, or
// a live game against the league's pitcher (his arsenal and plan by count, balls, strikes,
// fouls, walks, strikeouts, hit-by-pitch; the innings, outs, runners and runs: live_inning.hpp),
// the swing judged from the moment its key went down against the pitch's arrival, the bat's
// height, power or contact, the batter's side, the pro bot on request (B: at the pitch on its
// way, or at the next one he calls for), and the session's record. A batted ball's outcome
// is told when it comes down; while it flies, its launch. The window's view draws it; the tests drive it with scripted intents.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "game/modes/baseball/hitter.hpp"
#include "game/modes/baseball/live_inning.hpp"
#include "game/modes/baseball/pitcher.hpp"
#include "game/modes/baseball/session.hpp"
#include "game/modes/intent.hpp"

namespace sweetspot {

/// The call for a swing that missed, in a hitter's words: early or late by how much and why
/// (through the zone, past the end of the bat), or how far over or under the ball the bat went.
/// `timing_ms`: the press's timing as the player felt it; `beyond_m`: how much farther under
/// (+) or over the ball the bat was set than the swing's range let the physics take.
/// `height_read`: the bat's height was set for the player (timing only), so a miss is said
/// by its timing, the height only as where the bat went. `advise`: the swing was the player's,
/// so the call says what mends it; the pro's own miss is told without advice.
std::string miss_call(const SwingResult& result, double timing_ms, double beyond_m = 0.0, bool height_read = false,
                      bool advise = true);

class BattingCage {
 public:
  enum class Stage { Ready, Pitching, Batted, Called };

  /// The pitch plays at this fraction of real time: 0.4 s is a hitter's lifetime, not a game's.
  /// The standard cage's; `--difficulty easy` slows it further (the swing's window in the
  /// player's time grows as 1/scale: about +-28 ms at 0.5, +-47 ms at 0.3) and `pro` plays it
  /// in real time (+-14 ms, a hitter's own window).
  static constexpr double kPitchTimeScale = 0.5;
  static constexpr double kEasyPitchTimeScale = 0.3, kProPitchTimeScale = 1.0;
  /// The cage's bat (bats.toml): what it swings, and what its crack rings like.
  static constexpr const char* kBat = kGameBat;
  /// The strike zone's bottom and top (ft 1.6 and 3.5, as in_zone) and the plate's half width, m.
  static constexpr double kZoneLow = StrikeZone::kLow, kZoneHigh = StrikeZone::kHigh, kPlateHalf = StrikeZone::kHalfWidth;
  /// After the pitch crosses the plate it is taken (called) once this much pitch time more has passed.
  static constexpr double kTakenAfter = 0.15;  // s
  /// m the bat's height moves each Up or Down: a fifth of the zone in five presses, and
  /// under the contact's reach (the bat's and the ball's radii, 6.6 cm) so a step never
  /// jumps from over the ball to under it.
  static constexpr double kBatStep = 0.025;
  /// s after a pitch goes by that Space is still his swing, too late, not a call for the next
  /// pitch (a press a beat late would otherwise throw one he is not ready for; P still calls).
  static constexpr double kLateSwing = 1.2;
  /// The pitcher's delivery before the release, in pitch time (figures.hpp kWindupTime): a
  /// pitch called at mode time t leaves his hand at t + kWindupTime / time_scale().

  /// `time_scale`: the pitch's pace against real time, 0.1..1 (kPitchTimeScale by default).
  explicit BattingCage(const Assets& assets, std::uint64_t seed = 11, double time_scale = kPitchTimeScale);

  void update(const Intents& intents, double now);

  Stage stage() const { return stage_; }
  const PitchCall& call() const { return call_; }
  const PitchFlight& pitch() const { return pitch_; }
  /// The pitch's movement as Statcast reads it (its run and rise or drop, the seam wake's
  /// share): what the HUD tells once the pitch has gone by.
  const PitchMovement& movement() const { return movement_; }
  /// m, the cage's ball (the league's).
  double ball_radius() const;
  /// Pitch time (s since release, slowed by time_scale(); negative in the wind-up) at mode time `t`.
  double pitch_clock(double t) const { return (t - released_at_) * time_scale_; }
  /// The pitch's pace against real time (the constructor's; E steps it for the next pitch).
  double time_scale() const { return time_scale_; }
  /// The pace the next pitch will come at (E's choice; time_scale() once it is thrown).
  double next_time_scale() const { return next_time_scale_; }
  /// A pace in the player's words: "easy, 30 % of real speed", "standard, ...", "pro, real speed".
  static std::string pace_name(double time_scale);
  /// The batted ball's flight runs from this mode time.
  double batted_at() const { return batted_at_; }
  /// The last swing met the ball and its flight is on show (in the air, or called after it).
  bool batted() const { return stage_ == Stage::Batted || (stage_ == Stage::Called && last_.result.contact); }
  /// Mode time of the last swing's contact (or miss), for the batter's animation.
  double swung_at() const { return swung_at_; }
  double bat_height() const { return bat_height_; }  ///< m above the ground where the bat meets the ball's path
  bool power() const { return power_; }
  /// Timing only: the bat meets the pitch at the height a pro hitter reads it at (his read's
  /// own errors included), and the player's key is the swing's timing alone. Off: Up/Down set
  /// the height.
  /// The next pitch's thrower is left-handed: the live game's league pitcher, or in practice
  /// the last pitch's (the machine's right-hander).
  bool pitcher_left() const { return live_ ? pitcher_.profile().left_handed : call_.left_handed; }
  bool timing_only() const { return timing_only_; }
  bool left_handed() const { return lefty_; }
  const SwingRecord& last() const { return last_; }
  /// The last batted ball's path as the play went (as_played): a catch ends it in the glove.
  const ShotTrajectory& played() const { return played_; }
  const std::vector<SwingRecord>& swings() const { return swings_; }
  /// Pitches that have been taken or swung at this session (play --pitches counts these).
  int pitches_done() const { return pitches_done_; }
  /// m each swing's ball went as the play went (as_played's carry: to the glove on a catch),
  /// in swings() order.
  const std::vector<double>& carries_as_played() const { return carries_as_played_; }
  /// The swings whose outcome the player has been told: all but a batted ball still in the
  /// air (the HUD's session figures would otherwise give away a hit before its call).
  std::size_t swings_told() const { return swings_.size() - (told_ ? 0 : 1); }
  /// The last swing's outcome has been called: a batted ball's once the play is made, a
  /// miss once the pitch reaches the plate (a swing through it early is not yet a strike
  /// the umpire has seen, and the ball is still on its way).
  bool told() const { return told_; }
  /// The player's own last swings in a row that missed the ball (the pro's left out): three
  /// and the panel points to a slower pitch.
  int misses_in_a_row() const;
  const std::string& call_text() const { return call_text_; }
  /// The player's own swings as he has been told them (the pro's, B, only counted): the
  /// panel's figures and the exit report's. Contact counts fouls (a foul is contact); the
  /// batted-ball figures are Statcast's batted-ball events, fair balls only, so a long foul is
  /// not the session's longest hit, each counted once its play is called.
  struct Figures {
    int swings = 0, by_pro = 0, contact = 0, fair = 0, hard_hit = 0, home_runs = 0;
    double mean_exit_speed = 0.0;  ///< m/s, fair balls
    double mean_launch = 0.0;      ///< rad, fair balls
    double longest = 0.0;          ///< m, the longest fair ball as played (to the glove on a catch)
  };
  Figures figures() const;
  /// The other record's figures (batting practice's while live, the live game's while
  /// practising): A keeps the record it leaves and gives it back on the way back, so a
  /// switch loses no swings. None when the other record has no swing.
  std::optional<Figures> other_figures() const;
  /// The other record's swings as they were called, in order.
  const std::vector<SwingRecord>& other_swings() const { return kept_.swings; }
  /// Live at-bats: the count, and the plate appearances so far.
  bool live() const { return live_; }
  /// As told: while a ball in play is in the air, the count he swung at (the plate
  /// appearance it ends is not yet told either).
  const Count& count() const { return told_ ? count_ : count_before_; }
  struct AtBats {
    int pa = 0, strikeouts = 0, walks = 0, hit_by_pitch = 0, hits = 0, home_runs = 0, outs = 0;
  };
  /// As the player has been told them: a ball in play counts from its call.
  const AtBats& at_bats() const { return told_ ? at_bats_ : at_bats_before_; }
  /// Live: the plate appearances of the game now on (at_bats() counts every game's).
  int game_pa() const { return at_bats().pa - game_first_pa_; }
  /// In batting practice: the plate appearances of the live game kept for A's way back.
  int other_game_pa() const { return kept_.at_bats.pa - kept_.game_first_pa; }
  /// The final lines of the live games finished and replaced by a new one this session.
  const std::vector<std::string>& finished_games() const { return finals_; }
  /// Live: the game's scoreboard (innings, outs, runners, runs) as told, the ball in the air
  /// not yet on it; none in batting practice.
  const LiveInning::Board* board() const {
    if (!game_) return nullptr;
    return told_ ? &game_->board() : &board_before_;
  }

 private:
  void apply(const Intent& in);
  void advance(double t);
  /// `pressed_ms`: the swing's timing as the key gave it in the player's time, which the call
  /// reports (s holds it within the physics' range, in pitch time); `beyond_m`: the bat's
  /// height past the undercut range s holds (miss_call). `by_pro`: B's swing.
  void swing(const SwingInput& s, double t, double pressed_ms, double beyond_m, bool by_pro);
  void next_pitch(double t);
  /// A fresh record: no swings, no count, no plate appearances, the next pitch on call.
  void start_record();
  /// The league's starter for the live game now on (games_ of them so far): his hand drawn as
  /// the league's starters throw.
  void new_league_pitcher();
  /// `note` in brackets after the call (once): a press answered while the call stands.
  /// A live game that has ended: its final stays until P opens the next.
  bool game_over() const;
  void note_beside_call(std::string_view note);
  /// Live: the pitch's result on the count, and the plate appearance's end when it comes.
  void count_pitch(PitchResult r);

  const Assets& assets_;
  double time_scale_ = kPitchTimeScale;
  double next_time_scale_ = kPitchTimeScale;
  std::vector<PitchType> types_;
  Rng rng_;
  BotBatter bot_;
  Stage stage_ = Stage::Ready;
  PitchCall call_;
  PitchFlight pitch_;
  PitchMovement movement_;
  double released_at_ = 0.0, batted_at_ = 0.0, swung_at_ = -1e9;
  double taken_at_ = -1e9;  ///< when the last pitch went by untouched
  int pitches_done_ = 0;
  double bat_height_ = 0.76;
  bool power_ = true, lefty_ = false;
  SwingRecord last_;
  ShotTrajectory played_;
  std::vector<double> carries_as_played_;
  std::vector<SwingRecord> swings_;
  std::string call_text_;
  /// A batted ball's outcome, shown once its flight is over (until then its launch); a
  /// miss's call, shown once the pitch reaches the plate.
  std::string outcome_text_;
  double miss_told_at_ = 0.0;  ///< when a miss's call is due (mode time)
  /// Whether the last swing's outcome has been called; the at-bats before it while not.
  bool told_ = true;
  AtBats at_bats_before_;
  /// B asked the pro to swing at this pitch: he does when it reaches his timing.
  bool bot_armed_ = false;
  /// Space was pressed in this pitch's windup (a swing at nothing): its call says so.
  bool swung_too_soon_ = false;
  SwingInput bot_plan_;
  bool timing_only_ = false;
  /// B in a live game: the pro bats as the game's hitters do (hitter.hpp: his read of the
  /// pitch, his take-or-swing, his errors against live pitching), not his batting-practice
  /// swing; one for each side of the plate, made at first use with the game's aim and its
  /// report of the league's pitcher (game_).
  std::optional<Hitter> live_pro_[2];
  bool pro_takes_ = false;  ///< the pro let this pitch go: its call is his
  bool live_ = false;
  std::uint64_t seed_ = 0;  ///< the session's: a live game's teams and throws draw from it
  std::optional<LiveInning> game_;  ///< live: the innings the at-bats make
  int games_ = 0;                   ///< live games finished this session
  int game_first_pa_ = 0;           ///< at_bats_.pa when the live game now on began
  std::vector<std::string> finals_;  ///< their final lines, in order (the report lists them)
  LiveInning::Board board_before_;
  Pitcher pitcher_;
  BotBatter reader_;  ///< the pro's eye that sets the bat's height when timing_only_
  Count count_, count_before_;
  AtBats at_bats_;
  /// The record A left (the other mode's), given back when A returns to it.
  struct Kept {
    std::vector<SwingRecord> swings;
    std::vector<double> carries;
    AtBats at_bats;
    Count count;
    std::optional<LiveInning> game;
    int games = 0;
    int game_first_pa = 0;
    void clear();
  };
  Kept kept_;
  /// `swings` with their carries as played, the first `told` of them called.
  static Figures figures_of(const std::vector<SwingRecord>& swings, const std::vector<double>& carries, std::size_t told);
  /// A between pitches: this record kept, the other given back (or a fresh one).
  void switch_record();
};

}  // namespace sweetspot
