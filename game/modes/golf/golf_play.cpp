#include "game/modes/golf/golf_play.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include "game/modes/replay.hpp"
#include "game/rules/golf_scoring.hpp"
#include "game/rules/run_shot.hpp"

namespace sweetspot {

const char* to_string(GolfPlay::Stage s) {
  switch (s) {
    case GolfPlay::Stage::Flyover: return "flyover";
    case GolfPlay::Stage::Aiming: return "aiming";
    case GolfPlay::Stage::Swinging: return "swinging";
    case GolfPlay::Stage::Flying: return "flying";
    case GolfPlay::Stage::HoleOver: return "hole over";
    case GolfPlay::Stage::RoundOver: return "round over";
  }
  return "?";
}

GolfSetup default_golf_setup(const GolferSkill& skill, std::uint64_t seed) {
  GolfSetup s;
  s.players = {{"You", skill.name, true, 0, {}}, {skill.name + " bot", skill.name, false, 0, {}}};
  s.options.seed = seed;
  return s;
}

namespace {

std::size_t bag_index(const std::string& club) {
  const auto& bag = golf_bag();
  return static_cast<std::size_t>(std::find(bag.begin(), bag.end(), club) - bag.begin());
}

GolfSetup without_flyover(GolfSetup s) {
  s.flyover = false;
  return s;
}

// Player words for where a stroke ended.
const char* end_words(StrokeEnd e) {
  switch (e) {
    case StrokeEnd::Rest: return "";
    case StrokeEnd::Holed: return "In the hole!";
    case StrokeEnd::Water: return "In the water: one penalty stroke, dropped behind it, back toward where it was played from (Rule 17.1d)";
    case StrokeEnd::OutOfBounds: return "Out of bounds: stroke and distance";
  }
  return "";
}

// A holed stroke in a player's words, with what it scored: a putt "In the hole! Birdie", one
// from off the green where it came from ("In the hole from the fairway! Eagle"), an ace so.
std::string holed_words(const StrokeRecord& rec, const HoleCard& card) {
  std::string score = card.strokes == 1 ? std::string("a hole in one") : score_name(card.strokes, card.par);
  if (score.empty()) score = "par";
  score[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(score[0])));
  return (rec.lie == "green" || rec.lie.empty() ? std::string("In the hole! ") : "In the hole from the " + rec.lie + "! ") + score;
}

}  // namespace

GolfPlay::GolfPlay(const Assets& assets, Course course, GolfSetup setup)
    : assets_(assets),
      course_(std::move(course)),
      setup_(std::move(setup)),
      group_(assets, course_, setup_.players, setup_.options) {
  group_.replay(setup_.resume);
  restarts_ = setup_.resume_restarts;
  cancelled_ = setup_.resume_cancelled;
  begin_turn(0.0);
  if (group_.finished()) {
    stage_ = Stage::RoundOver;  // a saved round that was already over: its final card
    // ... over the green of its last hole, which the header names.
    round_hole_ = std::min(group_.hole_index(), course_.holes.size()) - 1;
  } else if (setup_.flyover && group_.events().size() <= group_.hole_first_event(group_.hole_index())) {
    // A round resumed in the middle of a hole goes on from the ball: its flyover was seen.
    stage_ = Stage::Flyover;
    flyover_at_ = 0.0;
  }
}

GolfPlay::GolfPlay(const Assets& assets, Course course, const GolferSkill& skill, std::uint64_t seed)
    : GolfPlay(assets, std::move(course), without_flyover(default_golf_setup(skill, seed))) {}

const std::string& GolfPlay::club() const { return golf_bag()[club_]; }

bool GolfPlay::human_turn() const { return !group_.finished() && !group_.bot_turn(); }

Vec3 GolfPlay::ball_centre() const {
  const GolfRound& r = round();
  if (r.finished()) return r.course().holes.back().pin;
  const bool teed = r.teed() && r.lie() == "tee";
  const double tee = teed ? assets_.equipment().club_info_of(club()).tee_height : 0.0;
  return r.ball() + Vec3(0.0, assets_.equipment().ball("tour").radius + tee, 0.0);
}

Vec3 GolfPlay::aim_direction() const {
  if (round().finished()) return Vec3::UnitX();
  const double a = round().line_to_pin() + aim_;
  return Vec3(std::cos(a), 0.0, std::sin(a));
}

const std::optional<MeterClock>& GolfPlay::last_click() const {
  static const std::optional<MeterClock> none;
  const auto who = static_cast<std::size_t>(player_);
  return who < click_of_.size() ? click_of_[who] : none;
}

bool GolfPlay::last_click_here() const {
  const auto who = static_cast<std::size_t>(player_);
  return last_click() && who < click_hole_.size() && click_hole_[who] == group_.hole_index();
}

