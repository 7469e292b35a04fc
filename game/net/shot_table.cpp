#include "game/net/shot_table.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "game/content/course_file.hpp"
#include "game/rules/run_shot.hpp"
#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/round.hpp"
#include "game/report/flight_json.hpp"
#include "game/report/report.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr double kDegPerRad = 180.0 / kPi;

// Below this ball speed a message is not a ball being hit: connectors send zeros when the
// device misread (GSPro resets the club on them, as the SLX proxy notes). 1 mph is
// far below a tap-in putt (a 30 cm putt leaves at ~2 mph).
constexpr double kMinBallSpeedMph = 1.0;

LaunchNumbers launch_numbers(const OcBallData& b) {
  LaunchNumbers n;
  n.ball_speed = mph_to_mps(b.speed_mph);
  n.vertical_angle = b.vla_deg / kDegPerRad;
  n.horizontal_angle = b.hla_deg / kDegPerRad;
  n.spin = rpm_to_radps(b.total_spin_rpm);
  n.spin_axis = b.spin_axis_deg / kDegPerRad;
  return n;
}

nlohmann::json club_data_json(const OcClubData& c) {
  nlohmann::json j = nlohmann::json::object();
  if (c.speed_mph) j["speed_mps"] = mph_to_mps(*c.speed_mph);
  if (c.angle_of_attack_deg) j["attack_angle_deg"] = *c.angle_of_attack_deg;
  if (c.path_deg) j["path_deg"] = *c.path_deg;
  if (c.face_to_target_deg) j["face_angle_deg"] = *c.face_to_target_deg;
  if (c.loft_deg) j["dynamic_loft_deg"] = *c.loft_deg;
  if (c.lie_deg) j["lie_deg"] = *c.lie_deg;
  if (c.horizontal_impact_mm || c.vertical_impact_mm)
    j["impact_offset_m"] = {c.horizontal_impact_mm.value_or(0.0) / 1000.0, c.vertical_impact_mm.value_or(0.0) / 1000.0};
  if (c.closure_rate_dps) j["closure_rate_dps"] = *c.closure_rate_dps;
  return j;
}

}  // namespace

std::optional<ShotResult> predict_from_club_data(const Assets& assets, const std::string& club, const OcClubData& c) {
  // A device that measures no club speed (or sends zeros for "not measured") gives us no
  // delivery to strike with.
  if (!c.speed_mph || *c.speed_mph <= 0.0) return std::nullopt;
  ShotSpec s;
  s.sport = "golf";
  s.world = kFlatWorld;
  ClubStrike strike;
  strike.club = club;
  GolfSwing& g = strike.swing;
  g.club_speed = mph_to_mps(*c.speed_mph);
  g.attack_angle = c.angle_of_attack_deg.value_or(0.0) / kDegPerRad;
  g.club_path = c.path_deg.value_or(0.0) / kDegPerRad;
  // Face angle and loft as a device measures them: where the face meets the ball
  // (TrackMan's definitions), so a toe strike's bulge is not counted twice.
  g.strike_face_angle = c.face_to_target_deg.value_or(0.0) / kDegPerRad;
  // A loft of 0 is how connectors say "not measured"; the club's typical loft stands in. A
  // negative one is a measurement this model cannot strike with (the face turned past
  // vertical onto the ball): said, not silently replaced by the typical loft.
  if (c.loft_deg && *c.loft_deg < 0.0) {
    char loft[32];
    std::snprintf(loft, sizeof loft, "%g", *c.loft_deg);
    throw InputError(std::string("ClubData.Loft = ") + loft +
                     " deg: a face delivered with negative loft is not modelled (allowed: 0 for not measured, or a "
                     "positive dynamic loft within the club's range)");
  }
  if (c.loft_deg && *c.loft_deg > 0.0) g.strike_loft = *c.loft_deg / kDegPerRad;
  if (c.horizontal_impact_mm) g.impact_toe = *c.horizontal_impact_mm / 1000.0;
  if (c.vertical_impact_mm && *c.vertical_impact_mm != 0.0) g.impact_up = *c.vertical_impact_mm / 1000.0;
  if (c.closure_rate_dps) g.closure_rate = *c.closure_rate_dps / kDegPerRad;
  s.strike = strike;
  s.placement.teed = false;
  try {
    return launch_shot(resolve(s, assets), "club data");
  } catch (const InputError& e) {
    throw InputError(std::string("ClubData: ") + e.what());
  }
}

