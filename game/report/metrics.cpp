// The metric registry. Display conversions happen here and in the other report writers only.
#include "game/report/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/error.hpp"
#include "physics/math.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr double kDeg = 180.0 / kPi;

std::string fixed(double v, int decimals) {
  if (std::fabs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;  // no "-0.0"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", std::fabs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

using Show = std::function<std::optional<std::string>(const ShotResult&, const DisplayUnits&)>;
using Number = std::function<std::optional<double>(const ShotResult&, const DisplayUnits&)>;

bool struck(const ShotResult& r) { return r.impact.present; }
bool club(const ShotResult& r) { return r.impact.present && !r.club.club.empty(); }
bool bat(const ShotResult& r) { return r.impact.present && !r.bat.bat.empty(); }

// Builders for the common shapes of a metric.
Metric speed(std::string_view id, std::string_view label, std::string_view csv, std::function<bool(const ShotResult&)> has,
             std::function<double(const ShotResult&)> mps, std::string_view expect = "") {
  Metric m;
  m.id = id;
  m.label = label;
  m.number = [=](const ShotResult& r, const DisplayUnits& u) -> std::optional<double> {
    if (!has(r)) return std::nullopt;
    return u.speed(mps(r));
  };
  m.show = [n = m.number](const ShotResult& r, const DisplayUnits& u) -> std::optional<std::string> {
    const auto v = n(r, u);
    if (!v) return std::nullopt;
    return fixed(*v, 1) + " " + u.speed_unit();
  };
  m.csv_name = [=](const DisplayUnits& u) { return std::string(csv) + (u.imperial() ? "_mph" : "_mps"); };
  m.csv_value = [n = m.number](const ShotResult& r, const DisplayUnits& u) {
    const auto v = n(r, u);
    return v ? num(*v) : std::string();
  };
  m.expect = expect;
  return m;
}

Metric distance(std::string_view id, std::string_view label, std::string_view csv,
                std::function<double(const ShotResult&)> metres, std::string_view expect = "", int decimals = 1) {
  Metric m;
  m.id = id;
  m.label = label;
  m.number = [=](const ShotResult& r, const DisplayUnits& u) -> std::optional<double> { return u.dist(metres(r)); };
  m.show = [=](const ShotResult& r, const DisplayUnits& u) -> std::optional<std::string> {
    return fixed(u.dist(metres(r)), decimals) + " " + u.distance_unit();
  };
  m.csv_name = [=](const DisplayUnits& u) { return std::string(csv) + "_" + u.distance_unit(); };
  m.csv_value = [=](const ShotResult& r, const DisplayUnits& u) { return num(u.dist(metres(r))); };
  m.expect = expect;
  return m;
}

Metric angle(std::string_view id, std::string_view label, std::string_view csv, std::function<bool(const ShotResult&)> has,
             std::function<double(const ShotResult&)> rad, std::string_view note = "", std::string_view expect = "") {
  Metric m;
  m.id = id;
  m.label = label;
  m.number = [=](const ShotResult& r, const DisplayUnits&) -> std::optional<double> {
    if (!has(r)) return std::nullopt;
    return rad(r) * kDeg;
  };
  m.show = [=](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!has(r)) return std::nullopt;
    std::string out = fixed(rad(r) * kDeg, 1) + " deg";
    if (!note.empty()) out.append(" ").append(note);
    return out;
  };
  m.csv_name = [=](const DisplayUnits&) { return std::string(csv) + "_deg"; };
  m.csv_value = [=](const ShotResult& r, const DisplayUnits&) { return has(r) ? num(rad(r) * kDeg) : std::string(); };
  m.expect = expect;
  return m;
}

Metric spin(std::string_view id, std::string_view label, std::string_view csv, std::function<double(const ShotResult&)> radps,
            std::string_view expect = "") {
  Metric m;
  m.id = id;
  m.label = label;
  m.number = [=](const ShotResult& r, const DisplayUnits&) -> std::optional<double> { return radps_to_rpm(radps(r)); };
  m.show = [=](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    return fixed(radps_to_rpm(radps(r)), 0) + " rpm";
  };
  m.csv_name = [=](const DisplayUnits&) { return std::string(csv); };
  m.csv_value = [=](const ShotResult& r, const DisplayUnits&) { return num(radps_to_rpm(radps(r))); };
  m.expect = expect;
  return m;
}

Metric text(std::string_view id, std::string_view label, Show show, std::string_view csv = "") {
  Metric m;
  m.id = id;
  m.label = label;
  m.show = show;
  m.number = [](const ShotResult&, const DisplayUnits&) -> std::optional<double> { return std::nullopt; };
  m.csv_name = [=](const DisplayUnits&) { return std::string(csv.empty() ? id : csv); };
  m.csv_value = [show](const ShotResult& r, const DisplayUnits& u) { return show(r, u).value_or(""); };
  return m;
}

Metric plain(std::string_view id, std::string_view label, std::function<bool(const ShotResult&)> has,
             std::function<double(const ShotResult&)> value, int decimals, std::string_view unit, std::string_view csv,
             std::string_view expect = "") {
  Metric m;
  m.id = id;
  m.label = label;
  m.number = [=](const ShotResult& r, const DisplayUnits&) -> std::optional<double> {
    if (!has(r)) return std::nullopt;
    return value(r);
  };
  m.show = [=](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!has(r)) return std::nullopt;
    std::string out = fixed(value(r), decimals);
    if (!unit.empty()) out.append(" ").append(unit);
    return out;
  };
  m.csv_name = [=](const DisplayUnits&) { return std::string(csv); };
  m.csv_value = [=](const ShotResult& r, const DisplayUnits&) { return has(r) ? num(value(r)) : std::string(); };
  m.expect = expect;
  return m;
}

