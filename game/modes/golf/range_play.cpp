#include "game/modes/golf/range_play.hpp"

#include <cmath>
#include <cstdio>

#include "game/modes/golf/golfer.hpp"
#include "game/modes/replay.hpp"
#include "physics/units.hpp"

namespace sweetspot {

RangePlay::RangePlay(const Assets& assets, const GolferSkill& skill, int shots_per_club, MeterDifficulty difficulty,
                     std::uint64_t seed)
    : assets_(assets), skill_(skill), per_club_(shots_per_club), difficulty_(difficulty), session_(assets, skill),
      bot_(assets, skill, seed) {}

const std::string& RangePlay::club() const { return golf_bag()[club_]; }

std::vector<Vec3> RangePlay::targets(bool imperial) {
  // m left (-) or right (+) of the line: 4-7 deg apart as the tee's camera sees them, clear of
  // the stripes' numbers just left of the line; the farthest on it.
  constexpr double kOff[] = {-8.0, 10.0, -14.0, 14.0, 0.0};
  std::vector<Vec3> out;
  const double step = imperial ? yd_to_m(50.0) : 50.0;  // m
  for (int k = 0; k < 5; ++k) out.emplace_back(step * (k + 1), 0.0, kOff[k]);
  return out;
}

int RangePlay::shots_with_club() const {
  int n = 0;
  for (const RangeShot& s : session_.shots()) n += s.club == club();
  return n;
}

void RangePlay::update(const Intents& intents, double now) {
  apply_in_time_order(intents, now, [this](double t) { advance(t); }, [this](const Intent& in) { apply(in); });
}

void RangePlay::advance(double t) {
  if (stage_ == Stage::Swinging && meter_) {
    meter_->update(t);
    if (meter_->phase() == MeterClock::Phase::Abandoned) {
      meter_.reset();
      stage_ = Stage::Aiming;
      message_ = "Swing abandoned, nothing hit";
    } else if (const auto m = meter_->result()) {
      last_click_ = *meter_;
      strike(*m, t, false);
    }
  }
  if (stage_ == Stage::Flying && t - struck_at_ >= duration(last_.trajectory)) stage_ = Stage::Aiming;
}

void RangePlay::strike(const MeterInput& m, double t, bool caddie) {
  const std::string club = this->club();
  session_.hit(club, m, &last_);
  struck_at_ = t;
  meter_.reset();
  stage_ = Stage::Flying;
  // The ball just hit, and how it was swung: the meter's own click error (as the golf
  // round's message gives it), or the skill's drawn one for B.
  const double late = caddie || !last_click_ ? m.accuracy_ms : last_click_->click_error_ms();
  char msg[200];
  std::snprintf(msg, sizeof msg, "Last ball: %s, shot %d of %d, power %.0f\u00a0%%, %s%s", club_name(club).c_str(), shots_with_club(), per_club_,
                100.0 * m.power, timing_words(late).c_str(), caddie ? " (your\u00a0skill's\u00a0swing)" : "");
  message_ = msg;
  // A club's shots done: the next club down the bag comes up.
  if (shots_with_club() >= per_club_ && club_ + 2 < golf_bag().size()) ++club_;
}

void RangePlay::apply(const Intent& in) {
  const double t = in.time;
  switch (in.kind) {
    case IntentKind::Restart:
      session_ = RangeSession(assets_, skill_);
      club_ = 0;
      stage_ = Stage::Aiming;
      // The last ball goes with the session: nothing struck yet, nothing to show.
      last_ = ShotResult{};
      struck_at_ = 0.0;
      meter_.reset();
      message_ = "A new session";
      return;
    case IntentKind::Cancel:
      if (stage_ == Stage::Swinging) {
        meter_.reset();
        stage_ = Stage::Aiming;
        message_ = "Swing cancelled";
      }
      return;
    case IntentKind::Continue:
      if (stage_ == Stage::Flying) stage_ = Stage::Aiming;
      return;
    default: break;
  }
  if (stage_ == Stage::Aiming) {
    if (in.kind == IntentKind::ClubUp && club_ > 0) --club_;
    if (in.kind == IntentKind::ClubDown && club_ + 2 < golf_bag().size()) ++club_;  // the putter stays in the bag
    if (in.kind == IntentKind::CaddiePlays) strike(bot_.full_swing(), t, true);
    if (in.kind == IntentKind::Swing) {
      meter_.emplace(next_meter());
      meter_->click(t);
      stage_ = Stage::Swinging;
    }
  } else if (stage_ == Stage::Swinging && in.kind == IntentKind::Swing && meter_) {
    meter_->click(t);
    if (const auto m = meter_->result()) {
      last_click_ = *meter_;
      strike(*m, t, false);
    }
  } else if (stage_ == Stage::Flying && in.kind == IntentKind::Swing) {
    stage_ = Stage::Aiming;
  } else if (stage_ == Stage::Flying &&
             (in.kind == IntentKind::ClubUp || in.kind == IntentKind::ClubDown || in.kind == IntentKind::CaddiePlays)) {
    // Choosing the next club, or asking for the next swing with your errors (B), ends the
    // last shot's view, as Enter and Space do, and goes on.
    stage_ = Stage::Aiming;
    apply(in);
  }
}

}  // namespace sweetspot