MeterClock GolfPlay::next_meter() const {
  // A putt the preview reaches: the marker slowed for a short one (putt_tempo); the caddie's
  // part swing with this club, slowed to its mark as well.
  const bool putting = club() == "putter";
  const double part = putting ? 1.0 : part_swing_power(club());
  const double tempo = putting && putt_plays_as_ > 0.0 ? MeterClock::putt_tempo(cup_mark_power())
                       : part < 1.0                    ? MeterClock::part_swing_tempo(part)
                                                       : MeterClock::tempo_for(putting);
  return MeterClock(tempo, putting, perfect_window_ms(setup_.difficulty));
}

const GolfPlay::OwnLast* GolfPlay::own_last(int player) const {
  const auto i = static_cast<std::size_t>(player);
  if (i >= own_last_.size() || !own_last_[i] || own_last_[i]->hole != group_.hole_index()) return nullptr;
  return &*own_last_[i];
}

double GolfPlay::flyover_progress(double now) const {
  if (stage_ != Stage::Flyover) return 1.0;
  return std::clamp((now - flyover_at_) / kFlyover, 0.0, 1.0);
}

void GolfPlay::choose_club() {
  const GolfRound& r = round();
  caddie_plan_.reset();
  caddie_passed_over_.clear();
  putt_read_.reset();
  if (r.finished()) return;
  // The caddie's club plays like the distance today: the wind, the lie, the ground; off the
  // green he points the aim where he would play it (a dogleg's corner when the cup is out of
  // reach, the way out from behind a tree, upwind of the pin in a crosswind, above it on a
  // slope), on the green at the cup: the player reads the putt (G asks for his read).
  aim_ = 0.0;
  if (r.lie() == "green") {
    club_ = bag_index("putter");
  } else {
    const StrokeInput plan = caddie().intend(r, &caddie_passed_over_);
    club_ = bag_index(plan.club);
    caddie_plan_ = plan;
    // Asked before his aim is taken (at his power): whether his club aimed at the flag would
    // strike a tree.
    const bool tree_at_flag = tree_in_the_way(plan.club).has_value();
    aim_ = plan.aim;
    aim_why_ = aim_why_for(r, tree_at_flag);
  }
}

GolfPlay::AimWhy GolfPlay::aim_why_for(const GolfRound& r, bool tree_at_flag) const {
  // Under half a degree the aim reads "at the pin" (the HUD's 0.0 deg): no reason to tell.
  if (std::abs(aim_) < deg_to_rad(0.5)) return AimWhy::Pin;
  // The corner's, when the aim points to the bend's side of the pin and the bend lies at least
  // half as far off the pin's line (a caddie cutting the corner aims inside it): a hole whose
  // bend lies a degree off the line to the cup looks straight, and an aim there is the wind's
  // or the tree's.
  if (const std::optional<Vec3> bend = r.next_bend()) {
    const Vec3& b = r.ball();
    const double to_bend = std::remainder(std::atan2(bend->z() - b.z(), bend->x() - b.x()) - r.line_to_pin(), 2.0 * kPi);
    if (to_bend * aim_ > 0.0 && std::abs(to_bend) >= 0.5 * std::abs(aim_)) {
      // How far the line turns there: toward the next bend after it, or the pin.
      Vec3 after = r.hole().pin;
      const std::vector<Vec3>& bends = r.hole().bends;
      const auto it = std::find(bends.begin(), bends.end(), *bend);
      if (it != bends.end() && it + 1 != bends.end()) after = *(it + 1);
      const double turn = std::remainder(std::atan2(after.z() - bend->z(), after.x() - bend->x()) -
                                             std::atan2(bend->z() - b.z(), bend->x() - b.x()),
                                         2.0 * kPi);
      return std::abs(turn) >= kDoglegTurn ? AimWhy::Corner : AimWhy::Bend;
    }
  }
  if (tree_at_flag) return AimWhy::WayOut;
  // The wind's or the ground's part: the caddie's own stroke, flown along his aim, is brought
  // back toward the pin's line in the air (the wind's drift) or after it lands (a slope's
  // break). Whichever brings it back by at least half the aim's offset there is the reason: a
  // 13 m chip aimed 8 deg off in a 5 m/s crosswind drifts ~0.3 m in the air, and its aim is
  // the green's slope or the caddie's line, not the wind's.
  const double power = caddie_plan_ ? caddie_plan_->meter.power : 1.0;
  const FlownHere& f = flown_here(club(), power);
  const double aim_line = r.line_to_pin() + aim_;
  const AlongAcross land = relative(r.ball(), aim_line, f.landing), rest = relative(r.ball(), aim_line, f.rest);
  const double back = aim_ > 0.0 ? -1.0 : 1.0;  // + toward the pin's side of the aim line
  const double tan_aim = std::tan(std::abs(aim_));
  const double in_air = back * land.across;
  const double on_ground = back * rest.across - in_air;
  const bool air_does = f.carry > 0.0 && in_air >= 0.5 * land.along * tan_aim;
  const bool ground_does = on_ground >= 0.5 * rest.along * tan_aim;
  const HoleWind hw = r.wind();
  const double cross = hw.speed * std::sin(hw.toward - r.line_to_pin());  // m/s, + toward the right
  constexpr double kCrossNoted = 2.0;  // m/s (4.5 mph): moves a full shot's landing by metres
  if (std::abs(cross) >= kCrossNoted && (cross > 0.0) == (aim_ < 0.0) && air_does && in_air >= on_ground) return AimWhy::Wind;
  if (ground_does) return AimWhy::Slope;
  return AimWhy::Line;
}