// Statcast columns: Statcast's names and units (mph, ft) in imperial; with --units metric
// the speed and distance columns are SI and say so in their name (launch_speed_mps,
// hit_distance_sc_m). Angles, rpm and seconds are the same in both.
enum class StatcastKind { Speed, Distance, Same };

Metric statcast(std::string_view id, std::string_view column, std::function<bool(const ShotResult&)> has,
                StatcastKind kind, std::function<double(const ShotResult&)> si) {
  Metric m;
  m.id = id;
  m.label = column;
  m.number = [=](const ShotResult& r, const DisplayUnits& u) -> std::optional<double> {
    if (!has(r)) return std::nullopt;
    const double v = si(r);
    switch (kind) {
      case StatcastKind::Speed: return u.imperial() ? mps_to_mph(v) : v;
      case StatcastKind::Distance: return u.imperial() ? m_to_ft(v) : v;
      case StatcastKind::Same: break;
    }
    return v;
  };
  m.show = [n = m.number](const ShotResult& r, const DisplayUnits& u) -> std::optional<std::string> {
    const auto v = n(r, u);
    if (!v) return std::nullopt;
    return num(*v);
  };
  m.csv_name = [=](const DisplayUnits& u) {
    std::string name(column);
    if (u.imperial() || kind == StatcastKind::Same) return name;
    if (name.size() > 3 && name.compare(name.size() - 3, 3, "_ft") == 0) name.resize(name.size() - 3);
    return name + (kind == StatcastKind::Speed ? "_mps" : "_m");
  };
  m.csv_value = [n = m.number](const ShotResult& r, const DisplayUnits& u) {
    const auto v = n(r, u);
    return v ? num(*v) : std::string();
  };
  return m;
}

const auto always = [](const ShotResult&) { return true; };



