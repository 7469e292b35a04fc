#include "game/modes/golf/round.hpp"

#include <algorithm>
#include <cmath>

#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"
#include "game/modes/golf/swing_meter.hpp"

namespace sweetspot {

const char* to_string(StrokeEnd e) {
  switch (e) {
    case StrokeEnd::Rest: return "rest";
    case StrokeEnd::Holed: return "holed";
    case StrokeEnd::Water: return "water";
    case StrokeEnd::OutOfBounds: return "out_of_bounds";
  }
  return "?";
}

const char* to_string(TeeShot t) {
  switch (t) {
    case TeeShot::None: return "";
    case TeeShot::Fairway: return "hit";
    case TeeShot::Left: return "left";
    case TeeShot::Right: return "right";
  }
  return "?";
}

GolfRound::GolfRound(const Assets& assets, Course course, const GolferSkill& golfer, std::vector<HoleWind> winds)
    : assets_(&assets), course_(std::move(course)), golfer_(golfer), winds_(std::move(winds)) {
  if (course_.holes.empty()) throw InputError("course '" + course_.name + "' has no holes");
  if (!winds_.empty() && winds_.size() != course_.holes.size())
    throw InputError("a round needs one wind per hole (" + std::to_string(course_.holes.size()) + "), not " +
                     std::to_string(winds_.size()));
  ball_ = hole().tee;
  card_.push_back(new_card());
}

std::optional<SurfaceContact> GolfRound::ground_at(double x, double z) const {
  const WorldAsset& w = *hole().world;
  const WorldDescription& d = w.description();
  SurfaceContact hit;
  if (!ground_under(*w.world, x, z, d.bounds_max.y(), d.bounds_max.y() - d.bounds_min.y(), &hit)) return std::nullopt;
  return hit;
}

std::vector<GolfRound::LineStretch> GolfRound::ground_to_pin(double step) const {
  const Vec3& from = ball_;
  const Vec3& to = hole().pin;
  const double length = to_pin();
  const int n = std::max(1, static_cast<int>(std::ceil(length / step)));
  std::vector<LineStretch> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double f = (i + 0.5) / n;
    out[static_cast<std::size_t>(i)] = {length / n, ground_at(from.x() + f * (to.x() - from.x()), from.z() + f * (to.z() - from.z()))};
  }
  return out;
}

namespace {
constexpr double kAboveGround = 0.5;  // m, more than any tee, ball or turf contact
}  // namespace

bool GolfRound::first_touch_in_a_tree(const FlightSummary& f) const { return lodged_off_the_ground(f.landing_position); }

bool GolfRound::lodged_off_the_ground(const Vec3& p) const {
  const std::optional<SurfaceContact> under = ground_at(p.x(), p.z());
  return under && p.y() - under->point.y() > kAboveGround;
}

std::string GolfRound::surface_at(const Vec3& p) const {
  const std::optional<SurfaceContact> hit = ground_at(p.x(), p.z());
  return hit ? to_string(hole().world->world->material(hit->material).kind) : "out_of_bounds";
}

std::string GolfRound::lie() const { return surface_at(ball_); }

double GolfRound::sand_entry(const std::string& club) const {
  return sand_entry_for(assets_->equipment().club(club), lie());
}

double GolfRound::to_pin() const { return std::hypot(hole().pin.x() - ball_.x(), hole().pin.z() - ball_.z()); }

std::optional<Vec3> GolfRound::next_bend() const {
  const Vec3& pin = hole().pin;
  const auto flat = [](const Vec3& a, const Vec3& b) { return std::hypot(a.x() - b.x(), a.z() - b.z()); };
  const double ball_to_pin = flat(ball_, pin);
  for (const Vec3& b : hole().bends)
    if (flat(b, pin) < ball_to_pin && flat(ball_, b) > kBendReached) return b;
  return std::nullopt;
}

double GolfRound::line_to_pin() const { return std::atan2(hole().pin.z() - ball_.z(), hole().pin.x() - ball_.x()); }

int GolfRound::total_strokes() const {
  int n = 0;
  for (const HoleCard& h : card_) n += h.strokes;
  return n;
}

