#include "game/ui/panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "game/content/equipment_file.hpp"
#include "game/content/scenario.hpp"
#include "game/content/scenario_schema.hpp"
#include "game/content/scenario_toml.hpp"
#include "game/report/report.hpp"
#include "game/ui/trajectory_plot.hpp"
#include "game/ui/wrapped_text.hpp"
#include "physics/aero.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

/// Shown beside the friction choice: the textbook model is kept for teaching only.
constexpr const char* kTextbookEnergyNote =
    "textbook: applies mu*J in full every time; it can reverse sliding and CREATE energy "
    "(see the energy-loss readout). Use coulomb for real shots.";

void edit(PanelContext& c, LabParam p, double si) {
  Intent in;
  in.kind = IntentKind::Edit;
  in.time = c.now;
  in.param = static_cast<int>(p);
  in.value = si;
  c.out.push_back(in);
}

void choose(PanelContext& c, LabChoice which, const std::string& text) {
  Intent in;
  in.kind = IntentKind::Choose;
  in.time = c.now;
  in.param = static_cast<int>(which);
  in.text = text;
  c.out.push_back(in);
}

// A slider over one ShotSpec field (SI) shown in its scenario key's display unit, bounded by
// the key's one range (the physics parameter's, through the schema); a change becomes an
// Edit intent with the value in SI. Ctrl+click types a value.
bool slider(PanelContext& c, LabParam p, const char* label, const char* fmt = "%.1f") {
  const LabParamInfo& info = lab_param_info(p);
  const KeySpec* spec = scenario_schema().find(info.key, info.strikes);
  if (spec == nullptr) return false;
  const Range* range = spec->range[static_cast<std::size_t>(info.element)];
  const Range& r = range ? *range : kAnyFinite;
  const std::string unit(spec->unit);
  const float lo = static_cast<float>(si_to_unit(r.min, unit, spec->dim));
  const float hi = static_cast<float>(si_to_unit(r.max, unit, spec->dim));
  float v = static_cast<float>(si_to_unit(c.lab.value(p), unit, spec->dim));
  std::string shown = std::string(fmt) + " ";
  for (const char ch : unit) shown += ch == '%' ? std::string("%%") : std::string(1, ch);  // a format string
  if (ImGui::SliderFloat(label, &v, lo, hi, shown.c_str(), ImGuiSliderFlags_AlwaysClamp)) {
    edit(c, p, unit_to_si(float_as_decimal(v), unit, spec->dim));
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

// An expectation's SI value in the display units its metric row uses.
double display_value(const std::string& expect, double si, const DisplayUnits& u) {
  for (const ExpectSpec& e : scenario_expectations()) {
    if (e.name != expect) continue;
    switch (e.dim) {
      case Dimension::Speed: return u.speed(si);
      case Dimension::Length: return u.dist(si);
      case Dimension::Angle: return rad_to_deg(si);
      case Dimension::AngularVelocity: return radps_to_rpm(si);
      default: return si;
    }
  }
  return si;
}

bool is_club(const LabModel& l) { return std::holds_alternative<ClubStrike>(l.spec().strike); }
bool is_bat(const LabModel& l) { return std::holds_alternative<BatStrike>(l.spec().strike); }
// Club face (golf) or barrel (baseball) with the impact point; a click moves it.
bool impact_picker(PanelContext& c) {
  const LabModel& s = c.lab;
  if (!is_club(s) && !is_bat(s)) return false;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const float w = ImGui::GetContentRegionAvail().x, h = 90.0f;
  ImGui::InvisibleButton("impact_picker", ImVec2(w, h));
  const bool clicked = ImGui::IsItemActive() && ImGui::IsMouseDown(0);
  const ImVec2 m = ImGui::GetIO().MousePos;
  const ImVec2 centre(o.x + w * 0.5f, o.y + h * 0.5f);
  if (is_club(s)) {
    const GolfSwing& g = std::get<ClubStrike>(s.spec().strike).swing;
    // Face drawn 1 px per mm (a driver face is ~110 × 55 mm; irons ~75 × 45 mm).
    const bool wood = s.resolved().club_info->kind == "wood";
    const float fw = wood ? 110.0f : 75.0f, fh = wood ? 55.0f : 45.0f;
    dl->AddRectFilled(ImVec2(centre.x - fw / 2, centre.y - fh / 2), ImVec2(centre.x + fw / 2, centre.y + fh / 2),
                      IM_COL32(70, 74, 82, 255), 12.0f);
    for (int k = -3; k <= 3; ++k)  // score lines
      dl->AddLine(ImVec2(centre.x - fw * 0.35f, centre.y + k * 6.0f), ImVec2(centre.x + fw * 0.35f, centre.y + k * 6.0f),
                  IM_COL32(95, 100, 110, 255));
    const float toe_mm = static_cast<float>(g.impact_toe * 1000.0);
    const double up_m = s.value(LabParam::ImpactUp);  // the club's usual strike
    const float up_mm = static_cast<float>(up_m * 1000.0);
    // Seen from the golfer's side of a right-hander's face, the toe is to the screen's right.
    dl->AddCircleFilled(ImVec2(centre.x + toe_mm, centre.y - up_mm), 5.0f, IM_COL32(255, 255, 255, 255));
    dl->AddText(ImVec2(o.x + 2, o.y + 2), IM_COL32(180, 180, 180, 255), "heel");
    dl->AddText(ImVec2(o.x + w - 24, o.y + 2), IM_COL32(180, 180, 180, 255), "toe");
    // A click on the face drawn moves the strike there, held on this club's own face (the
    // drawing is the bag's typical face; a driver's may be a little shorter); a click beside
    // it is no strike (it was taken as one, half of it refused as off the face).
    const bool on_face = std::abs(m.x - centre.x) <= fw / 2 && std::abs(m.y - centre.y) <= fh / 2;
    if (clicked && on_face) {
      const ClubSpec& club = *s.resolved().club;
      const double half_w = std::min(club.face_half_width, GolfSwing::kImpactToe.max);
      const double half_h = std::min(club.face_half_height, GolfSwing::kImpactUp.max);
      const double toe = std::clamp((m.x - centre.x) / 1000.0, -half_w, half_w);
      const double up = std::clamp(-(m.y - centre.y) / 1000.0, -half_h, half_h);
      if (std::abs(toe - g.impact_toe) > 5e-4 || std::abs(up - up_m) > 5e-4) {
        edit(c, LabParam::ImpactToe, toe);
        edit(c, LabParam::ImpactUp, up);
        return true;
      }
    }
  } else {
    const BatSwing& b = std::get<BatStrike>(s.spec().strike).swing;
    const BatSpec& bat = *s.resolved().bat;
    // Barrel, tip at the right; 1 px per 2 mm along, 1 px per 0.5 mm across.
    const float len = std::min(w - 20.0f, 420.0f);
    const float x_tip = centre.x + len / 2, x_knob = centre.x - len / 2;
    dl->AddRectFilled(ImVec2(x_knob, centre.y - 6), ImVec2(x_tip - len * 0.45f, centre.y + 6), IM_COL32(170, 130, 80, 255));
    dl->AddRectFilled(ImVec2(x_tip - len * 0.45f, centre.y - 18), ImVec2(x_tip, centre.y + 18), IM_COL32(190, 150, 95, 255), 8.0f);
    const float scale = len / static_cast<float>(bat.length);
    const float px = x_tip - static_cast<float>(b.impact_from_tip) * scale;
    const float py = centre.y - static_cast<float>(b.undercut * 1000.0) * 0.5f;
    dl->AddCircle(ImVec2(px, py), 18.0f, IM_COL32(255, 255, 255, 255), 24, 2.0f);
    dl->AddText(ImVec2(o.x + 2, o.y + 2), IM_COL32(180, 180, 180, 255), "knob");
    dl->AddText(ImVec2(o.x + w - 24, o.y + 2), IM_COL32(180, 180, 180, 255), "tip");
    if (clicked) {
      const double from_tip = std::clamp(static_cast<double>((x_tip - m.x) / scale), 0.0,
                                         bat.length - bat.pivot_from_knob - 0.05);
      const double undercut = std::clamp(-(m.y - centre.y) / 0.5 / 1000.0, -0.05, 0.05);
      if (std::abs(from_tip - b.impact_from_tip) > 2e-3 || std::abs(undercut - b.undercut) > 5e-4) {
        edit(c, LabParam::ImpactFromTip, from_tip);
        edit(c, LabParam::Undercut, undercut);
        return true;
      }
    }
  }
  return false;
}

bool shot_section(PanelContext& c) {
  bool changed = false;
  const LabModel& s = c.lab;
  const std::string& sport = s.resolved().sport->name;
  bool first = true;
  for (const SportProfile& p : c.assets.sports().sports) {
    if (!first) ImGui::SameLine();
    first = false;
    if (ImGui::RadioButton(p.name.c_str(), p.name == sport) && p.name != sport) {
      choose(c, LabChoice::Sport, p.name);
      changed = true;
    }
  }
  std::vector<BuiltinScenario> builtins;
  for (const BuiltinScenario& b : c.assets.scenarios())
    if (b.sport == sport) builtins.push_back(b);
  std::string chosen;
  if (combo("scenario", s.scenario().name, builtins, [](const BuiltinScenario& b) { return b.name; }, chosen)) {
    choose(c, LabChoice::Scenario, chosen);
    changed = true;
  }
  if (!s.scenario().description.empty()) ImGui::TextWrapped("%s", s.scenario().description.c_str());

  const EquipmentCatalog& eq = c.assets.equipment();
  if (is_club(s)) {
    const ClubSpec& club = *s.resolved().club;
    if (combo("club", club.name, eq.clubs, [](const ClubSpec& x) { return x.name; }, chosen)) {
      choose(c, LabChoice::Club, chosen);  // the new club's own delivered loft and strike
      changed = true;
    }
    changed |= slider(c, LabParam::ClubSpeed, "club speed");
    changed |= slider(c, LabParam::AttackAngle, "attack angle");
    changed |= slider(c, LabParam::ClubPath, "club path");
    changed |= slider(c, LabParam::DynamicLoft, "centre loft");
    changed |= slider(c, LabParam::FaceAngle, "centre face");
    changed |= slider(c, LabParam::ClosureRate, "closure rate", "%.0f");
    ImGui::Text("impact: toe %+.0f mm, up %+.0f mm", s.value(LabParam::ImpactToe) * 1000, s.value(LabParam::ImpactUp) * 1000);
    // The sliders set the face centre; a launch monitor (and the table) reads the face where
    // it met the ball, which the bulge and roll turn at an off-centre strike.
    const ClubNumbers& k = s.result().club;
    ImGui::TextDisabled("face at the strike %+.1f deg, loft %.1f deg", rad_to_deg(k.strike_face_angle),
                        rad_to_deg(k.strike_loft));
    ImGui::TextDisabled("click the face to move the impact point");
  } else if (is_bat(s)) {
    if (combo("bat", s.resolved().bat->name, eq.bats, [](const BatSpec& x) { return x.name; }, chosen)) {
      choose(c, LabChoice::Bat, chosen);
      changed = true;
    }
    const BatStrike& b = std::get<BatStrike>(s.spec().strike);
    changed |= slider(c, LabParam::BatSpeed, "bat speed");
    changed |= slider(c, LabParam::BatAttack, "attack angle");
    changed |= slider(c, LabParam::BatDirection, "attack direction");
    changed |= slider(c, LabParam::PitchSpeed, "pitch speed");
    changed |= slider(c, LabParam::PitchSpin, "pitch spin", "%.0f");
    ImGui::Text("impact: %.1f in from tip, undercut %+.0f mm", b.swing.impact_from_tip / 0.0254, b.swing.undercut * 1000);
    // Wrapped: on one line it would run off the left column's 340 px.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("click the barrel: along = impact point, up = undercut");
    ImGui::PopStyleColor();
  }
  changed |= impact_picker(c);
  return changed;
}

bool tuning_section(PanelContext& c) {
  bool changed = false;
  const LabModel& s = c.lab;
  if (std::holds_alternative<LaunchStrike>(s.spec().strike)) {
    // Launch numbers replace the strike: there is no e or mu to tune (and the scenario
    // refuses impact keys rather than ignore them).
    ImGui::TextDisabled("launch numbers given: no impact to tune");
    return false;
  }
  const ImpactSummary& im = s.result().impact;
  const ImpactMaterial& mat = s.resolved().material;
  changed |= slider(c, LabParam::E, "e  restitution", "%.3f");
  if (s.e_replaces_law()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    // The face's COR map still applies (ClubSpec::face_cor_factor): e falls off the face's
    // centre, so the monitor's e differs from the slider's wherever the strike is not there.
    if (im.present && std::abs(im.e - mat.e.at(0.0)) > 5e-4)
      ImGui::TextWrapped("e is constant over speed (it replaces the equipment's COR law); off the face's centre it falls: %.3f at this strike",
                         im.e);
    else
      ImGui::TextWrapped("e is constant: it replaces the equipment's speed-dependent COR");
    ImGui::PopStyleColor();
  } else if (mat.e.count > 1) {
    ImGui::TextDisabled("e: the COR law at this impact speed");
  }
  int impact_model = static_cast<int>(mat.model);
  const char* impact_models[] = {"compliant", "rigid"};
  if (ImGui::Combo("impact", &impact_model, impact_models, 2)) {
    choose(c, LabChoice::ImpactModel, impact_models[impact_model]);
    changed = true;
  }
  if (mat.model == ImpactModel::Rigid || mat.friction == FrictionModel::Textbook)
    changed |= slider(c, LabParam::Et, "e_t  along the face", "%.3f");
  else {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("e_t %.3f, restitution along the face (from the contact; the rigid model sets it)", im.present ? im.e_t : 0.0);
    ImGui::PopStyleColor();
  }
  changed |= slider(c, LabParam::Mu, "mu  face friction", "%.3f");
  if (im.present && im.mu_grip == 0.0) {
    ImGui::TextDisabled("friction does not change this launch");
  } else if (im.present && im.mu_grip > 0.0) {
    // Green: the contact grips from the start, the slider changes nothing above the threshold;
    // amber: the ball slides along the face first (it may still grip before it leaves, which
    // the monitor's "contact" says), and how far it slides is mu's.
    const bool grips = mat.mu >= im.mu_grip;
    ImGui::TextColored(grips ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f) : ImVec4(1.0f, 0.75f, 0.3f, 1.0f),
                       grips ? "mu above %.3f changes nothing" : "mu moves the launch up to %.3f", im.mu_grip);
    // With the contact's shear spring more friction is not always more spin: said, as a
    // physics reader expects the rigid model's rise to a plateau.
    if (!grips && mat.model == ImpactModel::Compliant)
      disabled_wrapped("spin peaks where the face first grips the ball; more mu grips it sooner and its shear spring gives some back");
  }
  int model = static_cast<int>(mat.friction);
  const char* models[] = {"none", "textbook", "coulomb"};
  if (ImGui::Combo("friction", &model, models, 3)) {
    choose(c, LabChoice::Friction, models[model]);
    changed = true;
  }
  if (mat.friction == FrictionModel::Textbook)
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s", kTextbookEnergyNote);
  std::vector<std::string> aeros;
  for (const AeroModel& m : c.assets.aero_models())
    if (m.sport == s.resolved().sport->name) aeros.push_back(m.name);
  std::string chosen;
  if (combo("aero", s.resolved().aero->name, aeros, [](const std::string& n) { return n; }, chosen)) {
    choose(c, LabChoice::Aero, chosen);
    changed = true;
  }
  changed |= slider(c, LabParam::Temperature, "temperature", "%.0f");
  changed |= slider(c, LabParam::Altitude, "altitude", "%.0f");
  changed |= slider(c, LabParam::Humidity, "humidity", "%.0f");
  changed |= slider(c, LabParam::WindSpeed, "wind", "%.0f");
  changed |= slider(c, LabParam::WindDirection, "wind toward", "%.0f");
  ImGui::TextDisabled("wind toward: 0 = tailwind, 90 = to the right");
  ImGui::SetNextItemWidth(200);
  ImGui::InputText("##save", &c.save_path);
  ImGui::SameLine();
  // Saving never replaces a file silently: an existing one needs a second, explicit yes.
  const auto save = [&c](const std::string& path) {
    Intent in;
    in.kind = IntentKind::Save;
    in.time = c.now;
    in.text = path;
    c.out.push_back(in);
  };
  if (ImGui::Button("Save scenario")) {
    std::error_code ec;
    if (std::filesystem::exists(c.save_path, ec))
      ImGui::OpenPopup("Overwrite?");
    else
      save(c.save_path);
  }
  if (ImGui::BeginPopupModal("Overwrite?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s already exists.", c.save_path.c_str());
    if (ImGui::Button("Overwrite")) {
      save(c.save_path);
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      c.note = "not saved: " + c.save_path + " exists (pick another name)";
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  return changed;
}

void monitor_section(PanelContext& c) {
  const ShotResult& r = c.lab.result();
  const Scenario& s = c.lab.scenario();
  const SportProfile& sport = *c.lab.resolved().sport;
  // Warnings first, where they are seen (values outside what labs measure, energy created,
  // spin past the aero fits), as `shot` prints them.
  for (const std::string& w : r.warnings) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    ImGui::TextWrapped("warning: %s", w.c_str());
    ImGui::PopStyleColor();
  }
  const DisplayUnits u = display_units(sport, UnitSystem::Imperial);
  // The label column fits the longest label of this sport (no "Landing angl" cut-offs);
  // the reference and difference columns fit a number; the shot's value takes the rest.
  float label_width = 0.0f;
  for (const std::string& id : sport.report)
    if (const Metric* m = find_metric(id)) label_width = std::max(label_width, ImGui::CalcTextSize(std::string(m->label).c_str()).x);
  const float number_width = ImGui::CalcTextSize("-0000.0").x;
  // But never so wide that the shot's own value is cut ("162." for 162.4 mph): a longer label
  // ("Restitution e / along the face e_t") wraps onto a second line instead.
  const float pad = 2.0f * ImGui::GetStyle().CellPadding.x;
  const float shot_width = ImGui::CalcTextSize("0000.0 mph").x;
  label_width = std::max(ImGui::CalcTextSize("Landing angle").x,
                         std::min(label_width, ImGui::GetContentRegionAvail().x - 2.0f * number_width - shot_width - 4.0f * pad));
  if (ImGui::BeginTable("monitor", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, label_width);
    ImGui::TableSetupColumn("shot", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("ref", ImGuiTableColumnFlags_WidthFixed, number_width);
    ImGui::TableSetupColumn("diff", ImGuiTableColumnFlags_WidthFixed, number_width);
    ImGui::TableHeadersRow();
    // The sport's launch-monitor rows, with the scenario's expected value when it has one.
    for (const std::string& id : sport.report) {
      const Metric* m = find_metric(id);
      if (m == nullptr) continue;
      const auto text = m->show(r, u);
      if (!text) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", std::string(m->label).c_str());
      ImGui::TableNextColumn();
      const auto got = m->number(r, u);
      const Expectation* ref = nullptr;
      if (got && !m->expect.empty())
        for (const Expectation& e : s.expectations)
          if (e.name == m->expect && !e.value.empty()) {
            ref = &e;
            break;
          }
      if (ref == nullptr) {
        // No reference on this row: its value may run on over the empty ref and diff cells
        // ("-0.1 deg (+ right)", "0 mm toe, 12 mm up") instead of being cut at its own.
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
        ImGui::PushClipRect(at, ImVec2(right, at.y + ImGui::GetTextLineHeightWithSpacing()), false);
        ImGui::TextUnformatted(text->c_str());
        ImGui::PopClipRect();
        continue;
      }
      ImGui::TextUnformatted(text->c_str());
      const double shown = display_value(ref->name, ref->value[0], u);
      // As the shot's own column reads: spin in whole rpm (2686, not 2686.0), speeds and
      // distances to a tenth.
      const bool whole = std::abs(shown) >= 1000.0;
      ImGui::TableNextColumn();
      ImGui::Text(whole ? "%.0f" : "%.1f", shown);
      ImGui::TableNextColumn();
      ImGui::Text(whole ? "%+.0f" : "%+.1f", *got - shown);
    }
    ImGui::EndTable();
  }
  ImGui::Text("end: %s   contact: %s   energy lost %.1f J", to_string(r.end),
              r.impact.present ? to_string(r.impact.contact) : "-", r.impact.energy_loss);
}

void replay_section(PanelContext& c) {
  const double end = duration(c.lab.result().trajectory);
  if (ImGui::Button(c.replay.playing ? "Pause" : "Play")) {
    if (!c.replay.playing && c.replay.time >= end) c.replay.time = -c.replay.pre_roll;
    c.replay.playing = !c.replay.playing;
  }
  ImGui::SameLine();
  if (ImGui::Button("Replay (R)")) c.replay.restart();
  ImGui::SameLine();
  float speed = static_cast<float>(c.replay.speed);
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("speed", &speed, 0.1f, 4.0f, "%.1fx")) c.replay.speed = speed;
  // The camera on a line of its own: beside the speed its label would run off the column.
  int cam = static_cast<int>(c.camera);
  const char* cams[] = {"behind", "side", "top", "follow"};
  ImGui::SetNextItemWidth(100);
  if (ImGui::Combo("camera (1-4)", &cam, cams, 4)) c.camera = static_cast<CameraKind>(cam);
  ImGui::SameLine();
  ImGui::TextDisabled("H: hide panels");
  float t = static_cast<float>(c.replay.time);
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderFloat("##time", &t, static_cast<float>(-c.replay.pre_roll), static_cast<float>(end), "%.2f s"))
    c.replay.scrub(t, end);
  if (!c.lab.status().empty()) ImGui::TextWrapped("%s", c.lab.status().c_str());
  else if (!c.note.empty()) ImGui::TextWrapped("%s", c.note.c_str());
  ImGui::TextDisabled("Space: hit again   Esc: pause   Tab: next mode");
}

constexpr ImGuiWindowFlags kColumnFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar;

void begin_column(const char* id, const Rect& r) {
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::Begin(id, nullptr, kColumnFlags);
  // Every slider and combo as wide as the column less its longest label ("attack direction"),
  // where ImGui's default (65 % of the column) cut it at 340 px.
  ImGui::PushItemWidth(-(ImGui::CalcTextSize("attack direction").x + ImGui::GetStyle().ItemInnerSpacing.x + 4.0f));
}

void end_column() {
  ImGui::PopItemWidth();
  ImGui::End();
}

bool section(const char* title, bool open_at_start) {
  return ImGui::CollapsingHeader(title, open_at_start ? ImGuiTreeNodeFlags_DefaultOpen : 0);
}

// The hidden layout's HUD: the numbers a player looks at, and the keys.
void hud(PanelContext& c, const Rect& view) {
  ImGui::SetNextWindowPos(ImVec2(view.x + 10, view.y + 10), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.45f);
  ImGui::Begin("##hud", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  const ShotResult& r = c.lab.result();
  const SportProfile& sport = *c.lab.resolved().sport;
  const DisplayUnits u = display_units(sport, UnitSystem::Imperial);
  std::string line;
  for (const char* id : {"ball_speed", "launch_angle", "spin_rate", "carry", "total"}) {
    const Metric* m = find_metric(id);
    if (m == nullptr) continue;
    const auto text = m->show(r, u);
    if (!text) continue;
    line += (line.empty() ? "" : "   ") + std::string(m->label) + " " + *text;
  }
  ImGui::TextUnformatted(line.c_str());
  ImGui::TextDisabled("H: panels   1-4: cameras (again: reset)   R: replay   Space: hit again   Esc: pause   Tab: next mode");
  if (!c.lab.status().empty()) ImGui::TextWrapped("%s", c.lab.status().c_str());
  ImGui::End();
}

}  // namespace

bool draw_panels(PanelContext& ctx, const PanelLayout& layout) {
  bool changed = false;
  switch (layout.kind) {
    case LayoutKind::Hidden:
      hud(ctx, layout.view);
      break;
    case LayoutKind::Wide:
      begin_column("##left", layout.left);
      if (section("Shot", true)) changed |= shot_section(ctx);
      if (section("Tuning (Ctrl+click a slider to type)###Tuning", true)) changed |= tuning_section(ctx);
      end_column();
      begin_column("##right", layout.right);
      if (section("Replay", true)) replay_section(ctx);
      if (section("Launch monitor", true)) monitor_section(ctx);
      if (section("Trajectory", true)) draw_trajectory_plots(ctx.lab.result().trajectory, ctx.replay.time);
      end_column();
      break;
    case LayoutKind::Sidebar:
      begin_column("##sidebar", layout.right);
      if (section("Replay", true)) replay_section(ctx);
      if (section("Launch monitor", true)) monitor_section(ctx);
      if (section("Shot", true)) changed |= shot_section(ctx);
      if (section("Tuning (Ctrl+click a slider to type)###Tuning", false)) changed |= tuning_section(ctx);
      if (section("Trajectory", false)) draw_trajectory_plots(ctx.lab.result().trajectory, ctx.replay.time);
      end_column();
      break;
  }
  return changed;
}

}  // namespace sweetspot