std::vector<Metric> build() {
  std::vector<Metric> m;
  // ---- launch ------------------------------------------------------------------------
  {
    // The swing's speed, and where a lie (sand, rough) took some of it before the face met the
    // ball, the speed it met the ball at: the one the smash factor divides by.
    Metric cs = speed("club_speed", "Club speed", "club_speed", club, [](const ShotResult& r) { return r.club.speed; });
    cs.show = [base = cs.show](const ShotResult& r, const DisplayUnits& u) -> std::optional<std::string> {
      auto out = base(r, u);
      if (out && !r.lie.empty() && r.club.speed_at_impact > 0.0 && r.club.speed_at_impact < 0.99 * r.club.speed)
        *out += ", " + fixed(u.speed(r.club.speed_at_impact), 1) + " at the ball (the " + r.lie + " took the rest)";
      return out;
    };
    m.push_back(cs);
  }
  m.push_back(speed("ball_speed", "Ball speed", "ball_speed", always,
                    [](const ShotResult& r) { return r.launch.ball_speed; }, "ball_speed"));
  m.push_back(speed("exit_velocity", "Exit velocity", "exit_velocity", always,
                    [](const ShotResult& r) { return r.launch.ball_speed; }, "ball_speed"));
  m.push_back(plain("smash_factor", "Smash factor", struck, [](const ShotResult& r) { return r.smash_factor; }, 2, "",
                    "smash_factor", "smash_factor"));
  m.push_back(angle("launch_angle", "Launch angle", "vertical_angle", always,
                    [](const ShotResult& r) { return r.launch.vertical_angle; }, "", "vertical_angle"));
  m.push_back(angle("launch_direction", "Launch direction", "horizontal_angle", always,
                    [](const ShotResult& r) { return r.launch.horizontal_angle; }, "(+ right)", "horizontal_angle"));
  m.push_back(angle("spray_angle", "Spray angle", "spray_angle", always,
                    [](const ShotResult& r) { return r.launch.horizontal_angle; }, "(+ right field)", "horizontal_angle"));
  m.push_back(spin("spin_rate", "Spin rate", "spin_rpm", [](const ShotResult& r) { return r.launch.spin.total; }, "spin"));
  m.push_back(spin("backspin", "Backspin", "backspin_rpm", [](const ShotResult& r) { return r.launch.spin.backspin; },
                   "backspin"));
  m.push_back(spin("sidespin", "Sidespin", "sidespin_rpm",
                   [](const ShotResult& r) { return r.launch.spin.sidespin_right; }, "sidespin"));
  m.push_back(text("back_side_spin", "Backspin / sidespin", [](const ShotResult& r, const DisplayUnits&) {
    return std::optional<std::string>(fixed(radps_to_rpm(r.launch.spin.backspin), 0) + " / " +
                                      fixed(radps_to_rpm(r.launch.spin.sidespin_right), 0) + " rpm");
  }));
  m.push_back(angle("spin_axis", "Spin axis", "spin_axis", always, [](const ShotResult& r) { return r.launch.spin.axis_rad; },
                    "(+ right)", "spin_axis"));
  // ---- club delivery -----------------------------------------------------------------
  m.push_back(angle("attack_angle", "Attack angle", "attack_angle", club, [](const ShotResult& r) { return r.club.attack_angle; }));
  m.push_back(angle("club_path", "Club path", "club_path", club, [](const ShotResult& r) { return r.club.path; },
                    "(+ in-to-out)"));
  // As a launch monitor reports them: the face angle and loft where the face meets the ball
  // (a toe strike on a driver's bulged face opens it ~2°, a high strike on its roll adds ~2°
  // of loft), and the 3D angle between the head's direction and that face.
  m.push_back(angle("face_angle", "Face angle", "face_angle", club,
                    [](const ShotResult& r) { return r.club.strike_face_angle; }, "(+ open)"));
  m.push_back(angle("dynamic_loft", "Dynamic loft", "dynamic_loft", club, [](const ShotResult& r) { return r.club.strike_loft; }));
  m.push_back(angle("spin_loft", "Spin loft", "spin_loft", club, [](const ShotResult& r) { return r.club.spin_loft; }));
  m.push_back(text("impact_point", "Impact point", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!club(r)) return std::nullopt;
    return fixed(r.club.impact_toe * 1000.0, 0) + " mm toe, " + fixed(r.club.impact_up * 1000.0, 0) + " mm up";
  }));
  m.push_back(text("club", "Club", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!club(r)) return std::nullopt;
    return r.club.club;
  }));
  // ---- bat delivery ------------------------------------------------------------------
  m.push_back(speed("bat_speed", "Bat speed", "bat_speed", bat, [](const ShotResult& r) { return r.bat.speed; }));
  m.push_back(speed("pitch_speed", "Pitch speed", "pitch_speed", bat, [](const ShotResult& r) { return r.bat.pitch_speed; }));
  // The batting convention (Nathan, "The Physics of Baseball"; Statcast's "collision
  // efficiency"): q = (EV − bat)/(pitch + bat), so EV = q·pitch + (1 + q)·bat; a
  // golf-style exit/bat speed ratio mixes the pitch's speed into the bat's.
  m.push_back(plain("collision_efficiency", "Collision efficiency q", bat, collision_efficiency, 3, "",
                    "collision_efficiency"));
  // Statcast's bat-tracking words (2024): attack angle and attack direction; the JSON says
  // bat.attack_angle_deg and bat.direction_deg.
  m.push_back(angle("swing_plane", "Attack angle", "attack_angle", bat, [](const ShotResult& r) { return r.bat.attack_angle; }));
  m.push_back(angle("swing_direction", "Attack direction", "attack_direction", bat,
                    [](const ShotResult& r) { return r.bat.direction; }, "(+ right field)"));
  m.push_back(plain("undercut", "Undercut", bat, [](const ShotResult& r) { return r.bat.undercut * 1000.0; }, 1, "mm",
                    "undercut_mm"));
  m.push_back(text("bat", "Bat", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!bat(r)) return std::nullopt;
    return r.bat.bat;
  }));
  // ---- flight ------------------------------------------------------------------------
  m.push_back(distance("carry", "Carry", "carry", [](const ShotResult& r) { return r.trajectory.summary.carry_m; }, "carry"));
  // Shown to the same tenth as Total: a home run that lands out of the park has the two equal,
  // and "427 ft" above "426.7 ft" read as two different balls.
  m.push_back(distance("distance", "Distance", "distance", [](const ShotResult& r) { return r.trajectory.summary.carry_m; },
                       "carry"));
  m.push_back(distance("total", "Total", "total", [](const ShotResult& r) { return r.trajectory.summary.total_m; }, "total"));
  m.push_back(distance("max_height", "Max height", "apex", [](const ShotResult& r) { return r.trajectory.summary.apex_m; },
                       "apex"));
  m.push_back(angle("landing_angle", "Landing angle", "landing_angle", always,
                    [](const ShotResult& r) { return r.trajectory.summary.landing_angle_deg / kDeg; }, "", "landing_angle"));
  m.push_back(plain("hang_time", "Hang time", always, [](const ShotResult& r) { return r.trajectory.summary.hang_time_s; }, 2,
                    "s", "hang_time_s", "hang_time"));
  m.push_back(distance("lateral", "Lateral", "lateral", [](const ShotResult& r) { return r.trajectory.summary.lateral_m; },
                       "lateral"));
  // TrackMan's Side and Side Total: metres right (+) of the target line at landing and at rest.
  m.push_back(distance("side", "Side", "side", [](const ShotResult& r) { return side_of_aim(r, r.trajectory.summary.landing_position); },
                       "", 1));
  m.push_back(distance("side_total", "Side total", "side_total",
                       [](const ShotResult& r) { return side_of_aim(r, r.trajectory.summary.rest_position); }, "", 1));
  m.push_back(text("end", "End", [](const ShotResult& r, const DisplayUnits&) {
    return std::optional<std::string>(to_string(r.end));
  }));
  // ---- impact ------------------------------------------------------------------------
  m.push_back(text("impact_model", "Impact model", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!struck(r)) return std::nullopt;
    return std::string(to_string(r.impact.friction)) + ", " + to_string(r.impact.contact);
  }));
  m.push_back(text("restitution", "Restitution e / along the face e_t", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!struck(r)) return std::nullopt;
    return fixed(r.impact.e, 3) + " / " + fixed(r.impact.e_t, 3);
  }));
  m.push_back(plain("friction", "Friction mu", struck, [](const ShotResult& r) { return r.impact.mu; }, 3, "", "mu"));
  // The grip threshold, when the caller computed it: whether turning µ changes anything.
  // The µ past which the launch no longer changes. With the compliant contact that is not
  // where the patch first grips (the contact row says whether it did): once it sticks, the
  // shear spring's release gives back part of the spin, less the more friction held it
  // (Maw, Barber & Fawcett 1976), so spin peaks at a lower µ and eases toward this one's.
  m.push_back(text("grip", "mu past which the launch is fixed", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!struck(r) || r.impact.mu_grip < 0.0) return std::nullopt;
    const std::string t = fixed(r.impact.mu_grip, 3);
    // Short enough for the launch-monitor panel's column (the tuning panel says it whole).
    if (r.impact.mu_grip == 0.0) return t + " (mu: no effect)";
    return t + (r.impact.mu >= r.impact.mu_grip ? " (mu: no effect)" : " (mu moves it)");
  }));
  m.push_back(text("impulse", "Impulse n / t", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!struck(r)) return std::nullopt;
    return fixed(r.impact.normal_impulse, 3) + " / " + fixed(r.impact.tangential_impulse, 3) + " N*s";
  }));
  m.push_back(plain("energy_lost", "Energy lost", struck, [](const ShotResult& r) { return r.impact.energy_loss; }, 1, "J",
                    "energy_loss_J"));
  m.push_back(text("e", "e", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!struck(r)) return std::nullopt;
    return num(r.impact.e);
  }));
  m.push_back(text("contact", "Contact", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!struck(r)) return std::nullopt;
    return std::string(to_string(r.impact.contact));
  }));
  m.push_back(text("scenario", "Scenario", [](const ShotResult& r, const DisplayUnits&) {
    return std::optional<std::string>(r.scenario);
  }));
  // ---- Statcast CSV columns (Statcast's names; imperial as Statcast, or SI) -------------
  // spray_angle, the spin, apex and hang-time columns are not in Statcast's CSV and use
  // Statcast-style names; plate_speed is the pitch's speed as it meets the bat (Statcast's
  // release_speed is measured at the hand, ~8 % faster).
  const auto& F = [](const ShotResult& r) -> const FlightSummary& { return r.trajectory.summary; };
  using K = StatcastKind;
  m.push_back(statcast("sc_launch_speed", "launch_speed", always, K::Speed, [](const ShotResult& r) { return r.launch.ball_speed; }));
  m.push_back(statcast("sc_launch_angle", "launch_angle", always, K::Same, [](const ShotResult& r) { return r.launch.vertical_angle * kDeg; }));
  m.push_back(statcast("sc_spray_angle", "spray_angle", always, K::Same, [](const ShotResult& r) { return r.launch.horizontal_angle * kDeg; }));
  m.push_back(statcast("sc_launch_spin_rate", "launch_spin_rate", always, K::Same,
                       [](const ShotResult& r) { return radps_to_rpm(r.launch.spin.total); }));
  m.push_back(statcast("sc_hit_distance", "hit_distance_sc", always, K::Distance, [=](const ShotResult& r) { return F(r).carry_m; }));
  m.push_back(statcast("sc_total_distance", "total_distance", always, K::Distance, [=](const ShotResult& r) { return F(r).total_m; }));
  m.push_back(statcast("sc_apex", "apex_ft", always, K::Distance, [=](const ShotResult& r) { return F(r).apex_m; }));
  m.push_back(statcast("sc_hang_time", "hang_time", always, K::Same, [=](const ShotResult& r) { return F(r).hang_time_s; }));
  m.push_back(statcast("sc_bat_speed", "bat_speed", bat, K::Speed, [](const ShotResult& r) { return r.bat.speed; }));
  m.push_back(statcast("sc_attack_angle", "attack_angle", bat, K::Same, [](const ShotResult& r) { return r.bat.attack_angle * kDeg; }));
  m.push_back(statcast("sc_attack_direction", "attack_direction", bat, K::Same, [](const ShotResult& r) { return r.bat.direction * kDeg; }));
  m.push_back(statcast("sc_plate_speed", "plate_speed", bat, K::Speed, [](const ShotResult& r) { return r.bat.pitch_speed; }));
  m.push_back(statcast("sc_pitch_spin_rate", "pitch_spin_rate", bat, K::Same,
                       [](const ShotResult& r) { return radps_to_rpm(r.bat.pitch_spin); }));
  m.push_back(plain("sc_collision_efficiency", "collision_efficiency", bat, collision_efficiency, 3, "", "collision_efficiency"));
  m.push_back(text("friction_model", "Friction model", [](const ShotResult& r, const DisplayUnits&) -> std::optional<std::string> {
    if (!struck(r)) return std::nullopt;
    return std::string(to_string(r.impact.friction));
  }, "friction"));
  return m;
}