ShotSpec GolfRound::spec_for(const StrokeInput& in) const {
  const EquipmentCatalog& eq = assets_->equipment();
  if (std::find(golf_bag().begin(), golf_bag().end(), in.club) == golf_bag().end()) {
    std::string names;
    for (const std::string& c : golf_bag()) names += (names.empty() ? "" : ", ") + c;
    throw InputError("club '" + in.club + "' is not in the bag (allowed: " + names + ")");
  }
  check_range("aim", in.aim, StrokeInput::kAim, "rad");
  ShotSpec s;
  s.sport = "golf";
  s.world = hole().world_name;
  ClubStrike c;
  c.club = in.club;
  c.swing = golfer_swing(golfer_, in.meter, eq, in.club);
  const ClubSpec& club = eq.club(in.club);
  c.swing.sand_entry = sand_entry_for(club, lie(), timing_error_ms(in.meter, club));
  s.strike = c;
  // The ball is kept in world coordinates; a placement is measured from the world's origin.
  const Vec3& origin = hole().world->description().origin;
  s.placement.x = ball_.x() - origin.x();
  s.placement.z = ball_.z() - origin.z();
  // The aim line: from the ball toward the cup, turned by the player's aim.
  double aim = line_to_pin() + in.aim;
  aim = std::remainder(aim, 2.0 * kPi);
  s.placement.aim = aim;
  s.placement.teed = teed_;
  s.cup = hole().pin;  // the course's cup, which may not be the world's own pin
  const HoleWind w = wind();
  s.environment.wind_speed = w.speed;
  s.environment.wind_direction = w.toward;
  return s;
}

ShotResult GolfRound::simulate(const StrokeInput& in, bool record_samples) const {
  const ShotSpec s = spec_for(in);
  return run_shot(resolve(s, *assets_), "hole " + std::to_string(hole().number), {true, record_samples});
}

ShotResult GolfRound::simulate_calm(const StrokeInput& in) const {
  ShotSpec s = spec_for(in);
  s.environment.wind_speed = 0.0;
  return run_shot(resolve(s, *assets_), "hole " + std::to_string(hole().number), {true, false});
}

HoleCard GolfRound::new_card() const {
  HoleCard c;
  c.number = hole().number;
  c.par = hole().par;
  return c;
}

HoleWind GolfRound::wind() const {
  if (winds_.empty() || finished()) return {};
  return winds_[hole_];
}

const StrokeRecord& GolfRound::concede_stroke() {
  if (finished()) throw InputError("the round is over");
  const std::size_t k = card_.size() - 1;
  HoleCard& h = card_[k];
  StrokeRecord rec;
  rec.club = "putter";
  rec.lie = lie();
  rec.start = ball_;
  rec.rest = hole().pin;
  rec.end = StrokeEnd::Holed;
  rec.conceded = true;
  ++h.strokes;
  if (rec.lie == "green" && rec.club == "putter") ++h.putts;
  h.holed = true;
  h.shots.push_back(rec);
  finish_hole();
  return card_[k].shots.back();
}

void GolfRound::concede_hole() {
  if (finished()) throw InputError("the round is over");
  card_.back().conceded = true;
  finish_hole();
}

void GolfRound::leave_hole() {
  if (finished()) throw InputError("the round is over");
  finish_hole();
}

Vec3 GolfRound::drop_back_on_line(const Vec3& in_water, const Vec3& from) const {
  // Rule 17.1d(2), back-on-the-line relief: on the line from the hole through where the ball
  // entered, behind it; here, from where it came to rest back toward where it was struck,
  // the first spot that is neither water nor out of bounds, and a metre more.
  const Vec3 d = Vec3(from.x() - in_water.x(), 0.0, from.z() - in_water.z());
  const double len = d.norm();
  const Vec3 u = len > 0.0 ? Vec3(d / len) : Vec3::UnitX() * -1.0;
  for (double t = 0.5; t < len + 50.0; t += 0.5) {
    const Vec3 p = in_water + t * u;
    const std::string s = surface_at(p);
    if (s != "water" && s != "out_of_bounds") {
      const Vec3 q = p + u;
      const std::string sq = surface_at(q);
      return sq != "water" && sq != "out_of_bounds" ? q : p;
    }
  }
  return from;
}

