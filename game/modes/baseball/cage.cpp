#include "game/modes/baseball/cage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "game/modes/baseball/figures.hpp"
#include "game/modes/replay.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {
/// How miss_call begins every miss; strike three swinging keeps the rest of its words.
constexpr std::string_view kSwingingStrike = "Swinging strike";
/// Said beside a missed pitch's call still to come, for a press that would call the next.
constexpr std::string_view kNextPitchAfterCall = "the next pitch once this one is called";
constexpr std::string_view kNewGameOnP = "the game is over: P for a new one";

// A miss's distance in a batter's units (the cage says feet, mph and inches): tenths under an
// inch, never "0.0 in"; whole inches past it.
std::string inches(double m) {
  const double in = m / 0.0254;
  char text[24];
  if (in < 0.95) std::snprintf(text, sizeof text, "%.1f in", std::max(0.1, std::round(10.0 * in) / 10.0));
  else std::snprintf(text, sizeof text, "%.0f in", in);
  return text;
}

}  // namespace

std::string miss_call(const SwingResult& r, double timing_ms, double beyond_m, bool height_read, bool advise) {
  // Why the bat missed: early or late, the ball past the end of the bat; or above or below it
  // where they crossed (off time the crossing moves: early over the ball, late under it).
  constexpr double kReach = 0.066;  // m, the bat's and the ball's radii together (95 %)
  const char* when = timing_ms >= 0 ? "late" : "early";
  char text[256];
  const double under = r.crossing_undercut + beyond_m, miss = std::abs(under) - kReach;
  // Past the end and off height too (the height he set the bat against the ball; a bat
  // through the zone crossed nowhere): the height said as well, so the next swing mends both.
  // With the height read for him (timing only) the height is not his to mend: not said.
  char height[48] = "";
  if (miss >= 0.01 && !height_read) std::snprintf(height, sizeof height, ", and %s %s it", inches(miss).c_str(), under > 0.0 ? "under" : "over");
  if (r.through)
    std::snprintf(text, sizeof text, "Swinging strike: %s by %.0f ms, the bat %s", when, std::abs(timing_ms),
                  timing_ms >= 0 ? "not around yet" : "already through the zone");
  else if (r.past_end)
    // The turned bat's end does not reach the ball's line, early or late, over a middle pitch
    // too: said as the hitter sees it, with what mends it.
    std::snprintf(text, sizeof text, "Swinging strike: %s by %.0f ms, %s: the ball went by past its end%s%s%s%s", when,
                  std::abs(timing_ms), timing_ms >= 0 ? "the bat had not come around" : "the bat had turned too far",
                  advise ? " (" : "", advise ? (timing_ms >= 0 ? "start the swing sooner" : "wait a touch longer") : "",
                  advise ? ")" : "", height);
  else if (miss > 0.0 && height_read)
    // His timing is what he controls; where the bat crossed follows from it and the pro's read
    // (early crosses over the ball, late under it): the height is said as the pro's.
    std::snprintf(text, sizeof text, "Swinging strike: %s by %.0f ms; at the height the pro read, the bat passed %s %s the ball",
                  when, std::abs(timing_ms), inches(miss).c_str(), under > 0.0 ? "under" : "over");
  else if (miss > 0.0)
    std::snprintf(text, sizeof text, "Swinging strike: the bat missed %s the ball by %s", under > 0.0 ? "under" : "over", inches(miss).c_str());
  else
    std::snprintf(text, sizeof text, "Swinging strike: %s by %.0f ms", when, std::abs(timing_ms));
  return text;
}

BattingCage::BattingCage(const Assets& assets, std::uint64_t seed, double time_scale)
    : assets_(assets),
      time_scale_(time_scale),
      next_time_scale_(time_scale),
      types_(load_pitch_types(assets)),
      rng_(seed),
      bot_(assets, batter_skill("pro"), 5),
      pitcher_(league_average_pitcher(types_), seed ^ 0x9E3779B97F4A7C15ULL),
      reader_(assets, batter_skill("pro"), seed ^ 0x5EED0F7EA0E5ULL) {
  if (!(time_scale >= 0.1 && time_scale <= 1.0))
    throw InputError("the cage's pitch time scale " + std::to_string(time_scale) + " is out of range (allowed: 0.1..1)");
  seed_ = seed;
  call_ = derby_pitch(types_, rng_);
}