GolfPlay::AimWhy GolfPlay::aim_why() const {
  // His reason is for his club and his line: another club or aim says nothing of it.
  if (!caddie_plan_ || aim_ != caddie_plan_->aim || club() != caddie_plan_->club) return AimWhy::Pin;
  return aim_why_;
}

GolfPlay::StrokeKey GolfPlay::key_for(const std::string& club, bool along_aim) const {
  return {player_, club, round().ball(), group_.hole_index(), along_aim ? aim_ : 0.0};
}

const GolfPlay::FlownHere& GolfPlay::flown_here(const std::string& club, double power) const {
  const GolfRound& r = round();
  std::optional<FlownHere>& slot = flown_[power < 1.0 ? 1 : 0];
  const StrokeKey key = key_for(club);
  if (slot && slot->key == key && slot->power == power) return *slot;
  StrokeInput in;
  in.club = club;
  in.aim = aim_;
  in.meter.power = power;
  const FlightSummary f = r.simulate(in).trajectory.summary;
  double calm = f.carry_m;
  Vec3 calm_landing = f.landing_position;
  if (r.wind().speed > 0.0) {
    const FlightSummary c = r.simulate_calm(in).trajectory.summary;
    calm = r.first_touch_in_a_tree(c) ? std::numeric_limits<double>::quiet_NaN() : c.carry_m;
    calm_landing = c.landing_position;
  }
  slot = FlownHere{key, power, f.carry_m, f.total_m, calm, f.landing_position,
                   f.rest_position, r.first_touch_in_a_tree(f), calm_landing};
  return *slot;
}

double GolfPlay::carry_here(const std::string& club, double power) const {
  if (round().finished() || club == "putter") return 0.0;
  return flown_here(club, power).carry;
}

double GolfPlay::calm_carry_here(const std::string& club, double power) const {
  if (round().finished() || club == "putter") return 0.0;
  return flown_here(club, power).calm_carry;
}

double GolfPlay::landing_rise_here(const std::string& club, double power) const {
  if (round().finished() || club == "putter") return 0.0;
  return flown_here(club, power).calm_landing.y() - round().ball().y();
}

double GolfPlay::stops_here(const std::string& club, double power) const {
  if (round().finished() || club == "putter") return 0.0;
  return flown_here(club, power).total;
}

Vec3 GolfPlay::landing_here(const std::string& club, double power) const {
  if (round().finished() || club == "putter") return ball_centre();
  return flown_here(club, power).landing;
}

double GolfPlay::part_swing_power(const std::string& club) const {
  return caddie_plan_ && caddie_plan_->club == club && caddie_plan_->meter.power < 1.0 ? caddie_plan_->meter.power : 1.0;
}

std::optional<double> GolfPlay::tree_in_the_way(const std::string& club) const {
  if (round().finished() || club == "putter") return std::nullopt;
  // A pitch the caddie means as a part swing is judged at its power: a full swing's flight
  // into a tree 60 yd off says nothing of a 25 % chip.
  const FlownHere& f = flown_here(club, part_swing_power(club));
  return f.in_tree ? std::optional<double>(f.carry) : std::nullopt;
}

void GolfPlay::begin_turn(double t) {
  concede_asked_ = false;  // a question asked on another turn is not this one's
  if (group_.finished()) return;
  player_ = group_.to_play();
  turn_at_ = t;
  choose_club();
  build_roll_table();
}

void GolfPlay::read_green() {
  if (putt_read_) {
    putt_read_.reset();
    return;
  }
  const GolfRound& r = round();
  if (r.lie() != "green") {
    say("G reads a putt once the ball is on the green");
    return;
  }
  const StrokeInput plan = caddie().intend(r);
  if (plan.club != "putter") {  // a strip of rough between ball and cup: he would chip it
    say("The caddie would not putt this one: he would play the " + club_name(plan.club));
    return;
  }
  const ShotResult rolled = r.simulate(plan, true);
  PuttRead read;
  read.aim = plan.aim;
  read.power = plan.meter.power;
  read.to_cup = r.to_pin();
  read.aim_off = read.to_cup * std::tan(plan.aim);
  read.plays_as = std::max(0.0, flat_roll(plan.meter.power) - GolfBot::kPuttPast);
  read.holes = rolled.end == ShotEnd::Holed;
  // Every 5 cm or so of roll is plenty for a line drawn on the green.
  const auto& samples = rolled.trajectory.samples;
  for (const TrajectorySample& s : samples)
    if (read.line.empty() || (s.position - read.line.back()).norm() >= 0.05) read.line.push_back(s.position);
  if (!samples.empty()) read.line.push_back(samples.back().position);
  club_ = bag_index("putter");
  aim_ = plan.aim;
  putt_read_ = std::move(read);
}