std::string club_for_delivery(const Assets& assets, const OcClubData& c, double vla_deg) {
  const EquipmentCatalog& eq = assets.equipment();
  std::string best = "driver";
  double gap = std::numeric_limits<double>::infinity();
  if (c.loft_deg && *c.loft_deg > 0.0) {
    // The device measured dynamic loft: the club whose typical loft is nearest.
    for (const std::string& club : golf_bag()) {
      const ClubSpec& spec = eq.club(club);
      // A full swing's speed is no putting stroke, however little loft the device saw
      // (the putter's reference is the game's full putting stroke, 13 mph; 2.5 x of it is
      // still slower than any full swing and leaves a device's hardest putt its club).
      const ClubInfo& info = eq.club_info_of(club);
      if (info.kind == "putter" && c.speed_mph && *c.speed_mph > 2.5 * mps_to_mph(info.tour_speed)) continue;
      const double typical = spec.dynamic_loft + strike_tilt(spec, spec.strike_height);
      const double d = std::abs(typical * kDegPerRad - *c.loft_deg);
      if (d < gap) gap = d, best = club;
    }
    return best;
  }
  if (!c.speed_mph || *c.speed_mph <= 0.0) return best;
  // No loft (most connectors send 0 for "not measured"): strike the device's delivery with
  // every club of the bag and keep the one whose launch angle is nearest the measured one.
  // Launch angle is set mostly by loft (and attack), so this identifies the club by the
  // impact model itself instead of by a table of typical launches.
  for (const std::string& club : golf_bag()) {
    try {
      const auto r = predict_from_club_data(assets, club, c);
      if (!r) continue;
      const double d = std::abs(r->launch.vertical_angle * kDegPerRad - vla_deg);
      if (d < gap) gap = d, best = club;
    } catch (const InputError&) {
      // A delivery this club cannot strike is not evidence for it.
    }
  }
  return best;
}

struct ShotTable::Impl {
  const Assets& assets;
  ShotTableOptions options;
  std::optional<Course> course;
  std::unique_ptr<GolfRound> round;
  std::unique_ptr<GolfBot> caddie;  // picks the club the game expects (a caddie of tour skill)
  int session_shots = 0;
  int rounds_done = 0;
  std::string range_club = "driver";

  Impl(const Assets& a, const ShotTableOptions& o) : assets(a), options(o) {
    if (!o.course.empty()) {
      course = load_course(assets, o.course);
      caddie = std::make_unique<GolfBot>(assets, golfer_skill("tour"), 1);
      new_round();
    } else {
      // Resolve the range once so an unknown world is refused before anyone connects.
      resolve(range_spec(LaunchNumbers{}), assets);
    }
  }

  void new_round() { round = std::make_unique<GolfRound>(assets, *course, golfer_skill("tour")); }

  ShotSpec range_spec(const LaunchNumbers& n) const {
    ShotSpec s;
    s.sport = "golf";
    s.world = options.world;
    s.strike = LaunchStrike{n};
    return s;
  }

  std::string club() const {
    if (!round) return range_club;
    if (round->lie() == "green") return "putter";
    return caddie->suggest(round->to_pin(), round->teed());
  }
};

ShotTable::ShotTable(const Assets& assets, const ShotTableOptions& o) : impl_(std::make_unique<Impl>(assets, o)) {}
ShotTable::~ShotTable() = default;

std::string ShotTable::club() const { return impl_->club(); }
const GolfRound* ShotTable::round() const { return impl_->round.get(); }

std::string ShotTable::where() const {
  if (!impl_->round) return "range on " + (impl_->options.world.empty() ? std::string("the golf hole") : impl_->options.world);
  const GolfRound& r = *impl_->round;
  char text[128];
  std::snprintf(text, sizeof text, "%s hole %d (par %d), %.0f m to the pin, %s", r.course().name.c_str(), r.hole().number,
                r.hole().par, r.to_pin(), r.lie().c_str());
  return text;
}

