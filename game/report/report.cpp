// Report writers. Display conversions happen here and only here.
#include "game/report/report.hpp"

#include "game/report/metrics.hpp"

#include <cstdio>
#include <vector>

#include "game/report/flight_json.hpp"
#include "game/report/metrics.hpp"
#include "physics/error.hpp"
#include "physics/math.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr double kDegPerRad = 180.0 / kPi;

}  // namespace

DisplayUnits display_units(const SportProfile& sport, UnitSystem units) { return DisplayUnits{units, sport.distance_unit}; }

void check_metric_ids(const SportProfile& sport) {
  for (const char* key : {"report", "csv"}) {
    for (const std::string& id : std::string_view(key) == "report" ? sport.report : sport.csv) {
      if (find_metric(id) != nullptr) continue;
      const auto at = sport.source.find(key);
      throw InputError((at != sport.source.end() ? at->second : std::string("sports.toml")) + ": " + key +
                       ": unknown launch-monitor metric '" + id + "' (allowed: " + metric_ids() + ")");
    }
  }
}

std::string launch_table(const ShotResult& r, const SportProfile& sport, UnitSystem units) {
  check_metric_ids(sport);
  std::string title = r.scenario;
  if (r.impact.present) title += "  (" + (r.club.club.empty() ? r.bat.bat : r.club.club) + ")";
  std::string table = metric_table(title, sport.report, r, display_units(sport, units));
  for (const std::string& w : r.warnings) table += "  warning: " + w + "\n";
  return table;
}

nlohmann::json shot_json(const ShotResult& r) {
  using nlohmann::json;
  const auto& L = r.launch;
  json j;
  j["scenario"] = r.scenario;
  j["sport"] = r.sport;
  if (!r.world.empty()) j["world"] = r.world;
  // The launch and flight objects are shared with `flight --json` (game/report/flight_json).
  j["launch"] = launch_json(L, r.impact.present ? r.smash_factor : -1.0);
  j["launch"]["rifle_spin_rpm"] = radps_to_rpm(L.spin.rifle);
  if (r.impact.present) {
    const auto& i = r.impact;
    j["impact"] = {
        {"e", i.e},
        {"e_t", i.e_t},
        {"e_t_nominal", i.e_t_nominal},
        {"mu", i.mu},
        {"friction", to_string(i.friction)},
        {"contact", to_string(i.contact)},
        {"normal_impulse_Ns", i.normal_impulse},
        {"tangential_impulse_Ns", i.tangential_impulse},
        {"energy_loss_J", i.energy_loss},
    };
    if (i.mu_grip >= 0.0) {
      j["impact"]["mu_grip"] = i.mu_grip;
      j["impact"]["grips"] = i.mu >= i.mu_grip;
    }
    if (!r.club.club.empty()) {
      j["club"] = {
          {"name", r.club.club},
          {"speed_mps", r.club.speed},
          {"attack_angle_deg", r.club.attack_angle * kDegPerRad},
          {"path_deg", r.club.path * kDegPerRad},
          {"face_angle_deg", r.club.face_to_target * kDegPerRad},
          {"strike_face_angle_deg", r.club.strike_face_angle * kDegPerRad},
          {"dynamic_loft_deg", r.club.dynamic_loft * kDegPerRad},
          {"strike_loft_deg", r.club.strike_loft * kDegPerRad},
          {"spin_loft_deg", r.club.spin_loft * kDegPerRad},
          {"impact_offset_m", {r.club.impact_toe, r.club.impact_up}},
      };
      if (!r.lie.empty()) j["club"]["lie"] = r.lie;
      if (r.club.sand_entry > 0.0) j["club"]["sand_entry_m"] = r.club.sand_entry;
    } else if (!r.bat.bat.empty()) {
      j["bat"] = {
          {"name", r.bat.bat},
          {"speed_mps", r.bat.speed},
          {"attack_angle_deg", r.bat.attack_angle * kDegPerRad},
          {"direction_deg", r.bat.direction * kDegPerRad},
          {"undercut_m", r.bat.undercut},
          {"pitch_speed_mps", r.bat.pitch_speed},
          {"collision_efficiency", collision_efficiency(r)},
      };
    }
  }
  j["flight"] = flight_json(r.trajectory.summary);
  j["flight"]["end"] = to_string(r.end);
  // TrackMan's Side / Side Total: from the target line, not the world axis (lateral_m).
  j["flight"]["side_m"] = side_of_aim(r, r.trajectory.summary.landing_position);
  j["flight"]["side_total_m"] = side_of_aim(r, r.trajectory.summary.rest_position);
  if (!r.warnings.empty()) j["warnings"] = r.warnings;
  return j;
}