void GolfPlay::build_roll_table() {
  roll_table_.clear();
  putt_plays_as_ = 0.0;
  putt_crosses_.clear();
  const GolfRound& r = round();
  // The preview is the human's meter's: a bot's turn has no use for it.
  if (r.finished() || r.to_pin() > kPuttGuideReach || !human_turn()) return;
  // The green's own surface, from under the cup.
  const WorldAsset& w = *r.hole().world;
  SurfaceContact hit;
  if (!ground_under(*w.world, r.hole().pin.x(), r.hole().pin.z(), w.description().bounds_max.y(),
                    w.description().bounds_max.y() - w.description().bounds_min.y(), &hit))
    return;
  const SurfaceMaterial& green = w.world->material(hit.material);
  StrokeInput in;
  in.club = "putter";
  for (double p = 0.05; p <= MeterInput::kPower.max + 1e-9; p += 0.05) {
    in.meter.power = p;
    roll_table_.emplace_back(p, flat_roll_distance(resolve(r.spec_for(in), assets_), green));
  }
  putt_plays_as_ = r.to_pin();
  if (r.lie() == "green") return;
  // Off the green the line crosses slower grass first. A rolling ball loses speed at a
  // steady rate on each surface (its rolling resistance), so v² falls by 2·c·g per metre: a
  // metre of a surface c times the green's takes as much out of the putt as c metres of
  // green. The ratio is read from the same physics as the putt: how far one stroke rolls on
  // the flat green against on the flat surface.
  in.meter.power = 0.5;
  const ResolvedShot putt = resolve(r.spec_for(in), assets_);
  const double on_green = flat_roll_distance(putt, green);
  std::vector<std::pair<int, double>> ratio;  // (material, green metres per metre)
  const auto ratio_of = [&](int material) {
    for (const auto& [m, k] : ratio)
      if (m == material) return k;
    const SurfaceMaterial& mat = w.world->material(material);
    // Water or a surface that stops the ball dead counts as a wall of rough (a putt is no
    // way across it); a green counts as itself.
    constexpr double kStops = 50.0;
    double k = 1.0;
    if (mat.kind != SurfaceKind::Green) {
      const double here = mat.kind == SurfaceKind::Water ? 0.0 : flat_roll_distance(putt, mat);
      k = here > 1e-3 ? std::clamp(on_green / here, 1.0, kStops) : kStops;
    }
    ratio.emplace_back(material, k);
    return k;
  };
  constexpr double kStep = 0.25;  // m along the line
  double plays = 0.0;
  for (const GolfRound::LineStretch& s : r.ground_to_pin(kStep)) {
    const double k = s.ground ? ratio_of(s.ground->material) : 1.0;
    if (s.ground && putt_crosses_.empty() && k > 1.0) putt_crosses_ = to_string(w.world->material(s.ground->material).kind);
    plays += k * s.length;
  }
  putt_plays_as_ = plays;
}

namespace {

// Linear interpolation in a table of increasing (a, b) pairs, from a to b (`forward`) or back;
// through the origin below the first pair, held at the last above it.
double interpolate(const std::vector<std::pair<double, double>>& table, double x, bool forward) {
  if (table.empty()) return 0.0;
  const auto in = [&](const std::pair<double, double>& e) { return forward ? e.first : e.second; };
  const auto out = [&](const std::pair<double, double>& e) { return forward ? e.second : e.first; };
  if (x <= in(table.front())) return out(table.front()) * x / std::max(in(table.front()), 1e-9);
  for (std::size_t k = 1; k < table.size(); ++k)
    if (x <= in(table[k]))
      return out(table[k - 1]) + (out(table[k]) - out(table[k - 1])) * (x - in(table[k - 1])) /
                                     std::max(in(table[k]) - in(table[k - 1]), 1e-9);
  return out(table.back());
}

}  // namespace

double GolfPlay::flat_roll(double power) const { return interpolate(roll_table_, power, true); }

double GolfPlay::power_for_roll(double distance) const { return interpolate(roll_table_, distance, false); }

double GolfPlay::cup_mark_power() const { return power_for_roll(putt_plays_as_ + GolfBot::kPuttPast); }