std::string ShotTable::player_reply() const {
  std::optional<double> distance;
  if (impl_->round) distance = std::round(m_to_yd(impl_->round->to_pin()) * 10.0) / 10.0;
  return reply_player("RH", gspro_club_code(club()), distance);
}

ShotTable::Played ShotTable::play(const OcMessage& m, bool record_samples) {
  Impl& s = *impl_;
  Played p;
  if (!m.ball) throw InputError("a shot needs BallData");
  if (m.ball->speed_mph < kMinBallSpeedMph) return p;  // not a ball hit: no shot
  const LaunchNumbers numbers = launch_numbers(*m.ball);
  const std::string club_before = s.club();
  // On the range the device's loft says which club is in the player's hands.
  if (!s.round && m.club) s.range_club = club_for_delivery(s.assets, *m.club, m.ball->vla_deg);
  const std::string club = s.round ? club_before : s.range_club;

  nlohmann::json line;
  line["shot_number"] = m.shot_number;
  line["session_shot"] = ++s.session_shots;
  line["device"] = m.device_id;
  line["club"] = club;
  ShotResult r;
  if (s.round) {
    GolfRound& round = *s.round;
    const int hole = round.hole().number;
    const StrokeRecord& rec = round.play_launch(club, numbers, &r);
    int hole_strokes = 0;
    for (const HoleCard& h : round.card())
      if (h.number == hole) hole_strokes = h.strokes;
    line["mode"] = "round";
    line["course"] = round.course().name;
    line["hole"] = hole;
    line["lie"] = rec.lie;
    line["end"] = to_string(rec.end);
    line["to_pin_m"] = rec.to_pin_m;
    line["hole_strokes"] = hole_strokes;
    for (const HoleCard& h : round.card())
      if (h.number == hole && h.picked_up) line["picked_up"] = true;
    if (!round.finished()) {
      // What the device is told next (the 201): the hole and club to play and the distance.
      line["next_hole"] = round.hole().number;
      line["next_club"] = s.club();
      line["next_to_pin_m"] = round.to_pin();
    }
    if (round.finished()) {
      line["round_over"] = true;
      line["round_strokes"] = round.total_strokes();
      line["round_par"] = round.total_par();
      p.round_over = true;
      ++s.rounds_done;
      s.new_round();
    }
  } else {
    r = run_shot(resolve(s.range_spec(numbers), s.assets), "range", {true, record_samples});
    line["mode"] = "range";
  }
  const nlohmann::json shot = shot_json(r);
  line["world"] = r.world;
  line["launch"] = shot["launch"];
  line["flight"] = shot["flight"];
  // Right (+) or left of the line the shot was aimed on, at landing: what a golfer calls the
  // miss (the flight's lateral_m is along the world's axis, which a hole may not follow).
  line["side_m"] = side_of_aim(r, r.trajectory.summary.landing_position);
  if (shot.contains("warnings")) line["warnings"] = shot["warnings"];
  if (m.club) {
    line["club_data"] = club_data_json(*m.club);
    try {
      if (const auto model = predict_from_club_data(s.assets, club, *m.club)) {
        const LaunchMetrics& d = r.launch;
        const LaunchMetrics& e = model->launch;
        line["model"] = {
            {"club", club},
            {"launch", launch_json(e, model->smash_factor)},
            // Model minus device: how far our impact model is from what the device measured.
            {"difference",
             {{"ball_speed_mps", e.ball_speed - d.ball_speed},
              {"vertical_angle_deg", (e.vertical_angle - d.vertical_angle) * kDegPerRad},
              {"horizontal_angle_deg", (e.horizontal_angle - d.horizontal_angle) * kDegPerRad},
              {"spin_rpm", radps_to_rpm(e.spin.total - d.spin.total)},
              {"spin_axis_deg", (e.spin.axis_rad - d.spin.axis_rad) * kDegPerRad}}},
        };
      }
    } catch (const InputError& e) {
      line["model_error"] = e.what();
    }
  }
  p.line = std::move(line);
  p.flown = true;
  // In a round every shot changes what the device must be told (the distance, often the hole
  // and club): the 201 goes after each; on the range only when the club changes.
  p.club_changed = s.round != nullptr || s.club() != club_before || p.round_over;
  p.result = std::move(r);
  return p;
}

}  // namespace sweetspot