std::string json_text(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json gspro_json(const ShotResult& r, int shot_number) {
  using nlohmann::json;
  const auto& L = r.launch;
  const bool club = r.impact.present && !r.club.club.empty();
  json j;
  j["DeviceID"] = "Sweetspot 0.1";
  j["Units"] = "Yards";
  j["ShotNumber"] = shot_number;
  j["APIversion"] = "1";
  j["BallData"] = {
      {"Speed", mps_to_mph(L.ball_speed)},
      {"SpinAxis", L.spin.axis_rad * kDegPerRad},
      {"TotalSpin", radps_to_rpm(L.spin.total)},
      {"BackSpin", radps_to_rpm(L.spin.backspin)},
      {"SideSpin", radps_to_rpm(L.spin.sidespin_right)},
      {"HLA", L.horizontal_angle * kDegPerRad},
      {"VLA", L.vertical_angle * kDegPerRad},
      {"CarryDistance", m_to_yd(r.trajectory.summary.carry_m)},
  };
  const auto& c = r.club;
  j["ClubData"] = {
      {"Speed", club ? mps_to_mph(c.speed) : 0.0},
      {"AngleOfAttack", club ? c.attack_angle * kDegPerRad : 0.0},
      // A launch monitor's face angle and loft are the face's where it meets the ball
      // (TrackMan's definitions), as predict_from_club_data reads them back.
      {"FaceToTarget", club ? c.strike_face_angle * kDegPerRad : 0.0},
      {"Lie", club ? c.lie * kDegPerRad : 0.0},
      {"Loft", club ? c.strike_loft * kDegPerRad : 0.0},
      {"Path", club ? c.path * kDegPerRad : 0.0},
      {"SpeedAtImpact", club ? mps_to_mph(c.speed_at_impact) : 0.0},
      {"VerticalFaceImpact", club ? c.impact_up * 1000.0 : 0.0},
      {"HorizontalFaceImpact", club ? c.impact_toe * 1000.0 : 0.0},
      {"ClosureRate", club ? c.closure_rate * kDegPerRad : 0.0},
  };
  j["ShotDataOptions"] = {
      {"ContainsBallData", true},
      {"ContainsClubData", club},
      {"LaunchMonitorIsReady", true},
      {"LaunchMonitorBallDetected", true},
      {"IsHeartBeat", false},
  };
  return j;
}

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (const char ch : text) {
    if (ch == '"') out += '"';
    out += ch;
  }
  out += '"';
  return out;
}

namespace {

const Metric& metric(const std::string& id) {
  const Metric* m = find_metric(id);
  if (m == nullptr) throw InputError("unknown CSV metric '" + id + "' (allowed: " + metric_ids() + ")");
  return *m;
}

}  // namespace

std::string csv_header(const SportProfile& sport, UnitSystem units) {
  check_metric_ids(sport);
  const DisplayUnits u = display_units(sport, units);
  std::string out;
  for (const std::string& id : sport.csv) {
    if (!out.empty()) out += ',';
    out += csv_field(metric(id).csv_name(u));
  }
  return out + "\n";
}

std::string csv_row(const ShotResult& r, const SportProfile& sport, UnitSystem units) {
  const DisplayUnits u = display_units(sport, units);
  std::string out;
  bool first = true;
  for (const std::string& id : sport.csv) {
    if (!first) out += ',';
    first = false;
    out += csv_field(metric(id).csv_value(r, u));
  }
  return out + "\n";
}

}  // namespace sweetspot
