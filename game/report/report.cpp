// Report writers. Display conversions happen here and only here.
#include "game/report/report.hpp"

#include <cstdio>
#include <vector>

#include "game/report/flight_json.hpp"
#include "physics/error.hpp"
#include "physics/math.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr double kDegPerRad = 180.0 / kPi;

std::string fixed(double v, int decimals) {
  if (std::fabs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;  // no "-0.0"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

struct Units {
  bool imperial;
  std::string speed_unit() const { return imperial ? "mph" : "m/s"; }
  double speed(double mps) const { return imperial ? mps_to_mph(mps) : mps; }
  std::string dist_unit() const { return imperial ? "yd" : "m"; }
  double dist(double m) const { return imperial ? m_to_yd(m) : m; }
  std::string short_unit() const { return imperial ? "ft" : "m"; }
  double short_dist(double m) const { return imperial ? m_to_ft(m) : m; }
};

using Rows = std::vector<std::pair<std::string, std::string>>;

std::string render(const std::string& title, const Rows& rows) {
  std::string out = title + "\n";
  for (const auto& [label, value] : rows) {
    std::string line = "  " + label;
    if (line.size() < 22) line.append(22 - line.size(), ' ');
    out += line + value + "\n";
  }
  return out;
}

std::string deg(double rad, int decimals = 1) { return fixed(rad * kDegPerRad, decimals) + " deg"; }
std::string rpm(double radps) { return fixed(radps_to_rpm(radps), 0) + " rpm"; }

void impact_rows(const ShotResult& r, Rows& rows) {
  if (!r.impact.present) return;
  const auto& i = r.impact;
  rows.emplace_back("Impact model", std::string(to_string(i.friction)) + ", " + to_string(i.contact));
  rows.emplace_back("Restitution e / e_t", fixed(i.e, 3) + " / " + fixed(i.e_t, 3));
  rows.emplace_back("Friction mu", fixed(i.mu, 3));
  rows.emplace_back("Impulse n / t", fixed(i.normal_impulse, 3) + " / " + fixed(i.tangential_impulse, 3) + " N*s");
  rows.emplace_back("Energy lost", fixed(i.energy_loss, 1) + " J");
}

std::string golf_table(const ShotResult& r, const Units& u) {
  const auto& L = r.launch;
  const auto& F = r.trajectory.summary;
  Rows rows;
  if (r.impact.present) rows.emplace_back("Club speed", fixed(u.speed(r.club.speed), 1) + " " + u.speed_unit());
  rows.emplace_back("Ball speed", fixed(u.speed(L.ball_speed), 1) + " " + u.speed_unit());
  if (r.impact.present) rows.emplace_back("Smash factor", fixed(r.smash_factor, 2));
  rows.emplace_back("Launch angle", deg(L.vertical_angle));
  rows.emplace_back("Launch direction", deg(L.horizontal_angle) + " (+ right)");
  rows.emplace_back("Spin rate", rpm(L.spin.total));
  rows.emplace_back("Backspin / sidespin",
                    fixed(radps_to_rpm(L.spin.backspin), 0) + " / " + fixed(radps_to_rpm(L.spin.sidespin_right), 0) + " rpm");
  rows.emplace_back("Spin axis", deg(L.spin.axis_rad) + " (+ right)");
  if (r.impact.present) {
    rows.emplace_back("Attack angle", deg(r.club.attack_angle));
    rows.emplace_back("Club path", deg(r.club.path) + " (+ in-to-out)");
    rows.emplace_back("Face angle", deg(r.club.face_to_target) + " (+ open)");
    rows.emplace_back("Dynamic loft", deg(r.club.dynamic_loft));
    rows.emplace_back("Spin loft", deg(r.club.dynamic_loft - r.club.attack_angle));
    rows.emplace_back("Impact point", fixed(r.club.impact_toe * 1000.0, 0) + " mm toe, " +
                                          fixed(r.club.impact_up * 1000.0, 0) + " mm up");
  }
  rows.emplace_back("Carry", fixed(u.dist(F.carry_m), 1) + " " + u.dist_unit());
  rows.emplace_back("Total", fixed(u.dist(F.total_m), 1) + " " + u.dist_unit());
  rows.emplace_back("Max height", fixed(u.dist(F.apex_m), 1) + " " + u.dist_unit());
  rows.emplace_back("Landing angle", deg(F.landing_angle_deg / kDegPerRad));
  rows.emplace_back("Hang time", fixed(F.hang_time_s, 2) + " s");
  rows.emplace_back("Lateral", fixed(u.dist(F.lateral_m), 1) + " " + u.dist_unit() + " (+ right)");
  rows.emplace_back("End", to_string(F.end));
  impact_rows(r, rows);
  std::string title = r.scenario;
  if (r.impact.present) title += "  (" + r.club.club + ")";
  return render(title, rows);
}

std::string baseball_table(const ShotResult& r, const Units& u) {
  const auto& L = r.launch;
  const auto& F = r.trajectory.summary;
  Rows rows;
  rows.emplace_back("Exit velocity", fixed(u.speed(L.ball_speed), 1) + " " + u.speed_unit());
  rows.emplace_back("Launch angle", deg(L.vertical_angle));
  rows.emplace_back("Spray angle", deg(L.horizontal_angle) + " (+ right field)");
  rows.emplace_back("Spin rate", rpm(L.spin.total));
  rows.emplace_back("Backspin / sidespin",
                    fixed(radps_to_rpm(L.spin.backspin), 0) + " / " + fixed(radps_to_rpm(L.spin.sidespin_right), 0) + " rpm");
  if (r.impact.present) {
    rows.emplace_back("Bat speed", fixed(u.speed(r.bat.speed), 1) + " " + u.speed_unit());
    rows.emplace_back("Smash factor", fixed(r.smash_factor, 2));
    rows.emplace_back("Pitch speed", fixed(u.speed(r.bat.pitch_speed), 1) + " " + u.speed_unit());
    rows.emplace_back("Swing plane", deg(r.bat.attack_angle));
    rows.emplace_back("Swing direction", deg(r.bat.direction) + " (+ right field)");
    rows.emplace_back("Undercut", fixed(r.bat.undercut * 1000.0, 1) + " mm");
  }
  rows.emplace_back("Distance", fixed(u.short_dist(F.carry_m), 0) + " " + u.short_unit());
  rows.emplace_back("Max height", fixed(u.short_dist(F.apex_m), 0) + " " + u.short_unit());
  rows.emplace_back("Hang time", fixed(F.hang_time_s, 2) + " s");
  rows.emplace_back("Landing angle", deg(F.landing_angle_deg / kDegPerRad));
  rows.emplace_back("End", to_string(F.end));
  impact_rows(r, rows);
  std::string title = r.scenario;
  if (r.impact.present) title += "  (" + r.bat.bat + ")";
  return render(title, rows);
}

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", std::fabs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

}  // namespace

UnitSystem parse_unit_system(std::string_view text, std::string_view flag) {
  if (text == "imperial") return UnitSystem::Imperial;
  if (text == "metric") return UnitSystem::Metric;
  throw InputError(std::string(flag) + " " + std::string(text) + ": unknown unit system; allowed: imperial, metric");
}

std::string launch_table(const ShotResult& r, UnitSystem units) {
  const Units u{units == UnitSystem::Imperial};
  return r.sport == Sport::Golf ? golf_table(r, u) : baseball_table(r, u);
}

nlohmann::json shot_json(const ShotResult& r) {
  using nlohmann::json;
  const auto& L = r.launch;
  json j;
  j["scenario"] = r.scenario;
  j["sport"] = to_string(r.sport);
  if (!r.world.empty()) j["world"] = r.world;
  // The launch and flight objects are shared with `flight --json` (game/report/flight_json).
  j["launch"] = launch_json(L, r.impact.present ? r.smash_factor : -1.0);
  j["launch"]["rifle_spin_rpm"] = radps_to_rpm(L.spin.rifle);
  if (r.impact.present) {
    const auto& i = r.impact;
    j["impact"] = {
        {"e", i.e},
        {"e_t", i.e_t},
        {"mu", i.mu},
        {"friction", to_string(i.friction)},
        {"contact", to_string(i.contact)},
        {"normal_impulse_Ns", i.normal_impulse},
        {"tangential_impulse_Ns", i.tangential_impulse},
        {"energy_loss_J", i.energy_loss},
    };
    if (r.sport == Sport::Golf) {
      j["club"] = {
          {"name", r.club.club},
          {"speed_mps", r.club.speed},
          {"attack_angle_deg", r.club.attack_angle * kDegPerRad},
          {"path_deg", r.club.path * kDegPerRad},
          {"face_angle_deg", r.club.face_to_target * kDegPerRad},
          {"dynamic_loft_deg", r.club.dynamic_loft * kDegPerRad},
          {"impact_offset_m", {r.club.impact_toe, r.club.impact_up}},
      };
    } else {
      j["bat"] = {
          {"name", r.bat.bat},
          {"speed_mps", r.bat.speed},
          {"attack_angle_deg", r.bat.attack_angle * kDegPerRad},
          {"direction_deg", r.bat.direction * kDegPerRad},
          {"undercut_m", r.bat.undercut},
          {"pitch_speed_mps", r.bat.pitch_speed},
      };
    }
  }
  j["flight"] = flight_json(r.trajectory.summary);
  return j;
}

nlohmann::json gspro_json(const ShotResult& r, int shot_number) {
  using nlohmann::json;
  const auto& L = r.launch;
  const bool club = r.impact.present && r.sport == Sport::Golf;
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
      {"FaceToTarget", club ? c.face_to_target * kDegPerRad : 0.0},
      {"Lie", club ? c.lie * kDegPerRad : 0.0},
      {"Loft", club ? c.dynamic_loft * kDegPerRad : 0.0},
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

std::string csv_header(Sport sport, UnitSystem units) {
  if (sport == Sport::Baseball) {
    // Statcast: launch_speed mph, launch_angle deg, hit_distance_sc ft, bat_speed mph,
    // release_speed / release_spin_rate of the pitch. spray_angle and the spin columns are
    // not in Statcast's CSV and use Statcast-style names. Always imperial, like Statcast.
    return "scenario,launch_speed,launch_angle,spray_angle,launch_spin_rate,hit_distance_sc,"
           "apex_ft,hang_time,bat_speed,release_speed,release_spin_rate,end\n";
  }
  if (units == UnitSystem::Imperial) {
    return "scenario,club,club_speed_mph,ball_speed_mph,smash_factor,launch_angle_deg,launch_direction_deg,"
           "spin_rpm,backspin_rpm,sidespin_rpm,spin_axis_deg,carry_yd,total_yd,apex_yd,landing_angle_deg,"
           "hang_time_s,lateral_yd,e,mu,friction,contact,end\n";
  }
  return "scenario,club,club_speed_mps,ball_speed_mps,smash_factor,launch_angle_deg,launch_direction_deg,"
         "spin_rpm,backspin_rpm,sidespin_rpm,spin_axis_deg,carry_m,total_m,apex_m,landing_angle_deg,"
         "hang_time_s,lateral_m,e,mu,friction,contact,end\n";
}

std::string csv_row(const ShotResult& r, UnitSystem units) {
  const auto& L = r.launch;
  const auto& F = r.trajectory.summary;
  std::vector<std::string> f;
  f.push_back(csv_field(r.scenario));
  if (r.sport == Sport::Baseball) {
    f.push_back(num(mps_to_mph(L.ball_speed)));
    f.push_back(num(L.vertical_angle * kDegPerRad));
    f.push_back(num(L.horizontal_angle * kDegPerRad));
    f.push_back(num(radps_to_rpm(L.spin.total)));
    f.push_back(num(m_to_ft(F.carry_m)));
    f.push_back(num(m_to_ft(F.apex_m)));
    f.push_back(num(F.hang_time_s));
    f.push_back(r.impact.present ? num(mps_to_mph(r.bat.speed)) : "");
    f.push_back(r.impact.present ? num(mps_to_mph(r.bat.pitch_speed)) : "");
    f.push_back(r.impact.present ? num(radps_to_rpm(r.bat.pitch_spin)) : "");
    f.push_back(to_string(F.end));
  } else {
    const Units u{units == UnitSystem::Imperial};
    f.push_back(csv_field(r.club.club));
    f.push_back(r.impact.present ? num(u.speed(r.club.speed)) : "");
    f.push_back(num(u.speed(L.ball_speed)));
    f.push_back(r.impact.present ? num(r.smash_factor) : "");
    f.push_back(num(L.vertical_angle * kDegPerRad));
    f.push_back(num(L.horizontal_angle * kDegPerRad));
    f.push_back(num(radps_to_rpm(L.spin.total)));
    f.push_back(num(radps_to_rpm(L.spin.backspin)));
    f.push_back(num(radps_to_rpm(L.spin.sidespin_right)));
    f.push_back(num(L.spin.axis_rad * kDegPerRad));
    f.push_back(num(u.dist(F.carry_m)));
    f.push_back(num(u.dist(F.total_m)));
    f.push_back(num(u.dist(F.apex_m)));
    f.push_back(num(F.landing_angle_deg));
    f.push_back(num(F.hang_time_s));
    f.push_back(num(u.dist(F.lateral_m)));
    f.push_back(r.impact.present ? num(r.impact.e) : "");
    f.push_back(r.impact.present ? num(r.impact.mu) : "");
    f.push_back(r.impact.present ? to_string(r.impact.friction) : "");
    f.push_back(r.impact.present ? to_string(r.impact.contact) : "");
    f.push_back(to_string(F.end));
  }
  std::string out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i > 0) out += ',';
    out += f[i];
  }
  out += '\n';
  return out;
}

}  // namespace sweetspot