void BattingCage::next_pitch(double t) {
  call_ = live_ ? pitcher_.next(count_, lefty_).call : derby_pitch(types_, rng_);
  pitch_ = throw_pitch(assets_, call_);
  movement_ = statcast_movement(assets_, pitch_);
  time_scale_ = next_time_scale_;
  released_at_ = t + kWindupTime / time_scale_;
  stage_ = Stage::Pitching;
  swung_too_soon_ = false;
  // A ball still in the air when the next pitch is called: its outcome is settled, and the
  // figures count it now rather than after the next swing.
  told_ = true;
  call_text_.clear();
  outcome_text_.clear();
  bot_armed_ = false;
  pro_takes_ = false;
  // A game over: the next pitch opens a fresh one (the session's figures go on).
  if (game_ && game_->board().final) {
    finals_.push_back(game_->board().final_line);
    game_first_pa_ = at_bats_.pa;
    game_.emplace(assets_, seed_ + static_cast<std::uint64_t>(++games_));
    new_league_pitcher();
    board_before_ = LiveInning::Board{};
    count_ = Count{};
  }
  // A new batter's first pitch: the game's next inning opens here after a third out.
  if (game_ && count_.balls == 0 && count_.strikes == 0) game_->next_batter();
}

void BattingCage::new_league_pitcher() {
  // Each game's starter throws with the hand the league's starters do (kLeftStarterShare).
  const std::uint64_t seed = seed_ + static_cast<std::uint64_t>(games_);
  const bool left = draws_left_handed(seed ^ 0x57A27E5C0FFEE33ULL, kLeftStarterShare);
  pitcher_ = Pitcher(league_average_pitcher(types_, left), seed ^ 0x9E3779B97F4A7C15ULL);
}

void BattingCage::start_record() {
  swings_.clear();
  pitches_done_ = 0;
  carries_as_played_.clear();
  last_ = SwingRecord{};
  call_text_.clear();
  outcome_text_.clear();
  count_ = Count{};
  at_bats_ = AtBats{};
  game_first_pa_ = 0;
  told_ = true;
  stage_ = Stage::Ready;
  bot_armed_ = false;
  // Live, the at-bats are a game from its first inning.
  if (live_) {
    game_.emplace(assets_, seed_);
    new_league_pitcher();
  } else {
    game_.reset();
  }
  board_before_ = LiveInning::Board{};
}

void BattingCage::count_pitch(PitchResult r) {
  const PlateEnd end = apply_pitch(count_, r);
  if (end == PlateEnd::None) {
    static const char* kWords[] = {"Ball", "Called strike", "Swinging strike", "Foul", "Foul tip", "In play", "Hit by pitch"};
    // The count after the pitch, said so: "Ball (3-2)" read as ball four at 3-2.
    const std::string count = "   (count now " + std::to_string(count_.balls) + "-" + std::to_string(count_.strikes) + ")";
    // A foul's or a miss's own words (call_text_) come first when the swing made some.
    call_text_ = ((r == PitchResult::Foul || r == PitchResult::SwingingStrike) && !call_text_.empty()
                      ? call_text_
                      : std::string(kWords[static_cast<int>(r)])) +
                 count;
    return;
  }
  ++at_bats_.pa;
  // The game's part: the runners, the outs, the runs (the plate appearance's last pitch, with
  // its swing for a ball in play).
  if (game_) {
    PitchRecord last;
    last.call = r;
    last.swung = r == PitchResult::InPlay || r == PitchResult::SwingingStrike || r == PitchResult::FoulTip;
    if (r == PitchResult::InPlay) last.result = last_.result;
    game_->end_plate_appearance(end == PlateEnd::Strikeout    ? "strikeout"
                                : end == PlateEnd::Walk       ? "walk"
                                : end == PlateEnd::HitByPitch ? "hit_by_pitch"
                                                              : to_string(last_.result.outcome),
                                last);
  }
  switch (end) {
    case PlateEnd::Strikeout:
      ++at_bats_.strikeouts;
      ++at_bats_.outs;
      // A swinging strike three keeps the miss's own words (early, late, over, under).
      if (r == PitchResult::SwingingStrike && call_text_.starts_with(kSwingingStrike))
        call_text_ = "Strikeout swinging" + call_text_.substr(kSwingingStrike.size());
      else
        call_text_ = r == PitchResult::CalledStrike ? "Strikeout looking"
                     : r == PitchResult::FoulTip    ? "Strikeout on a foul tip"
                                                    : "Strikeout swinging";
      break;
    case PlateEnd::Walk: ++at_bats_.walks; call_text_ = "Walk"; break;
    case PlateEnd::HitByPitch: ++at_bats_.hit_by_pitch; call_text_ = "Hit by pitch"; break;
    default: {
      const BattedOutcome o = last_.result.outcome;
      const bool hit = o == BattedOutcome::Single || o == BattedOutcome::Double || o == BattedOutcome::Triple ||
                       o == BattedOutcome::HomeRun;
      at_bats_.hits += hit;
      at_bats_.home_runs += o == BattedOutcome::HomeRun;
      at_bats_.outs += o == BattedOutcome::Out;
      break;  // the batted ball's words stay
    }
  }
  count_ = Count{};
}