bool GolfRound::on_another_green(const Vec3& p) const {
  const auto green = [&](double x, double z) {
    const std::optional<SurfaceContact> hit = ground_at(x, z);
    return hit && hole().world->world->material(hit->material).kind == SurfaceKind::Green;
  };
  if (!green(p.x(), p.z())) return false;
  const Vec3& pin = hole().pin;
  const double dx = pin.x() - p.x(), dz = pin.z() - p.z(), d = std::hypot(dx, dz);
  // Green all the way along the straight line to the cup: the same green.
  bool straight = true;
  for (double t = 0.5; t < d && straight; t += 0.5) straight = green(p.x() + dx * t / d, p.z() + dz * t / d);
  if (straight) return false;
  // Otherwise spread over the green from the ball on a 1 m grid: it is this hole's green if
  // the spread reaches the cup. A putting green is well under kLargestGreen across.
  constexpr double kCell = 1.0, kLargestGreen = 120.0;
  constexpr int kHalf = static_cast<int>(kLargestGreen / kCell);
  constexpr int kSide = 2 * kHalf + 1;
  std::vector<char> seen(static_cast<std::size_t>(kSide) * kSide, 0);
  const auto cell = [&](int i, int j) -> char& { return seen[static_cast<std::size_t>((i + kHalf) * kSide + (j + kHalf))]; };
  std::vector<std::pair<int, int>> todo{{0, 0}};
  cell(0, 0) = 1;
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    if (std::hypot(pin.x() - (p.x() + i * kCell), pin.z() - (p.z() + j * kCell)) <= 1.5 * kCell) return false;
    for (const auto& [ni, nj] : {std::pair{i + 1, j}, std::pair{i - 1, j}, std::pair{i, j + 1}, std::pair{i, j - 1}}) {
      if (std::abs(ni) > kHalf || std::abs(nj) > kHalf || cell(ni, nj)) continue;
      cell(ni, nj) = 1;
      if (green(p.x() + ni * kCell, p.z() + nj * kCell)) todo.push_back({ni, nj});
    }
  }
  return true;
}

Vec3 GolfRound::free_relief(const Vec3& spot) const {
  // Rule 16.1b (an immovable obstruction: the path) and Rule 13.1f (a wrong green): free relief
  // at the nearest point where the condition no longer interferes, no nearer the hole; here the
  // nearest such spot of playable ground (not a path, water, out of bounds or a green),
  // searched on rings 0.25 m apart (a place within the club-length relief area the Rules allow).
  const Vec3& pin = hole().pin;
  const double from_pin = std::hypot(pin.x() - spot.x(), pin.z() - spot.z());
  constexpr int kDirections = 32;
  for (double r = 0.25; r <= kMaxRelief; r += 0.25) {
    double best_pin = HUGE_VAL;
    std::optional<Vec3> best;
    for (int k = 0; k < kDirections; ++k) {
      const double a = 2.0 * kPi * k / kDirections;
      const double x = spot.x() + r * std::cos(a), z = spot.z() + r * std::sin(a);
      const double to_pin = std::hypot(pin.x() - x, pin.z() - z);
      if (to_pin < from_pin) continue;
      const std::optional<SurfaceContact> hit = ground_at(x, z);
      if (!hit) continue;
      const std::string s = to_string(hole().world->world->material(hit->material).kind);
      if (s == "path" || s == "water" || s == "out_of_bounds" || s == "green") continue;
      if (to_pin < best_pin) {  // of the ring's spots, the one the Rule's line from the hole favours least: any is as near
        best_pin = to_pin;
        best = Vec3(x, hit->point.y(), z);
      }
    }
    if (best) return *best;
  }
  return spot;  // no playable ground within reach: played as it lies
}

void GolfRound::finish_hole() {
  ++hole_;
  if (finished()) return;
  ball_ = hole().tee;
  teed_ = true;
  card_.push_back(new_card());
}

const StrokeRecord& GolfRound::play(const StrokeInput& in, ShotResult* shot) {
  if (finished()) throw InputError("the round is over");
  return play_spec(spec_for(in), in.club, in.meter.power, shot);
}

const StrokeRecord& GolfRound::play_launch(const std::string& club, const LaunchNumbers& numbers, ShotResult* shot) {
  if (finished()) throw InputError("the round is over");
  StrokeInput in;
  in.club = club;
  ShotSpec spec = spec_for(in);  // placement, aim at the cup, world
  spec.strike = LaunchStrike{numbers};
  return play_spec(spec, club, 1.0, shot);
}

