#include "game/modes/golf/golf_play.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "game/modes/replay.hpp"

namespace sweetspot {

const char* to_string(GolfPlay::Stage s) {
  switch (s) {
    case GolfPlay::Stage::Aiming: return "aiming";
    case GolfPlay::Stage::Swinging: return "swinging";
    case GolfPlay::Stage::Flying: return "flying";
    case GolfPlay::Stage::HoleOver: return "hole over";
    case GolfPlay::Stage::RoundOver: return "round over";
  }
  return "?";
}

namespace {

std::vector<int> bot_card(const Assets& assets, const Course& course, const GolferSkill& skill, std::uint64_t seed) {
  GolfRound round(assets, course, skill);
  GolfBot bot(assets, skill, seed);
  while (!round.finished()) round.play(bot.plan(round));
  std::vector<int> strokes;
  for (const HoleCard& c : round.card()) strokes.push_back(c.strokes);
  return strokes;
}

std::size_t bag_index(const std::string& club) {
  const auto& bag = golf_bag();
  return static_cast<std::size_t>(std::find(bag.begin(), bag.end(), club) - bag.begin());
}

}  // namespace

GolfPlay::GolfPlay(const Assets& assets, Course course, const GolferSkill& skill, std::uint64_t opponent_seed)
    : assets_(assets),
      course_(std::move(course)),
      skill_(skill),
      round_(assets, course_, skill),
      caddie_(assets, skill, 1),
      opponent_(bot_card(assets, course_, skill, opponent_seed)),
      played_(course_.holes.size()) {
  choose_club();
}

const std::string& GolfPlay::club() const { return golf_bag()[club_]; }

Vec3 GolfPlay::ball_centre() const {
  const bool teed = round_.teed() && round_.lie() == "tee";
  const double tee = teed ? assets_.equipment().club_info_of(club()).tee_height : 0.0;
  return round_.ball() + Vec3(0.0, assets_.equipment().ball("tour").radius + tee, 0.0);
}

Vec3 GolfPlay::aim_direction() const {
  const double a = round_.line_to_pin() + aim_;
  return Vec3(std::cos(a), 0.0, std::sin(a));
}

void GolfPlay::choose_club() {
  if (round_.finished()) return;
  club_ = bag_index(round_.lie() == "green" ? std::string("putter") : caddie_.suggest(round_.to_pin(), round_.teed()));
  aim_ = 0.0;
}

void GolfPlay::update(const Intents& intents, double now) {
  apply_in_time_order(intents, now, [this](double t) { advance(t); }, [this](const Intent& in) { apply(in); });
}

void GolfPlay::advance(double t) {
  if (stage_ == Stage::Swinging && meter_) {
    meter_->update(t);
    if (const auto m = meter_->result()) {
      last_meter_ = *m;
      strike({club(), aim_, *m}, t);
    }
  }
  if (stage_ == Stage::Flying && t - struck_at_ >= duration(last_.trajectory)) land(struck_at_ + duration(last_.trajectory));
}

void GolfPlay::land(double t) {
  landed_at_ = t;
  if (round_.finished()) {
    stage_ = Stage::RoundOver;
  } else if (round_.card().back().shots.empty()) {
    stage_ = Stage::HoleOver;  // the stroke ended the hole; the next one has not started
  } else {
    stage_ = Stage::Aiming;
    choose_club();
  }
}

void GolfPlay::strike(const StrokeInput& s, double t) {
  const std::size_t hole = round_.hole_index();
  const StrokeRecord& rec = round_.play(s, &last_);
  played_[hole].push_back(s);
  struck_at_ = t;
  meter_.reset();
  stage_ = Stage::Flying;
  char msg[160];
  if (last_meter_ && s.club == "putter") {
    std::snprintf(msg, sizeof msg, "putter: power %.0f %% -> %s", 100.0 * last_meter_->power, to_string(rec.end));
  } else if (last_meter_) {
    const double late = last_meter_->accuracy_ms;
    std::snprintf(msg, sizeof msg, "%s: power %.0f %%, %s %.0f ms -> %s%s", s.club.c_str(), 100.0 * last_meter_->power,
                  late >= 0 ? "late" : "early", std::abs(late), to_string(rec.end), rec.penalty ? " (penalty stroke)" : "");
  } else {
    std::snprintf(msg, sizeof msg, "caddie plays the %s -> %s%s", s.club.c_str(), to_string(rec.end),
                  rec.penalty ? " (penalty stroke)" : "");
  }
  message_ = msg;
}

void GolfPlay::apply(const Intent& in) {
  const double t = in.time;
  if (in.kind == IntentKind::Restart) {
    if (stage_ == Stage::RoundOver) new_round();
    else restart_hole();
    return;
  }
  const bool putting = club() == "putter";
  const int steps = in.param > 0 ? in.param : 1;
  switch (stage_) {
    case Stage::Aiming:
      switch (in.kind) {
        case IntentKind::AimLeft:
        case IntentKind::AimRight: {
          const double step = (putting ? kPuttAimStep : kAimStep) * steps;
          aim_ += in.kind == IntentKind::AimLeft ? -step : step;
          aim_ = std::clamp(aim_, StrokeInput::kAim.min, StrokeInput::kAim.max);
          break;
        }
        case IntentKind::ClubUp:
          if (club_ > 0) --club_;
          break;
        case IntentKind::ClubDown:
          if (club_ + 1 < golf_bag().size()) ++club_;
          break;
        case IntentKind::CaddieClub: choose_club(); break;
        case IntentKind::Swing: {
          const double length = assets_.equipment().club(club()).length;
          meter_.emplace(MeterClock::tempo_for(length, putting), putting);
          meter_->click(t);
          stage_ = Stage::Swinging;
          message_.clear();
          break;
        }
        case IntentKind::CaddiePlays: {
          const StrokeInput s = caddie_.plan(round_);
          club_ = bag_index(s.club);
          aim_ = s.aim;
          last_meter_.reset();
          strike(s, t);
          break;
        }
        default: break;
      }
      break;
    case Stage::Swinging:
      if (in.kind == IntentKind::Swing && meter_) {
        meter_->click(t);
        if (const auto m = meter_->result()) {
          last_meter_ = *m;
          strike({club(), aim_, *m}, t);
        }
      } else if (in.kind == IntentKind::Cancel) {
        meter_.reset();
        stage_ = Stage::Aiming;
        ++cancelled_;
        message_ = "swing cancelled: no stroke counted";
      }
      break;
    case Stage::Flying:
      if (in.kind == IntentKind::Continue || in.kind == IntentKind::Swing) {
        struck_at_ = t - duration(last_.trajectory);  // the flight's end, now
        land(t);
      }
      break;
    case Stage::HoleOver:
      if ((in.kind == IntentKind::Continue || in.kind == IntentKind::Swing) && t - landed_at_ >= kCardGrace) {
        stage_ = Stage::Aiming;
        choose_club();
        message_.clear();
      }
      break;
    case Stage::RoundOver:
      if (in.kind == IntentKind::Continue && t - landed_at_ >= kCardGrace) new_round();
      break;
  }
}

void GolfPlay::new_round() {
  round_ = GolfRound(assets_, course_, skill_);
  for (auto& h : played_) h.clear();
  stage_ = Stage::Aiming;
  meter_.reset();
  last_meter_.reset();
  message_.clear();
  choose_club();
}

void GolfPlay::restart_hole() {
  // The round is deterministic: the holes before, replayed from their strokes, leave it
  // exactly where it was when this hole began.
  const std::size_t hole = round_.hole_index();
  round_ = GolfRound(assets_, course_, skill_);
  for (std::size_t h = 0; h < hole; ++h)
    for (const StrokeInput& s : played_[h]) round_.play(s);
  played_[hole].clear();
  stage_ = Stage::Aiming;
  meter_.reset();
  message_ = "hole " + std::to_string(round_.hole().number) + " restarted";
  choose_club();
}

}  // namespace sweetspot