double BattingCage::ball_radius() const { return assets_.equipment().ball("mlb").radius; }

void BattingCage::update(const Intents& intents, double now) {
  apply_in_time_order(intents, now, [this](double t) { advance(t); }, [this](const Intent& in) { apply(in); });
}

void BattingCage::advance(double t) {
  if (bot_armed_ && stage_ == Stage::Pitching) {
    // His bat meets the pitch at his timing: at that instant of mode time, whatever the
    // frame rate.
    const double contact = released_at_ + std::max(0.0, pitch_.flight_time + 1e-3 * bot_plan_.timing_ms) / time_scale_;
    if (t >= contact) swing(bot_plan_, contact, bot_plan_.timing_ms / time_scale_, 0.0, true);
  }
  if (stage_ == Stage::Pitching && pitch_clock(t) > pitch_.flight_time + kTakenAfter) {
    last_ = SwingRecord{};
    last_.call = call_;
    last_.pitch = pitch_;
    last_.swung = false;
    const double r = assets_.equipment().ball("mlb").radius;
    const bool strike = StrikeZone::contains(pitch_.plate, r);
    call_text_ = strike ? "Called strike" : "Ball";
    stage_ = Stage::Called;
    taken_at_ = t;
    ++pitches_done_;
    if (live_)
      count_pitch(hits_batter(pitch_.plate, lefty_, r) ? PitchResult::HitByPitch
                  : strike                              ? PitchResult::CalledStrike
                                                        : PitchResult::Ball);
    // His Space in the windup swung at nothing: said beside the call it became.
    if (swung_too_soon_) call_text_ += "   (your swing came too soon: before the pitch)";
    if (pro_takes_) call_text_ = "The pro takes: " + call_text_;
  }
  if (stage_ == Stage::Called && !told_ && t >= miss_told_at_) {
    call_text_ = outcome_text_;
    told_ = true;
  }
  if (stage_ == Stage::Batted) {
    // The call comes when the play is made: a fielder has the ball (a catch, a hit fielded
    // off the wall) or a home run lands; the ball may roll on in the corner for seconds more.
    const FieldingPlay& play = last_.result.play;
    double call_at = duration(played_);
    if (play.fielder >= 0 && play.fielded_time > 0.0) call_at = std::min(call_at, play.fielded_time);
    else if (last_.result.outcome == BattedOutcome::HomeRun) call_at = std::min(call_at, played_.summary.hang_time_s);
    if (t - batted_at_ >= call_at) {
      if (!outcome_text_.empty()) call_text_ = outcome_text_;
      told_ = true;
    }
    if (t - batted_at_ >= duration(played_)) stage_ = Stage::Called;
  }
}