const GolfPlay::CarryTable& GolfPlay::carry_table(const std::string& club) const {
  static const CarryTable none;
  const GolfRound& r = round();
  if (r.finished() || club == "putter") return none;
  // Along the aim: turned into a tree, every power's carry is the tree's.
  const StrokeKey key = key_for(club);
  if (carry_table_ && carry_table_->key == key) return *carry_table_;
  CarryTable t{key, {}, {}};
  StrokeInput in;
  in.club = club;
  in.aim = aim_;
  double longest = 0.0, farthest = 0.0;
  // Every 5 % up to 20 % (a chip's few yards are all down there), every 10 % above.
  for (const double power : {0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1}) {
    in.meter.power = std::min(power, MeterInput::kPower.max);
    const FlightSummary f = r.simulate(in).trajectory.summary;
    longest = std::max(longest, f.carry_m);
    farthest = std::max(farthest, f.total_m);
    t.table.emplace_back(in.meter.power, longest);
    t.stops.emplace_back(in.meter.power, farthest);
  }
  carry_table_ = std::move(t);
  return *carry_table_;
}

const std::vector<GolfPlay::Hazard>& GolfPlay::hazards_on_line(const std::string& club) const {
  static const std::vector<Hazard> none;
  const GolfRound& r = round();
  if (r.finished() || club == "putter") return none;
  const StrokeKey key = key_for(club);
  if (hazards_ && hazards_->key == key) return hazards_->hazards;
  std::vector<Hazard> out;
  // Out to past where it stops by what a miss of length runs on (10 %, at least 10 m), every
  // 2 m; a gap under 5 m between two stretches of one kind is the same hazard (a sample
  // landing on a bunker's lip).
  constexpr double kStep = 2.0, kJoin = 5.0;
  const double reach = std::min(r.to_pin() + 20.0, stops_here(club, part_swing_power(club)) * 1.1 + 10.0);
  const Vec3 d = aim_direction(), b = r.ball();
  for (double s = kStep; s <= reach; s += kStep) {
    const std::string kind = r.surface_at(b + s * d);
    if (kind != "water" && kind != "sand") continue;
    if (!out.empty() && out.back().kind == kind && s - out.back().to <= kJoin) out.back().to = s;
    else out.push_back({kind, s, s});
  }
  hazards_ = HazardsHere{key, std::move(out)};
  return hazards_->hazards;
}

double GolfPlay::carry_at_power(const std::string& club, double power) const { return interpolate(carry_table(club).table, power, true); }

double GolfPlay::power_for_carry(const std::string& club, double distance) const {
  return interpolate(carry_table(club).table, distance, false);
}

double GolfPlay::stop_at_power(const std::string& club, double power) const { return interpolate(carry_table(club).stops, power, true); }

double GolfPlay::power_for_stop(const std::string& club, double distance) const {
  return interpolate(carry_table(club).stops, distance, false);
}

std::optional<GolfPlay::PinPower> GolfPlay::pin_power(const std::string& club) const {
  const GolfRound& r = round();
  if (r.finished() || club == "putter") return std::nullopt;
  const StrokeKey key = key_for(club);
  if (pin_power_ && pin_power_->key == key) return pin_power_->answer;
  const double to_pin = r.to_pin();
  std::optional<PinPower> answer;
  const auto& stops = carry_table(club).stops;
  // The table's first power past the pin and the one before it bracket it.
  for (std::size_t k = 1; k < stops.size() && !answer; ++k) {
    if (stops[k - 1].second >= to_pin) break;  // its lowest power already runs past
    if (stops[k].second < to_pin) continue;
    StrokeInput in;
    in.club = club;
    in.aim = aim_;
    PinPower lo{stops[k - 1].first, stops[k - 1].second}, hi{stops[k].first, stops[k].second};
    while (hi.power - lo.power > kPinPowerStep) {
      in.meter.power = 0.5 * (lo.power + hi.power);
      const double stop = r.simulate(in).trajectory.summary.total_m;
      (stop < to_pin ? lo : hi) = PinPower{in.meter.power, stop};
    }
    answer = std::abs(lo.stops - to_pin) < std::abs(hi.stops - to_pin) ? lo : hi;
  }
  pin_power_ = PinPowerHere{key, answer};
  return answer;
}

