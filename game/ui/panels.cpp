#include "game/ui/panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "game/equipment/equipment_file.hpp"
#include "game/scenario/scenario_catalog.hpp"
#include "game/ui/trajectory_plot.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/aero.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

constexpr float kLeftWidth = 360.0f;
constexpr float kRightWidth = 380.0f;

double to_deg(double rad) { return rad * 180.0 / kPi; }

// A slider over a value shown in display units; on change writes the override.
bool slider(UiState& st, const char* label, const std::string& key, double display_value, float lo,
            float hi, const char* unit, const char* fmt = "%.1f") {
  float v = static_cast<float>(display_value);
  char shown[64];
  std::snprintf(shown, sizeof shown, "%s %s", fmt, unit);
  if (ImGui::SliderFloat(label, &v, lo, hi, shown)) {
    st.set(key, quantity_text(v, unit));
    return true;
  }
  return false;
}

template <class List, class NameOf>
bool combo(const char* label, const std::string& current, const List& items, NameOf name_of,
           std::string& chosen) {
  bool changed = false;
  if (ImGui::BeginCombo(label, current.c_str())) {
    for (const auto& item : items) {
      const std::string n = name_of(item);
      if (ImGui::Selectable(n.c_str(), n == current)) {
        chosen = n;
        changed = n != current;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

// Club face (golf) or barrel (baseball) with the impact point; a click moves it.
bool impact_picker(PanelContext& c) {
  const Scenario& s = c.scenario;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const float w = ImGui::GetContentRegionAvail().x, h = 90.0f;
  ImGui::InvisibleButton("impact_picker", ImVec2(w, h));
  const bool clicked = ImGui::IsItemActive() && ImGui::IsMouseDown(0);
  const ImVec2 m = ImGui::GetIO().MousePos;
  const ImVec2 centre(o.x + w * 0.5f, o.y + h * 0.5f);
  if (s.sport == Sport::Golf) {
    // Face drawn 1 px per mm (a driver face is ~110 × 55 mm; irons ~75 × 45 mm).
    const bool wood = s.club.loft < 25.0 * kPi / 180.0;
    const float fw = wood ? 110.0f : 75.0f, fh = wood ? 55.0f : 45.0f;
    dl->AddRectFilled(ImVec2(centre.x - fw / 2, centre.y - fh / 2), ImVec2(centre.x + fw / 2, centre.y + fh / 2),
                      IM_COL32(70, 74, 82, 255), 12.0f);
    for (int g = -3; g <= 3; ++g)  // score lines
      dl->AddLine(ImVec2(centre.x - fw * 0.35f, centre.y + g * 6.0f), ImVec2(centre.x + fw * 0.35f, centre.y + g * 6.0f),
                  IM_COL32(95, 100, 110, 255));
    const float toe_mm = static_cast<float>(s.golf_swing.impact_toe * 1000.0);
    const float up_mm = static_cast<float>(s.golf_swing.impact_up * 1000.0);
    // Seen from the golfer's side of a right-hander's face, the toe is to the screen's right.
    dl->AddCircleFilled(ImVec2(centre.x + toe_mm, centre.y - up_mm), 5.0f, IM_COL32(255, 255, 255, 255));
    dl->AddText(ImVec2(o.x + 2, o.y + 2), IM_COL32(180, 180, 180, 255), "heel");
    dl->AddText(ImVec2(o.x + w - 24, o.y + 2), IM_COL32(180, 180, 180, 255), "toe");
    if (clicked) {
      const double toe = std::clamp((m.x - centre.x) / 1000.0, -0.04, 0.04);
      const double up = std::clamp(-(m.y - centre.y) / 1000.0, -0.025, 0.025);
      if (std::abs(toe - s.golf_swing.impact_toe) > 5e-4 || std::abs(up - s.golf_swing.impact_up) > 5e-4) {
        c.state.set("swing.impact_offset", quantity_list_text({toe * 1000.0, up * 1000.0}, "mm"));
        return true;
      }
    }
  } else {
    // Barrel, tip at the right; 1 px per 2 mm along, 1 px per 0.5 mm across.
    const float len = std::min(w - 20.0f, 420.0f);
    const float x_tip = centre.x + len / 2, x_knob = centre.x - len / 2;
    dl->AddRectFilled(ImVec2(x_knob, centre.y - 6), ImVec2(x_tip - len * 0.45f, centre.y + 6), IM_COL32(170, 130, 80, 255));
    dl->AddRectFilled(ImVec2(x_tip - len * 0.45f, centre.y - 18), ImVec2(x_tip, centre.y + 18), IM_COL32(190, 150, 95, 255), 8.0f);
    const float scale = len / static_cast<float>(s.bat.length);
    const float px = x_tip - static_cast<float>(s.bat_swing.impact_from_tip) * scale;
    const float py = centre.y - static_cast<float>(s.bat_swing.undercut * 1000.0) * 0.5f;
    dl->AddCircle(ImVec2(px, py), 18.0f, IM_COL32(255, 255, 255, 255), 24, 2.0f);
    dl->AddText(ImVec2(o.x + 2, o.y + 2), IM_COL32(180, 180, 180, 255), "knob");
    dl->AddText(ImVec2(o.x + w - 24, o.y + 2), IM_COL32(180, 180, 180, 255), "tip");
    if (clicked) {
      const double from_tip = std::clamp(static_cast<double>((x_tip - m.x) / scale), 0.0, 0.45);
      const double undercut = std::clamp(-(m.y - centre.y) / 0.5 / 1000.0, -0.05, 0.05);
      if (std::abs(from_tip - s.bat_swing.impact_from_tip) > 2e-3 || std::abs(undercut - s.bat_swing.undercut) > 5e-4) {
        c.state.set("swing.impact_from_tip", quantity_text(from_tip * 1000.0, "mm"));
        c.state.set("swing.undercut", quantity_text(undercut * 1000.0, "mm"));
        return true;
      }
    }
  }
  return false;
}

bool shot_panel(PanelContext& c) {
  bool changed = false;
  const Scenario& s = c.scenario;
  UiState& st = c.state;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kLeftWidth, 0), ImGuiCond_Always);
  ImGui::Begin("Shot", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);

  int sport = s.sport == Sport::Golf ? 0 : 1;
  if (ImGui::RadioButton("golf", &sport, 0) && s.sport != Sport::Golf) {
    st.choose_scenario("golf/driver");
    changed = true;
  }
  ImGui::SameLine();
  if (ImGui::RadioButton("baseball", &sport, 1) && s.sport != Sport::Baseball) {
    st.choose_scenario("baseball/line-drive");
    changed = true;
  }
  std::vector<BuiltinScenario> builtins = builtin_scenarios();
  std::erase_if(builtins, [&](const BuiltinScenario& b) { return b.sport != s.sport; });
  std::string chosen;
  if (combo("scenario", st.scenario, builtins, [](const BuiltinScenario& b) { return b.name; }, chosen)) {
    st.choose_scenario(chosen);
    changed = true;
  }
  if (!s.description.empty()) ImGui::TextWrapped("%s", s.description.c_str());

  const EquipmentCatalog& eq = default_equipment();
  if (s.sport == Sport::Golf) {
    if (combo("club", s.club.name, eq.clubs, [](const ClubSpec& x) { return x.name; }, chosen)) {
      st.set("club.name", chosen);
      st.overrides.erase("swing.dynamic_loft");  // the new club's own delivered loft
      changed = true;
    }
    const GolfSwing& g = s.golf_swing;
    changed |= slider(st, "club speed", "swing.speed", mps_to_mph(g.club_speed), 40, 140, "mph");
    changed |= slider(st, "attack angle", "swing.attack_angle", to_deg(g.attack_angle), -10, 10, "deg");
    changed |= slider(st, "club path", "swing.path", to_deg(g.club_path), -10, 10, "deg");
    const double loft = std::isnan(g.dynamic_loft) ? s.club.dynamic_loft : g.dynamic_loft;
    changed |= slider(st, "dynamic loft", "swing.dynamic_loft", to_deg(loft), 5, 65, "deg");
    changed |= slider(st, "face angle", "swing.face_angle", to_deg(g.face_angle), -10, 10, "deg");
    changed |= slider(st, "closure rate", "swing.closure_rate", to_deg(g.closure_rate), 0, 3000, "deg/s", "%.0f");
    ImGui::Text("impact: toe %+.0f mm, up %+.0f mm", g.impact_toe * 1000, g.impact_up * 1000);
    ImGui::TextDisabled("click the face to move the impact point");
  } else {
    if (combo("bat", s.bat.name, eq.bats, [](const BatSpec& x) { return x.name; }, chosen)) {
      st.set("bat.name", chosen);
      changed = true;
    }
    const BatSwing& b = s.bat_swing;
    changed |= slider(st, "bat speed", "swing.speed", mps_to_mph(b.bat_speed), 40, 95, "mph");
    changed |= slider(st, "swing plane", "swing.attack_angle", to_deg(b.attack_angle), -20, 40, "deg");
    changed |= slider(st, "direction", "swing.direction", to_deg(b.direction), -45, 45, "deg");
    changed |= slider(st, "pitch speed", "pitch.speed", mps_to_mph(c.scenario.pitch.speed), 0, 105, "mph");
    changed |= slider(st, "pitch spin", "pitch.spin", radps_to_rpm(c.scenario.pitch.spin), 0, 3000, "rpm", "%.0f");
    ImGui::Text("impact: %.1f in from tip, undercut %+.0f mm", b.impact_from_tip / 0.0254, b.undercut * 1000);
    ImGui::TextDisabled("click the barrel: along = impact point, up = undercut");
  }
  changed |= impact_picker(c);
  ImGui::End();
  return changed;
}

bool tuning_panel(PanelContext& c) {
  bool changed = false;
  const Scenario& s = c.scenario;
  UiState& st = c.state;
  ImGui::SetNextWindowPos(ImVec2(8, 470), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kLeftWidth, 0), ImGuiCond_Always);
  ImGui::Begin("Tuning", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  const ImpactSummary& im = c.result.impact;
  changed |= slider(st, "e", "impact.e", im.present ? im.e : 0.8, 0.0f, 1.0f, "", "%.3f");
  changed |= slider(st, "e_t", "impact.e_t", s.material.e_t, 0.0f, 1.0f, "", "%.3f");
  changed |= slider(st, "mu", "impact.mu", s.material.mu, 0.0f, 1.0f, "", "%.3f");
  int model = static_cast<int>(s.material.friction);
  const char* models[] = {"none", "textbook", "coulomb"};
  if (ImGui::Combo("friction", &model, models, 3)) {
    st.set("impact.friction", models[model]);
    changed = true;
  }
  if (s.material.friction == FrictionModel::Textbook)
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s", kTextbookEnergyNote);
  std::vector<std::string> aeros;
  for (const std::string& n : aero_model_names())
    if (aero_model(n).sport == to_string(s.sport)) aeros.push_back(n);
  std::string chosen;
  if (combo("aero", s.aero->name, aeros, [](const std::string& n) { return n; }, chosen)) {
    st.set("aero.model", chosen);
    changed = true;
  }
  const Environment& env = s.environment;
  changed |= slider(st, "temperature", "environment.temperature", kelvin_to_fahrenheit(env.temperature), 20, 110, "F", "%.0f");
  changed |= slider(st, "altitude", "environment.altitude", env.altitude, 0, 3000, "m", "%.0f");
  changed |= slider(st, "humidity", "environment.humidity", env.humidity * 100.0, 0, 100, "%", "%.0f");
  changed |= slider(st, "wind", "environment.wind_speed", mps_to_mph(env.wind_speed), 0, 40, "mph", "%.0f");
  changed |= slider(st, "wind toward", "environment.wind_direction", to_deg(env.wind_direction), -180, 180, "deg", "%.0f");
  ImGui::TextDisabled("wind toward: 0 = tailwind, 90 = to the right");
  ImGui::SetNextItemWidth(200);
  ImGui::InputText("##save", &c.save_path);
  ImGui::SameLine();
  if (ImGui::Button("Save scenario")) {
    try {
      const std::string path = c.save_path;
      write_file_atomic(path, scenario_toml(c.scenario));
      c.status = "saved " + path;
    } catch (const std::exception& e) {
      c.status = e.what();
    }
  }
  ImGui::End();
  return changed;
}

void monitor_row(const char* name, double got, const Scenario& s, const char* expect_key, double to_display,
                 const char* unit) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  ImGui::TableNextColumn();
  ImGui::Text("%.1f %s", got * to_display, unit);
  for (const Expectation& e : s.expectations) {
    if (e.name != expect_key || e.value.empty()) continue;
    ImGui::TableNextColumn();
    ImGui::Text("%.1f", e.value[0] * to_display);
    ImGui::TableNextColumn();
    ImGui::Text("%+.1f", (got - e.value[0]) * to_display);
    return;
  }
}

void monitor_panel(PanelContext& c) {
  const ShotResult& r = c.result;
  const Scenario& s = c.scenario;
  const float x = ImGui::GetIO().DisplaySize.x - kRightWidth - 8;
  ImGui::SetNextWindowPos(ImVec2(x, 8), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kRightWidth, 0), ImGuiCond_Always);
  ImGui::Begin("Launch monitor", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  const double deg = 180.0 / kPi, rpm = 1.0 / kRadPerSecPerRpm;
  const bool golf = s.sport == Sport::Golf;
  const double dist = golf ? 1.0 / kMetresPerYard : 1.0 / kMetresPerFoot;
  const char* du = golf ? "yd" : "ft";
  if (ImGui::BeginTable("monitor", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("");
    ImGui::TableSetupColumn("shot");
    ImGui::TableSetupColumn("ref");
    ImGui::TableSetupColumn("diff");
    ImGui::TableHeadersRow();
    const double mph = 1.0 / kMpsPerMph;
    monitor_row(golf ? "ball speed" : "exit velocity", r.launch.ball_speed, s, "ball_speed", mph, "mph");
    monitor_row("launch angle", r.launch.vertical_angle, s, "vertical_angle", deg, "deg");
    monitor_row(golf ? "launch direction" : "spray angle", r.launch.horizontal_angle, s, "horizontal_angle", deg, "deg");
    monitor_row("spin", r.launch.spin.total, s, "spin", rpm, "rpm");
    monitor_row("spin axis", r.launch.spin.axis_rad, s, "spin_axis", deg, "deg");
    monitor_row("backspin", r.launch.spin.backspin, s, "backspin", rpm, "rpm");
    monitor_row("sidespin", r.launch.spin.sidespin_right, s, "sidespin", rpm, "rpm");
    if (golf) monitor_row("smash factor", r.smash_factor, s, "smash_factor", 1.0, "");
    const FlightSummary& f = r.trajectory.summary;
    monitor_row(golf ? "carry" : "distance", f.carry_m, s, "carry", dist, du);
    monitor_row("total", f.total_m, s, "total", dist, du);
    monitor_row("apex", f.apex_m, s, "apex", dist, du);
    monitor_row("land angle", f.landing_angle_deg / deg, s, "landing_angle", deg, "deg");
    monitor_row("hang time", f.hang_time_s, s, "hang_time", 1.0, "s");
    monitor_row("lateral", f.lateral_m, s, "lateral", dist, du);
    ImGui::EndTable();
  }
  ImGui::Text("end: %s   contact: %s   energy lost %.1f J", to_string(r.trajectory.summary.end),
              r.impact.present ? to_string(r.impact.contact) : "-", r.impact.energy_loss);
  ImGui::End();
}

void trajectory_panel(PanelContext& c) {
  const float x = ImGui::GetIO().DisplaySize.x - kRightWidth - 8;
  ImGui::SetNextWindowPos(ImVec2(x, 430), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kRightWidth, 0), ImGuiCond_Always);
  ImGui::Begin("Trajectory", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  draw_trajectory_plots(c.result.trajectory, c.replay.time);
  ImGui::End();
}

void replay_panel(PanelContext& c) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const float w = size.x - kLeftWidth - kRightWidth - 32;
  ImGui::SetNextWindowPos(ImVec2(kLeftWidth + 16, size.y - 96), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w, 0), ImGuiCond_Always);
  ImGui::Begin("Replay", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  const double end = duration(c.result.trajectory);
  if (ImGui::Button(c.replay.playing ? "Pause" : "Play")) {
    if (!c.replay.playing && c.replay.time >= end) c.replay.time = 0.0;
    c.replay.playing = !c.replay.playing;
  }
  ImGui::SameLine();
  if (ImGui::Button("Replay (R)")) c.replay.restart();
  ImGui::SameLine();
  float speed = static_cast<float>(c.replay.speed);
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("speed", &speed, 0.1f, 4.0f, "%.1fx")) c.replay.speed = speed;
  ImGui::SameLine();
  int cam = static_cast<int>(c.camera);
  const char* cams[] = {"behind", "side", "top", "follow"};
  ImGui::SetNextItemWidth(100);
  if (ImGui::Combo("camera (1-4)", &cam, cams, 4)) c.camera = static_cast<CameraKind>(cam);
  float t = static_cast<float>(c.replay.time);
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderFloat("##time", &t, 0.0f, static_cast<float>(end), "%.2f s")) c.replay.scrub(t, end);
  if (!c.status.empty()) ImGui::TextWrapped("%s", c.status.c_str());
  ImGui::End();
}

}  // namespace

bool draw_panels(PanelContext& ctx) {
  bool changed = shot_panel(ctx);
  changed |= tuning_panel(ctx);
  monitor_panel(ctx);
  trajectory_panel(ctx);
  replay_panel(ctx);
  return changed;
}

}  // namespace sweetspot