void BattingCage::swing(const SwingInput& s, double t, double pressed_ms, double beyond_m, bool by_pro) {
  bot_armed_ = false;
  swung_at_ = t;
  last_ = SwingRecord{};
  last_.call = call_;
  last_.pitch = pitch_;
  last_.timing_ms = s.timing_ms;
  last_.undercut = s.undercut;
  last_.by_pro = by_pro;
  last_.result = swing_at(assets_, pitch_, s, batter_skill("pro").bat_speed, kBat);
  ++pitches_done_;
  played_ = last_.result.foul_tip ? into_the_mitt(last_.result.shot.trajectory)
                                   : as_played(last_.result.shot.trajectory, last_.result.play);
  // A foul tip is its own call (into the catcher's mitt: a strike, the third one too).
  last_.call_text = last_.result.foul_tip ? "foul_tip" : to_string(last_.result.outcome);
  swings_.push_back(last_);
  carries_as_played_.push_back(played_.summary.carry_m);
  at_bats_before_ = at_bats_;
  count_before_ = count_;
  if (game_) board_before_ = game_->board();
  told_ = !last_.result.contact;
  char text[256];
  // Where on the bat, and, when it went straight up or into the dirt, which side of the
  // ball's centre; and when he met it, as a miss's call says it, in his own time: early pulls
  // the ball, late sends it the other way. What to change next swing, said while the ball
  // flies and kept in its call once it is down (a foul most of all: it is the swing to mend).
  // Within half a 60 Hz frame (8 ms) no key press is finer: on time.
  std::string how_met;
  if (last_.result.contact) {
    const double la = rad_to_deg(last_.result.shot.launch.vertical_angle);
    const char* side = la > 50.0 ? ", under the ball" : la < -20.0 ? ", on top of the ball" : "";  // Statcast's pop-ups leave above 50 deg
    constexpr double kOnTimeMs = 8.0;
    char when[32] = ", on time";
    if (std::abs(pressed_ms) >= kOnTimeMs)
      std::snprintf(when, sizeof when, ", %.0f ms %s", std::abs(pressed_ms), pressed_ms > 0.0 ? "late" : "early");
    how_met = std::string(contact_spot(assets_.equipment().bat(kBat), last_.result.impact_from_tip)) + side + when;
    const std::string words = last_.result.outcome == BattedOutcome::Foul ? (last_.result.foul_tip ? "Foul tip" : "Foul ball")
                                                                           : last_.result.play.description;
    // How far: to the glove on a catch, where it came down otherwise (Statcast's hit
    // distance, as the field's label); a ground ball's first hop a few feet out says nothing
    // of it, so a fielded one says where he picked it up (the field's rest label).
    const FieldingPlay& play = last_.result.play;
    const double launch = last_.result.shot.launch.vertical_angle;
    const bool grounder = batted_ball_type(launch) == BattedBallType::GroundBall && !play.caught;
    char how_far[48];
    // A foul back to the screen behind the plate is dead there (stop_at_backstop): every such
    // ball would read the backstop's 60 ft, which says nothing of it.
    const Vec3 end = played_.samples.empty() ? Vec3::Zero().eval() : played_.samples.back().position;
    const bool to_backstop = last_.result.outcome == BattedOutcome::Foul && !play.caught && end.x() < 0.0 &&
                             std::hypot(end.x(), end.z()) >= kFoulGround - 0.01;
    if (to_backstop)
      std::snprintf(how_far, sizeof how_far, "back to the screen");
    else if (grounder && play.fielder >= 0 && !play.foul)
      std::snprintf(how_far, sizeof how_far, "fielded at %.0f ft", m_to_ft(played_.summary.total_m));
    else if (grounder)  // a foul grounder: where it was touched or stopped, as the field's label
      std::snprintf(how_far, sizeof how_far, "%.0f ft", m_to_ft(played_.summary.total_m));
    else std::snprintf(how_far, sizeof how_far, "%.0f ft", m_to_ft(played_.summary.carry_m));
    std::snprintf(text, sizeof text, "%s  %.0f mph, %.0f deg, %s; %s", words.c_str(), mps_to_mph(last_.result.shot.launch.ball_speed),
                  la, how_far, how_met.c_str());
    call_text_ = text;
    batted_at_ = t;
    stage_ = Stage::Batted;
  } else {
    call_text_ = miss_call(last_.result, pressed_ms, beyond_m, timing_only_ && !by_pro, !by_pro);
    stage_ = Stage::Called;
  }
  if (live_) {
    const BattedOutcome o = last_.result.outcome;
    count_pitch(!last_.result.contact     ? PitchResult::SwingingStrike
                : o == BattedOutcome::Foul ? (last_.result.foul_tip ? PitchResult::FoulTip : PitchResult::Foul)
                                           : PitchResult::InPlay);
    // The call as the game scored the play once its runners changed it (a ground out that
    // became a double play), so the banner, the panel and the log say one thing.
    // Only for a ball put in play: that play ended the plate appearance and set scored_as; a
    // foul later ("Foul ball" starts with "Foul") is no rescored play of an earlier one.
    const std::string& fielded = last_.result.play.description;
    const bool in_play = last_.result.contact && o != BattedOutcome::Foul;
    if (in_play && stage_ == Stage::Batted && game_ && !game_->board().scored_as.empty() && call_text_.starts_with(fielded))
      call_text_ = game_->board().scored_as + call_text_.substr(fielded.size());
  }
  if (by_pro) call_text_ = "The pro: " + call_text_;  // his swing, not the player's
  if (stage_ == Stage::Batted) {
    // While the ball flies the call is its launch, as a broadcast shows it; the outcome when it lands.
    outcome_text_ = call_text_;
    // Exit velocity to a tenth, as Statcast gives it: 94.6 mph rounded to "95" read as hard-hit
    // (95 mph and up) where the session's figures count it as not.
    const double la = rad_to_deg(last_.result.shot.launch.vertical_angle);
    std::snprintf(text, sizeof text, "%s%.1f mph off the bat, %.0f deg, %s", by_pro ? "The pro: " : "",
                  mps_to_mph(last_.result.shot.launch.ball_speed), la, how_met.c_str());
    call_text_ = text;
  }
  // What the call will say once the ball is down (a batted ball's outcome, counted), or says now.
  swings_.back().said = stage_ == Stage::Batted ? outcome_text_ : call_text_;
  // A miss before the ball reaches the plate: the strike (a strikeout's, a walk-off's
  // count) is called when it gets there; until then the swing is all there is to say.
  const double arrives = released_at_ + pitch_.flight_time / time_scale_;
  if (!last_.result.contact && t < arrives) {
    outcome_text_ = call_text_;
    call_text_ = by_pro ? "The pro swings and misses" : "Swing and a miss";
    told_ = false;
    miss_told_at_ = arrives;
  }
}