std::optional<GolfPlay::Spread> GolfPlay::skill_spread(const std::string& club, double power) const {
  const GolfRound& r = round();
  if (r.finished() || club == "putter") return std::nullopt;
  const StrokeKey key = key_for(club);
  if (skill_spread_ && skill_spread_->key == key && skill_spread_->power == power) return skill_spread_->answer;
  const GolferSkill& sk = skill();
  StrokeInput in;
  in.club = club;
  in.aim = aim_;
  const auto flown = [&](double power, double accuracy_ms) {
    in.meter.power = std::clamp(power, 0.02, MeterInput::kPower.max);
    in.meter.accuracy_ms = std::clamp(accuracy_ms, MeterInput::kAccuracy.min, MeterInput::kAccuracy.max);
    return r.simulate(in);
  };
  // The bot's own draws (GolfBot::plan): power x (1 + N(sd)), sd the full swing's power_sd
  // and partial_feel_sd per unit of power a part swing leaves out; the third click
  // N(accuracy_sd_ms).
  const double sd = sk.power_sd + sk.partial_feel_sd * (1.0 - std::min(power, 1.0));
  const double long_carry = flown(power * (1.0 + 2.0 * sd), 0.0).trajectory.summary.carry_m;
  const double short_carry = flown(power * (1.0 - 2.0 * sd), 0.0).trajectory.summary.carry_m;
  const ShotResult late = flown(power, 2.0 * sk.accuracy_sd_ms), early = flown(power, -2.0 * sk.accuracy_sd_ms);
  const double side = side_of_aim(late, late.trajectory.summary.landing_position) -
                      side_of_aim(early, early.trajectory.summary.landing_position);
  const Spread answer{0.25 * std::abs(long_carry - short_carry), 0.25 * std::abs(side)};
  skill_spread_ = SpreadHere{key, power, answer};
  return answer;
}

void GolfPlay::update(const Intents& intents, double now) {
  apply_in_time_order(intents, now, [this](double t) { advance(t); }, [this](const Intent& in) { apply(in); });
}

void GolfPlay::advance(double t) {
  if (stage_ == Stage::Flyover && t - flyover_at_ >= kFlyover) {
    stage_ = Stage::Aiming;
    turn_at_ = flyover_at_ + kFlyover;
  }
  if (stage_ == Stage::Swinging && meter_) {
    // The meter's own ends wait for a click the player's lag still has on its way.
    meter_->update(t - setup_.input_latency);
    if (meter_->phase() == MeterClock::Phase::Abandoned) {
      const bool meter_putting = meter_->putting();
      meter_.reset();
      stage_ = Stage::Aiming;
      ++cancelled_;
      say(meter_putting ? "Putt abandoned, no stroke counted (Space: start, Space: power)"
                        : "Swing abandoned, no stroke counted (Space: start, Space: power, Space: accuracy)");
      swing_undone_ = true;
    } else if (const auto m = meter_->result()) {
      strike_from_meter(*m, t);
    }
  }
  if (stage_ == Stage::Aiming && !group_.finished() && group_.bot_turn() && t - turn_at_ >= kBotAddress) {
    last_meter_.reset();
    // A match's hole the bot can no longer halve: he picks up, as match players do.
    if (group_.hole_lost_for_next()) concede_hole(turn_at_ + kBotAddress);
    else strike(group_.bot_stroke(), true, turn_at_ + kBotAddress);
  }
  if (stage_ == Stage::Flying && t - struck_at_ >= duration(last_.trajectory)) land(struck_at_ + duration(last_.trajectory));
}

void GolfPlay::concede_hole(double t) {
  const std::size_t hole = group_.hole_index();
  round_hole_ = hole;  // the hole the card and header show once it is over
  group_.concede_hole();
  landed_at_ = t;
  say(group_.note());
  if (group_.finished()) stage_ = Stage::RoundOver;
  else if (group_.hole_index() != hole) stage_ = Stage::HoleOver;
  else begin_turn(t);
}

void GolfPlay::land(double t) {
  landed_at_ = t;
  say(pending_message_, true);
  if (!group_.note().empty()) message_ += (message_.empty() ? "" : ". ") + group_.note();
  // The player's own copy without their name: "stroke 2: 7-iron, ..." reads as theirs.
  std::string own = pending_message_;
  const std::string who = group_.players()[static_cast<std::size_t>(shooter_)].name + ", ";
  if (own.starts_with(who)) own.erase(0, who.size());
  own_last_.resize(group_.players().size());
  own_last_[static_cast<std::size_t>(shooter_)] = OwnLast{own, last_record_, last_rest_lie_, round_hole_};
  if (group_.finished()) {
    stage_ = Stage::RoundOver;
  } else if (group_.hole_index() != round_hole_) {
    stage_ = Stage::HoleOver;  // everyone is done with the hole; the next has not started
  } else {
    stage_ = Stage::Aiming;
    begin_turn(t);
  }
}

void GolfPlay::strike_from_meter(const MeterInput& m, double t) {
  last_meter_ = m;
  const auto who = static_cast<std::size_t>(player_);
  click_of_.resize(group_.players().size());
  click_hole_.resize(group_.players().size(), 0);
  click_of_[who] = *meter_;
  click_hole_[who] = group_.hole_index();
  strike({club(), aim_, m}, false, t);
}