const std::vector<Metric>& registry() {
  static const std::vector<Metric> all = build();  // immutable after first use
  return all;
}

}  // namespace

UnitSystem parse_unit_system(std::string_view text, std::string_view flag) {
  if (text == "imperial") return UnitSystem::Imperial;
  if (text == "metric") return UnitSystem::Metric;
  throw InputError(std::string(flag) + " " + std::string(text) + ": unknown unit system; allowed: imperial, metric");
}

double DisplayUnits::speed(double mps) const { return imperial() ? mps_to_mph(mps) : mps; }
double DisplayUnits::dist(double m) const {
  if (!imperial()) return m;
  return distance == "ft" ? m_to_ft(m) : m_to_yd(m);
}

const Metric* find_metric(std::string_view id) {
  for (const Metric& m : registry())
    if (m.id == id) return &m;
  return nullptr;
}

std::string metric_ids() {
  std::string out;
  for (const Metric& m : registry()) out += (out.empty() ? "" : ", ") + std::string(m.id);
  return out;
}

double collision_efficiency(const ShotResult& r) {
  const double closing = r.bat.pitch_speed + r.bat.speed;
  return closing > 0.0 ? (r.launch.ball_speed - r.bat.speed) / closing : 0.0;
}

std::string metric_table(const std::string& title, const std::vector<std::string>& rows, const ShotResult& r,
                         const DisplayUnits& u) {
  std::string out = title + "\n";
  // The value column starts after the longest label (20 characters at least), so a long
  // label never runs into its value.
  std::size_t column = 22;
  for (const std::string& id : rows)
    if (const Metric* m = find_metric(id)) column = std::max(column, m->label.size() + 4);
  for (const std::string& id : rows) {
    const Metric* m = find_metric(id);
    if (m == nullptr) throw InputError("unknown launch-monitor metric '" + id + "' (allowed: " + metric_ids() + ")");
    const auto value = m->show(r, u);
    if (!value) continue;
    std::string line = "  " + std::string(m->label);
    line.append(column - line.size(), ' ');
    out += line + *value + "\n";
  }
  return out;
}

}  // namespace sweetspot