bool BattingCage::game_over() const { return live_ && game_ && game_->board().final; }

void BattingCage::note_beside_call(std::string_view note) {
  const std::string said = "   (" + std::string(note) + ")";
  if (!call_text_.ends_with(said)) call_text_ += said;
}

int BattingCage::misses_in_a_row() const {
  int n = 0;
  for (auto it = swings_.rbegin(); it != swings_.rend(); ++it) {
    if (it->by_pro) continue;
    if (it->result.contact) break;
    ++n;
  }
  return n;
}

BattingCage::Figures BattingCage::figures() const { return figures_of(swings_, carries_as_played_, swings_told()); }

std::optional<BattingCage::Figures> BattingCage::other_figures() const {
  if (kept_.swings.empty()) return std::nullopt;
  return figures_of(kept_.swings, kept_.carries, kept_.swings.size());
}

void BattingCage::Kept::clear() {
  swings.clear();
  carries.clear();
  at_bats = AtBats{};
  count = Count{};
  game.reset();
  games = 0;
  game_first_pa = 0;
}

void BattingCage::switch_record() {
  Kept leaving{std::move(swings_), std::move(carries_as_played_), at_bats_, count_, std::nullopt, games_, game_first_pa_};
  if (game_) leaving.game.emplace(std::move(*game_));
  live_ = !live_;
  start_record();
  swings_ = std::move(kept_.swings);
  carries_as_played_ = std::move(kept_.carries);
  at_bats_ = kept_.at_bats;
  count_ = kept_.count;
  games_ = kept_.games;
  game_first_pa_ = kept_.game_first_pa;
  if (kept_.game) {
    game_.reset();
    game_.emplace(std::move(*kept_.game));
  }
  kept_.swings = std::move(leaving.swings);
  kept_.carries = std::move(leaving.carries);
  kept_.at_bats = leaving.at_bats;
  kept_.count = leaving.count;
  kept_.games = leaving.games;
  kept_.game_first_pa = leaving.game_first_pa;
  kept_.game.reset();
  if (leaving.game) kept_.game.emplace(std::move(*leaving.game));
  if (live_) new_league_pitcher();  // the game gone back to keeps its starter's hand
}