void GolfPlay::strike(const StrokeInput& s, bool bot, double t) {
  putt_read_.reset();  // read from where the ball lay
  round_hole_ = group_.hole_index();
  struck_hole_ = round_hole_;
  shooter_ = player_;
  const GolfPlayer& who = player_info();
  const int stroke_no = round().card().back().strokes + 1;
  const StrokeRecord rec = bot ? group_.play_drawn(s, &last_) : group_.play(s, &last_);
  last_record_ = rec;
  const GolfRound& mine = round();
  const bool moved_on = mine.finished() || mine.hole_index() != round_hole_;
  last_rest_lie_ = moved_on ? "holed" : mine.lie();
  last_hit_tree_ = !moved_on && mine.first_touch_in_a_tree(last_.trajectory.summary);
  struck_at_ = t;
  meter_.reset();
  stage_ = Stage::Flying;
  club_ = bag_index(s.club);
  say("");
  char msg[320];
  const char* result = end_words(rec.end);
  const std::string rest = rec.unplayable ? std::string(": lodged in a tree, unplayable, one stroke (Rule 19.2)")
                          : rec.relief       ? std::string(": on the cart path, free relief (Rule 16.1)")
                          : rec.wrong_green  ? std::string(": on another hole's green, free relief (Rule 13.1f)")
                          : rec.end == StrokeEnd::Holed ? ": " + holed_words(rec, mine.card().at(std::min(round_hole_, mine.card().size() - 1)))
                          : rec.end == StrokeEnd::Rest ? std::string() : std::string(": ") + result;
  if (last_meter_ && s.club == "putter") {
    std::snprintf(msg, sizeof msg, "%s, stroke %d: putt at %.0f %% power%s", who.name.c_str(), stroke_no,
                  100.0 * last_meter_->power, rest.c_str());
  } else if (last_meter_) {
    // The click as he made it (the meter he just swung: his own last click).
    const double late = last_click() ? last_click()->click_error_ms() : last_meter_->accuracy_ms;
    // The meter plays a swing whose last click never came at its latest (MeterInput::kAccuracy).
    const bool at_the_limit = std::abs(late) >= MeterInput::kAccuracy.max - 0.5;
    // At the limit the player never made the third click in time: said so, in his words.
    // Early past the window is a click that came too soon; late past it, one that never came.
    const std::string timing = !at_the_limit ? timing_words(late)
                               : late < 0.0  ? "accuracy click too early, played as the earliest swing (" + timing_words(late) + ")"
                                             : "no accuracy click in time, played as the latest swing (" + timing_words(late) + ")";
    // From a bunker a splash says how it met the sand: the timing moved where it entered.
    const std::string sand = splash_words(assets_.equipment().club(s.club), rec.lie, last_.club.sand_entry);
    std::snprintf(msg, sizeof msg, "%s, stroke %d: %s, power %.0f\u00a0%%, %s%s%s", who.name.c_str(), stroke_no, club_name(s.club).c_str(),
                  100.0 * last_meter_->power, timing.c_str(), sand.empty() ? "" : (", " + sand).c_str(), rest.c_str());
  } else {
    std::snprintf(msg, sizeof msg, "%s, stroke %d: %s%s%s", who.name.c_str(), stroke_no, club_name(s.club).c_str(),
                  who.human ? " (the caddie's swing)" : "", rest.c_str());
  }
  pending_message_ = msg;
}