const StrokeRecord& GolfRound::play_spec(const ShotSpec& spec, const std::string& club, double power, ShotResult* shot) {
  const ResolvedShot resolved = resolve(spec, *assets_);
  ShotResult r = run_shot(resolved, "hole " + std::to_string(hole().number), {true, shot != nullptr});
  const std::size_t k = card_.size() - 1;
  HoleCard& h = card_[k];
  const bool tee_shot = h.shots.empty() && h.par >= 4;
  // The hole's line from the tee: to its first bend, or to the cup on a straight hole.
  const Vec3 line_to = next_bend().value_or(hole().pin);
  std::string rest_surface;  // where the ball came to rest, before any relief moved it
  StrokeRecord rec;
  rec.club = club;
  rec.power = power;
  rec.lie = resolved.start_surface;
  rec.start = resolved.ball_centre;
  rec.rest = r.trajectory.summary.rest_position;
  rec.carry_m = r.trajectory.summary.carry_m;
  rec.side_m = side_of_aim(r, r.trajectory.summary.landing_position);
  ++h.strokes;
  if (rec.lie == "green" && club == "putter") ++h.putts;
  switch (r.end) {
    case ShotEnd::Holed:
      rec.end = StrokeEnd::Holed;
      break;
    case ShotEnd::Water:
      rec.end = StrokeEnd::Water;
      rec.penalty = 1;
      ball_ = drop_back_on_line(rec.rest, rec.start);
      teed_ = false;
      break;
    case ShotEnd::OutOfBounds:
    case ShotEnd::StepLimit:
      // Stroke and distance: play again from where it was struck (teed again on the tee).
      rec.end = StrokeEnd::OutOfBounds;
      rec.penalty = 1;
      break;
    default:
      rec.end = StrokeEnd::Rest;
      ball_ = Vec3(rec.rest.x(), rec.rest.y() - resolved.ball.radius, rec.rest.z());
      teed_ = false;
      rest_surface = surface_at(ball_);
      if (lodged_off_the_ground(rec.rest)) {
        // No one plays a ball out of a tree's branches: unplayable (Rule 19.2c), one stroke,
        // dropped at the spot on the ground directly below it.
        rec.unplayable = true;
        rec.penalty = 1;
        if (const std::optional<SurfaceContact> below = ground_at(rec.rest.x(), rec.rest.z())) ball_ = below->point;
      }
      if (surface_at(ball_) == "path") {
        const Vec3 moved = free_relief(ball_);
        rec.relief = (moved - ball_).norm() > 0.0;  // none where no ground lies beside the path
        ball_ = moved;
      } else if (on_another_green(ball_)) {
        // Rule 13.1f: a ball on a wrong green must not be played from it; free relief off it.
        const Vec3 moved = free_relief(ball_);
        rec.wrong_green = (moved - ball_).norm() > 0.0;
        ball_ = moved;
      }
      break;
  }
  h.penalties += rec.penalty;
  h.strokes += rec.penalty;
  if (tee_shot) {
    const bool fairway = rec.end == StrokeEnd::Holed || (rest_surface == "fairway" && !rec.unplayable);
    const Vec3 line = line_to - rec.start, off = rec.rest - rec.start;
    h.tee_shot = fairway ? TeeShot::Fairway : line.x() * off.z() - line.z() * off.x() >= 0.0 ? TeeShot::Right : TeeShot::Left;
  }
  const bool on_this_green = rec.end == StrokeEnd::Rest && surface_at(ball_) == "green" && !on_another_green(ball_);
  if (h.strokes <= h.par - 2 && (rec.end == StrokeEnd::Holed || on_this_green)) h.green_in_regulation = true;
  rec.to_pin_m = rec.end == StrokeEnd::Holed ? 0.0 : std::hypot(hole().pin.x() - rec.rest.x(), hole().pin.z() - rec.rest.z());
  if (rec.end != StrokeEnd::Holed) {
    const double lx = hole().pin.x() - rec.start.x(), lz = hole().pin.z() - rec.start.z();
    const double to_cup = std::hypot(lx, lz);
    if (to_cup > 0.0) {
      const double ox = rec.rest.x() - rec.start.x(), oz = rec.rest.z() - rec.start.z();
      rec.past_m = (ox * lx + oz * lz) / to_cup - to_cup;
      rec.right_m = (lx * oz - lz * ox) / to_cup;  // facing +x, +z (south) is the right hand
    }
  }
  h.shots.push_back(rec);
  if (shot != nullptr) *shot = std::move(r);
  if (rec.end == StrokeEnd::Holed) {
    h.holed = true;
    finish_hole();
  } else if (h.strokes >= kPickUp) {
    h.strokes = kPickUp;
    h.picked_up = true;
    finish_hole();
  }
  return card_[k].shots.back();
}

}  // namespace sweetspot