BattingCage::Figures BattingCage::figures_of(const std::vector<SwingRecord>& swings, const std::vector<double>& carries, std::size_t told) {
  Figures f;
  for (std::size_t i = 0; i < swings.size(); ++i) {
    const SwingRecord& s = swings[i];
    if (s.by_pro) {
      ++f.by_pro;
      continue;
    }
    ++f.swings;
    if (!s.result.contact) continue;
    ++f.contact;
    if (i >= told || s.result.outcome == BattedOutcome::Foul) continue;
    ++f.fair;
    f.mean_exit_speed += s.result.shot.launch.ball_speed;
    f.mean_launch += s.result.shot.launch.vertical_angle;
    f.hard_hit += s.result.hard_hit;
    f.home_runs += s.result.outcome == BattedOutcome::HomeRun;
    f.longest = std::max(f.longest, carries[i]);
  }
  if (f.fair > 0) {
    f.mean_exit_speed /= f.fair;
    f.mean_launch /= f.fair;
  }
  return f;
}

std::string BattingCage::pace_name(double time_scale) {
  // A hitter's own window at game speed is about +-14 ms (the class comment): in the player's
  // time it grows as 1 / scale.
  constexpr double kWindowMs = 14.0;
  const char* name = time_scale == kEasyPitchTimeScale ? "easy, "
                     : time_scale == kProPitchTimeScale ? "pro, "
                     : time_scale == kPitchTimeScale    ? "standard, "
                                                        : "";  // a --difficulty of its own
  char text[96];
  if (time_scale >= 1.0) std::snprintf(text, sizeof text, "%sreal speed (hit within about %.0f ms)", name, kWindowMs);
  else
    std::snprintf(text, sizeof text, "%s%.0f %% of real speed (hit within about %.0f ms)", name, 100.0 * time_scale,
                  kWindowMs / time_scale);
  return text;
}