void GolfPlay::apply(const Intent& in) {
  const double t = in.time;
  if (in.kind != IntentKind::Concede && concede_asked_) {
    // The question answered no, and that is all the key does, as the pause menu's
    // confirmations take theirs: the aim, the club or a swing are the next key's.
    concede_asked_ = false;
    say("Hole not conceded: play on");
    return;
  }
  if (in.kind == IntentKind::Restart) {
    if (stage_ == Stage::RoundOver) new_round(t);
    else restart_hole(t);
    return;
  }
  const bool putting = club() == "putter";
  const int steps = in.param > 0 ? in.param : 1;
  switch (stage_) {
    case Stage::Flyover:
      if (in.kind == IntentKind::Continue || in.kind == IntentKind::Swing || in.kind == IntentKind::Cancel) {
        stage_ = Stage::Aiming;
        turn_at_ = t;
      }
      break;
    case Stage::Aiming:
      if (!human_turn()) {
        // A bot's turn: Enter lets it swing at once. A stroke's key is not lost without a
        // word: whose turn it is, and how to hurry it.
        if (in.kind == IntentKind::Continue) turn_at_ = t - kBotAddress;
        else if (in.kind == IntentKind::Swing || in.kind == IntentKind::CaddiePlays)
          say(player_info().name + " is to play, not you (Enter: let him swing now)");
        break;
      }
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
        case IntentKind::ReadGreen: read_green(); break;
        case IntentKind::Swing: {
          meter_.emplace(next_meter());
          swing_undone_ = false;
          meter_->click(t);
          stage_ = Stage::Swinging;
          say("");
          break;
        }
        case IntentKind::Concede:
          // Giving up a hole (and perhaps the match) takes a second press: H is a key a
          // newcomer tries for help.
          if (group_.options().format == GolfFormat::Match && !concede_asked_) {
            concede_asked_ = true;
            say("Concede hole " + std::to_string(group_.hole_index() + 1) + "? H again gives it up; any other key plays on");
          } else if (group_.options().format == GolfFormat::Match) {
            concede_asked_ = false;
            concede_hole(t);
          } else {
            // Not a silent key: what H is, and why it does nothing here (the Rules of Golf
            // allow a concession only in match play, Rule 3.2b).
            say("H concedes a hole, in match play only");
          }
          break;
        case IntentKind::CaddiePlays: {
          const StrokeInput s = group_.bot_stroke();
          aim_ = s.aim;
          last_meter_.reset();
          strike(s, true, t);
          break;
        }
        default: break;
      }
      break;
    case Stage::Swinging:
      if (in.kind == IntentKind::Swing && meter_) {
        // The power and accuracy clicks answer what the player saw: take off the lag.
        meter_->click(std::max(t - setup_.input_latency, meter_->started()));
        if (const auto m = meter_->result()) strike_from_meter(*m, t);
      } else if (in.kind == IntentKind::Cancel) {
        const bool putt = meter_ && meter_->putting();
        meter_.reset();
        stage_ = Stage::Aiming;
        ++cancelled_;
        say(putt ? "Putt cancelled, no stroke counted (Space: putt again)" : "Swing cancelled, no stroke counted (Space: swing again)");
        swing_undone_ = true;
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
        say("");
        begin_turn(t);
        stage_ = setup_.flyover ? Stage::Flyover : Stage::Aiming;
        flyover_at_ = t;
      }
      break;
    case Stage::RoundOver:
      // The final card stays until a new round is asked for (N, or the menu's restart): the
      // Enters a player presses to skip flights and turns never throw it away.
      if (in.kind == IntentKind::NewRound) new_round(t);
      break;
  }
}

void GolfPlay::new_round(double t) {
  group_ = GolfGroup(assets_, course_, setup_.players, setup_.options);
  last_record_ = StrokeRecord{};
  last_ = ShotResult{};
  own_last_.clear();
  restarts_.clear();
  pending_message_.clear();
  meter_.reset();
  last_meter_.reset();
  click_of_.clear();
  click_hole_.clear();
  struck_hole_.reset();
  say("");
  begin_turn(t);
  stage_ = setup_.flyover ? Stage::Flyover : Stage::Aiming;
  flyover_at_ = t;
}

int GolfPlay::strokes_a_restart_loses() const {
  const std::size_t hole = hole_shown();
  if (stage_ == Stage::RoundOver || hole >= course_.holes.size()) return 0;
  const auto& events = group_.events();
  const std::size_t first = std::min(group_.hole_first_event(hole), events.size());
  int swings = 0;
  for (std::size_t i = first; i < events.size(); ++i) swings += events[i].kind != GolfEvent::Kind::ConcedeHole;
  // The strokes the card would lose: the swings, and the penalty strokes and gimmes with them.
  int strokes = 0;
  for (std::size_t p = 0; p < group_.players().size(); ++p) {
    const auto& card = group_.round(static_cast<int>(p)).card();
    if (hole < card.size()) strokes += card[hole].strokes;
  }
  return std::max(swings, strokes);
}

void GolfPlay::restart_hole(double t) {
  // The hole being played: during a flight, or on the card after it, the hole of the last
  // stroke (the group may already be on the next, or done).
  const std::size_t hole = hole_shown();
  if (hole >= course_.holes.size()) {
    new_round(t);
    return;
  }
  // The round is deterministic: the turns before this hole, replayed, leave it exactly where
  // it was when the hole began.
  restarts_.resize(course_.holes.size(), 0);
  // A restart before any stroke on the hole throws nothing away: no mulligan to mark.
  const bool threw_away = strokes_a_restart_loses() > 0;
  if (threw_away) ++restarts_[hole];
  const std::size_t first = std::min(group_.hole_first_event(hole), group_.events().size());
  std::vector<GolfEvent> before(group_.events().begin(), group_.events().begin() + static_cast<std::ptrdiff_t>(first));
  group_ = GolfGroup(assets_, course_, setup_.players, setup_.options);
  group_.replay(before);
  meter_.reset();
  last_record_ = StrokeRecord{};
  last_ = ShotResult{};  // the strokes thrown away are not there to replay
  struck_hole_.reset();
  own_last_.clear();
  pending_message_.clear();
  landed_at_ = t;
  stage_ = Stage::Aiming;
  begin_turn(t);
  say("Hole " + std::to_string(course_.holes[group_.hole_index()].number) +
      (threw_away ? " restarted (the card marks it R)" : " restarted"));
}

}  // namespace sweetspot