void BattingCage::apply(const Intent& in) {
  const double t = in.time;
  switch (in.kind) {
    case IntentKind::BatUp:
    case IntentKind::BatDown:
      bat_height_ += in.kind == IntentKind::BatUp ? kBatStep : -kBatStep;
      bat_height_ = std::clamp(bat_height_, kZoneLow - 0.3, kZoneHigh + 0.3);
      break;
    case IntentKind::TogglePower:
      // Said as the pace is (below), once nothing else is being called: the panel's one word
      // changing is easy to miss, and the trade is the point of the key.
      power_ = !power_;
      if (stage_ == Stage::Ready || (stage_ == Stage::Called && told_))
        call_text_ = power_ ? "Power swing: full bat speed" : "Contact swing: 92 % of the power swing's bat speed";
      break;
    case IntentKind::ToggleSide:
      lefty_ = !lefty_;
      if (stage_ == Stage::Ready || (stage_ == Stage::Called && told_))
        call_text_ = lefty_ ? "Batting left-handed" : "Batting right-handed";
      break;
    case IntentKind::ToggleTiming: timing_only_ = !timing_only_; break;
    case IntentKind::TogglePace: {
      // The next pitch's pace (one thrown, or a ball still in the air, keeps the clock it
      // runs on), and what it gives the swing's window in the player's own time; said once
      // nothing else is being called.
      next_time_scale_ = next_time_scale_ == kPitchTimeScale       ? kEasyPitchTimeScale
                         : next_time_scale_ == kEasyPitchTimeScale ? kProPitchTimeScale
                                                                   : kPitchTimeScale;
      if (stage_ == Stage::Ready || (stage_ == Stage::Called && told_)) call_text_ = std::string("Pitch pace: ") + pace_name(next_time_scale_);
      break;
    }
    case IntentKind::ToggleLive:
      // Between pitches: batting practice, or a live game from its first inning at 0-0.
      if (stage_ == Stage::Pitching) break;
      // A ball in play still in the air is called first (the switch would clear its record
      // and its call unseen); the press is answered, not dropped.
      if (!told_) {
        note_beside_call("A: once this ball is called");
        break;
      }
      // Each keeps its own record: practice swings are not the at-bats' (and the other's
      // last pitch is not this one's); the one left is kept for the way back.
      switch_record();
      call_text_ = live_ ? (at_bats_.pa > 0 ? "Back to the live game" : "Live game: you bat for the visitors against the league, nine innings")
                         : (swings_.empty() ? "Batting practice" : "Back to batting practice");
      break;
    case IntentKind::Restart:
      // A fresh session: both records cleared, the next pitch on call.
      kept_.clear();
      start_record();
      break;
    case IntentKind::Pitch:
    case IntentKind::Swing:
      if (in.kind == IntentKind::Swing && stage_ == Stage::Called && t - taken_at_ < kLateSwing) {
        // A swing pressed just after the pitch went by: too late, and not a call for the next;
        // said beside the call, so the press is not lost without a word.
        // How late in the player's own time (the pitch plays slowed), as a swing's call says it:
        // past the swing's reach the ball is in the catcher's glove, so the pitch was taken.
        if (call_text_.find("too late") == std::string::npos) {
          const double late_ms = 1000.0 * (t - released_at_ - pitch_.flight_time / time_scale_);
          char late[96];
          std::snprintf(late, sizeof late, "   (your swing came %.0f ms too late: the pitch was by)", late_ms);
          call_text_ += late;
        }
        break;
      }
      if (stage_ == Stage::Called && !told_) {
        // A second press while the pitch he missed is still on its way: one swing a pitch,
        // and the next pitch only once this one is called.
        note_beside_call(in.kind == IntentKind::Swing ? "one swing a pitch" : kNextPitchAfterCall);
      } else if (stage_ != Stage::Pitching && in.kind == IntentKind::Swing && game_over()) {
        // The final stays until P, as the panel says: the Space he swung with all game does
        // not throw it away.
        note_beside_call(kNewGameOnP);
      } else if (stage_ != Stage::Pitching) {
        // Space between pitches calls for the next one, as P does.
        next_pitch(t);
      } else if (in.kind == IntentKind::Swing && pitch_clock(t) < 0.0) {
        // He holds until the ball is on its way: a key pressed during the windup swings at
        // nothing, and says so.
        call_text_ = "Too soon: swing once the pitcher lets the ball go";
        swung_too_soon_ = true;
      } else if (in.kind == IntentKind::Swing) {
        SwingInput s;
        // The swing's timing as pressed; the physics takes it within its range (past ±150 ms
        // the bat is round or not yet started either way), the call says it as it was, in the
        // player's own time (the pitch plays slowed: 100 ms of pitch time took him 200).
        const double timing_ms = 1000.0 * (pitch_clock(t) - pitch_.flight_time);
        s.timing_ms = std::clamp(timing_ms, SwingInput::kTiming.min, SwingInput::kTiming.max);
        // Timing only: the pro's read of the pitch's height (a fly ball's in practice, a line
        // drive's in a game), with his errors; else where the player set the bat.
        const double undercut = timing_only_ ? reader_.plan(pitch_, !live_, lefty_).undercut : pitch_.plate.y() - bat_height_;
        s.undercut = std::clamp(undercut, SwingInput::kUndercut.min, SwingInput::kUndercut.max);
        s.power = power_;
        s.left_handed = lefty_;
        // His body meets the pitch where it is pitched (contact_lead_for); the key's timing is
        // against that moment.
        s.contact_lead = contact_lead_for(inside_by(pitch_.plate, lefty_));
        swing(s, t, timing_ms / time_scale_, undercut - s.undercut, false);
      }
      break;
    case IntentKind::BotSwings:
      // Between pitches B calls for one; the pro swings at it when it reaches him (advance),
      // unless it is already past him.
      if (bot_armed_ || (pro_takes_ && stage_ == Stage::Pitching)) break;  // he has this pitch already
      if (stage_ == Stage::Called && !told_) {
        note_beside_call(kNextPitchAfterCall);  // the missed pitch is called first; the press is answered
        break;
      }
      if (stage_ != Stage::Pitching && game_over()) {
        note_beside_call(kNewGameOnP);  // the final stays until P
        break;
      }
      if (stage_ != Stage::Pitching) next_pitch(t);
      else if (pitch_clock(t) > pitch_.flight_time) break;
      if (live_) {
        // Against live pitching he reads the pitch and may take it, as a game's hitter does.
        std::optional<Hitter>& h = live_pro_[lefty_ ? 1 : 0];
        if (!h) h.emplace(batter_skill("pro"), lefty_, seed_ * 31 + (lefty_ ? 2 : 1), game_->batting().lineup.front().aim_inside());
        const PitchRead read = h->read(pitch_, call_.type.type, game_->report(), count_);
        if (!h->swings(read, count_)) {
          pro_takes_ = true;
          break;
        }
        bot_plan_ = h->swing(read, count_);
      } else {
        bot_plan_ = bot_.plan(pitch_, true, lefty_);
      }
      bot_armed_ = true;
      break;
    default: break;
  }
}

}  // namespace sweetspot
