#include "game/app/bat_app.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "game/modes/baseball/session.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "game/ui/replay.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

using Clock = std::chrono::steady_clock;

/// The pitch plays at this fraction of real time: 0.4 s is a hitter's lifetime, not a game's.
constexpr double kPitchTimeScale = 0.5;
constexpr double kZoneLow = 1.6 * 0.3048, kZoneHigh = 3.5 * 0.3048, kPlateHalf = 0.2159;

struct Cage {
  enum class Stage { Ready, Pitching, Batted, Called };
  explicit Cage(const Assets& a) : types(load_pitch_types(a)), rng(11), bot(a, batter_skill("pro"), 5) {}
  std::vector<PitchType> types;
  Rng rng;
  BotBatter bot;
  std::unique_ptr<ShotScene> scene;
  Stage stage = Stage::Ready;
  PitchCall call;
  PitchFlight pitch;
  double pitch_clock = 0.0;  // s of pitch time since release
  double bat_height = 0.76;  // m: where the bat meets the ball's path (the undercut's reference)
  bool power = true;
  bool lefty = false;
  SwingRecord last;
  ReplayState replay;
  std::vector<SwingRecord> swings;
  std::string call_text;
  double called_at = 0.0;
  int done_frames = 0;
};

Camera batter_view() {
  Camera c;
  c.eye = Vec3(-3.2, 1.6, -0.45);  // behind a right-handed batter, over his shoulder
  c.target = Vec3(10.0, 1.0, 0.0);
  c.fov_y = deg_to_rad(36.0);
  return c;
}

void draw_zone(const Cage& c, const Camera& cam, int w, int h) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const auto pt = [&](double y, double z) -> std::optional<ImVec2> {
    const auto p = cam.project(Vec3(0.0, y, z), w, h);
    if (!p) return std::nullopt;
    return ImVec2(static_cast<float>((*p)(0)), static_cast<float>((*p)(1)));
  };
  const auto a = pt(kZoneHigh, -kPlateHalf), b = pt(kZoneHigh, kPlateHalf), d = pt(kZoneLow, kPlateHalf),
             e = pt(kZoneLow, -kPlateHalf);
  if (a && b && d && e) {
    dl->AddQuad(*a, *b, *d, *e, IM_COL32(255, 255, 255, 200), 2.0f);
  }
  // The bat's height: where the swing will meet the ball.
  const auto l = pt(c.bat_height, -kPlateHalf - 0.25), r = pt(c.bat_height, kPlateHalf + 0.25);
  if (l && r) dl->AddLine(*l, *r, c.power ? IM_COL32(255, 170, 40, 230) : IM_COL32(80, 200, 255, 230), 3.0f);
}

void draw_stats(const Cage& c, int w, int h) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_Always);
  ImGui::Begin("Batting cage", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::Text("Pitch: %s %.0f mph", c.call.type.type.c_str(), mps_to_mph(c.call.type.speed));
  ImGui::Text("Swing: %s, %s-handed", c.power ? "power" : "contact", c.lefty ? "left" : "right");
  // One short line each: the panel is 360 px wide and cut "B: the pro swings" to "B: the pro swi".
  ImGui::TextDisabled("P: pitch  Space: swing  Up/Down: bat height");
  ImGui::TextDisabled("C: power/contact  L: batter's side");
  ImGui::TextDisabled("B: the pro swings  Tab: Lab");
  ImGui::Separator();
  int n = 0, contact = 0, hard = 0, hr = 0;
  double ev = 0.0, la = 0.0, longest = 0.0;
  for (const SwingRecord& s : c.swings) {
    ++n;
    if (!s.result.contact) continue;
    ++contact;
    ev += mps_to_mph(s.result.shot.launch.ball_speed);
    la += rad_to_deg(s.result.shot.launch.vertical_angle);
    hard += s.result.hard_hit;
    hr += s.result.outcome == BattedOutcome::HomeRun;
    longest = std::max(longest, s.result.shot.trajectory.summary.carry_m);
  }
  ImGui::Text("Swings %d, contact %d, home runs %d", n, contact, hr);
  if (contact > 0) {
    ImGui::Text("Avg exit velocity %.1f mph, launch %.1f deg", ev / contact, la / contact);
    ImGui::Text("Hard-hit %.0f %%, longest %.0f ft", 100.0 * hard / contact, m_to_ft(longest));
  }
  ImGui::End();

  // The spray chart, bottom right: home plate at the bottom, 450 ft to the top.
  const float size = 220.0f, x0 = static_cast<float>(w) - size - 12.0f, y0 = static_cast<float>(h) - size - 12.0f;
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  dl->AddRectFilled(ImVec2(x0, y0), ImVec2(x0 + size, y0 + size), IM_COL32(40, 90, 45, 220), 6.0f);
  const float scale = size / 140.0f;  // m
  const ImVec2 home(x0 + size / 2, y0 + size - 8.0f);
  const auto px = [&](const Vec3& p) { return ImVec2(home.x + static_cast<float>(p.z()) * scale, home.y - static_cast<float>(p.x()) * scale); };
  dl->AddLine(home, px(Vec3(130, 0, 130)), IM_COL32(240, 240, 240, 255));
  dl->AddLine(home, px(Vec3(130, 0, -130)), IM_COL32(240, 240, 240, 255));
  for (const SwingRecord& s : c.swings) {
    if (!s.result.contact) continue;
    const FlightSummary& f = s.result.shot.trajectory.summary;
    const Vec3 p = f.carry_m > 40.0 || s.result.outcome == BattedOutcome::HomeRun ? f.landing_position : f.rest_position;
    ImU32 col = IM_COL32(150, 150, 150, 255);
    switch (s.result.outcome) {
      case BattedOutcome::HomeRun: col = IM_COL32(220, 40, 40, 255); break;
      case BattedOutcome::Triple: col = IM_COL32(250, 130, 0, 255); break;
      case BattedOutcome::Double: col = IM_COL32(235, 200, 100, 255); break;
      case BattedOutcome::Single: col = IM_COL32(40, 160, 140, 255); break;
      case BattedOutcome::Foul: col = IM_COL32(140, 200, 230, 255); break;
      default: break;
    }
    dl->AddCircleFilled(px(p), 4.0f, col);
  }
  dl->AddText(ImVec2(x0 + 6, y0 + 4), IM_COL32(255, 255, 255, 255), "spray chart");
}

}  // namespace

WindowNext run_bat_loop(const Assets& assets, GameWindow& win, Renderer& renderer, const PlayOptions& o,
                        FrameStats& stats, std::ostream& out) {
  auto cage = std::make_unique<Cage>(assets);
  Cage& c = *cage;
  ShotSceneInput in;
  in.assets = &assets;
  in.world = assets.world("ballpark");
  in.distance_unit = "ft";
  in.ball_radius = assets.equipment().ball("mlb").radius;
  c.scene = std::make_unique<ShotScene>(in);
  c.call = derby_pitch(c.types, c.rng);
  auto last = Clock::now();
  const auto origin = last;
  while (!win.should_close()) {
    const auto t0 = Clock::now();
    const double dt = std::chrono::duration<double>(t0 - last).count();
    const double now = std::chrono::duration<double>(t0 - origin).count();
    last = t0;
    const FrameInput fin = win.begin_frame();
    const auto swing = [&](SwingInput s) {
      c.last = SwingRecord{};
      c.last.call = c.call;
      c.last.pitch = c.pitch;
      c.last.timing_ms = s.timing_ms;
      c.last.undercut = s.undercut;
      c.last.result = swing_at(assets, c.pitch, s, batter_skill("pro").bat_speed);
      c.last.call_text = to_string(c.last.result.outcome);
      c.swings.push_back(c.last);
      char text[96];
      if (c.last.result.contact)
        std::snprintf(text, sizeof text, "%s  %.0f mph, %.0f deg, %.0f ft", c.last.call_text.c_str(),
                      mps_to_mph(c.last.result.shot.launch.ball_speed), rad_to_deg(c.last.result.shot.launch.vertical_angle),
                      m_to_ft(c.last.result.shot.trajectory.summary.carry_m));
      else
        std::snprintf(text, sizeof text, "strike (%+.0f ms)", s.timing_ms);
      c.call_text = text;
      if (c.last.result.contact) {
        c.scene->set_shot(c.last.result.shot.trajectory, std::nullopt);
        c.replay.restart();
        c.stage = Cage::Stage::Batted;
      } else {
        c.stage = Cage::Stage::Called;
        c.called_at = now;
      }
    };
    for (const int key : fin.keys) {
      if (key == GLFW_KEY_TAB) return WindowNext::Lab;
      if (key == GLFW_KEY_UP) c.bat_height += 0.01;
      if (key == GLFW_KEY_DOWN) c.bat_height -= 0.01;
      c.bat_height = std::clamp(c.bat_height, kZoneLow - 0.3, kZoneHigh + 0.3);
      if (key == GLFW_KEY_C) c.power = !c.power;
      if (key == GLFW_KEY_L) c.lefty = !c.lefty;
      if ((key == GLFW_KEY_P || (key == GLFW_KEY_SPACE && c.stage != Cage::Stage::Pitching)) &&
          c.stage != Cage::Stage::Pitching) {
        c.call = derby_pitch(c.types, c.rng);
        c.pitch = throw_pitch(assets, c.call);
        c.scene->set_shot(c.pitch.trajectory, std::nullopt);
        c.pitch_clock = 0.0;
        c.stage = Cage::Stage::Pitching;
        c.call_text.clear();
        continue;
      }
      if (c.stage == Cage::Stage::Pitching && key == GLFW_KEY_SPACE) {
        SwingInput s;
        s.timing_ms = 1000.0 * (c.pitch_clock - c.pitch.flight_time);
        s.timing_ms = std::clamp(s.timing_ms, SwingInput::kTiming.min, SwingInput::kTiming.max);
        s.undercut = std::clamp(c.pitch.plate.y() - c.bat_height, SwingInput::kUndercut.min, SwingInput::kUndercut.max);
        s.power = c.power;
        s.left_handed = c.lefty;
        swing(s);
      }
      if (c.stage == Cage::Stage::Pitching && key == GLFW_KEY_B) swing(c.bot.plan(c.pitch, true, c.lefty));
    }
    if (c.stage == Cage::Stage::Pitching) {
      c.pitch_clock += dt * kPitchTimeScale;
      if (c.pitch_clock > c.pitch.flight_time + 0.15) {  // taken: called by the zone
        c.last = SwingRecord{};
        c.last.call = c.call;
        c.last.pitch = c.pitch;
        c.last.swung = false;
        c.call_text = in_zone(c.pitch.plate, 0.0369) ? "called strike" : "ball";
        c.stage = Cage::Stage::Called;
        c.called_at = now;
      }
    }
    if (c.stage == Cage::Stage::Batted) {
      c.replay.advance(dt, duration(c.last.result.shot.trajectory));
      if (!c.replay.playing) {
        c.stage = Cage::Stage::Called;
        c.called_at = now;
      }
    }
    const int w = win.framebuffer_width(), h = win.framebuffer_height();
    if (w > 0 && h > 0) {
      if (w != renderer.width() || h != renderer.height()) renderer.resize(w, h);
      const bool batted = c.stage == Cage::Stage::Batted || (c.stage == Cage::Stage::Called && c.last.result.contact);
      const double t = c.stage == Cage::Stage::Pitching ? std::min(c.pitch_clock, c.pitch.flight_time)
                       : batted ? (c.stage == Cage::Stage::Batted ? c.replay.time : duration(c.last.result.shot.trajectory))
                                : c.pitch.flight_time;
      const Camera cam = batted ? c.scene->camera(CameraKind::Behind, t, w, h) : batter_view();
      renderer.draw(c.scene->build(cam, t, w, h), cam);
      renderer.blit_to(0, w, h);
      if (!batted) draw_zone(c, cam, w, h);
    }
    draw_stats(c, w, h);
    if (!c.call_text.empty()) {
      ImDrawList* dl = ImGui::GetForegroundDrawList();
      const ImVec2 pos(0.5f * static_cast<float>(w) - 160.0f, 60.0f);
      dl->AddRectFilled(ImVec2(pos.x - 10, pos.y - 6), ImVec2(pos.x + 330, pos.y + 24), IM_COL32(0, 0, 0, 170), 4.0f);
      dl->AddText(pos, IM_COL32(255, 230, 120, 255), c.call_text.c_str());
    }
    win.render_ui();
    bool finish = false;
    if (o.exit_when_done && o.pitches > 0 && static_cast<int>(c.swings.size()) >= o.pitches && c.stage == Cage::Stage::Called)
      finish = ++c.done_frames >= 30;
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    if (end_frame(win, o, stats, ms, out, finish)) {
      for (const SwingRecord& s : c.swings) out << "swing: " << s.call_text << "\n";
      return WindowNext::Quit;
    }
  }
  return WindowNext::Quit;
}

}  // namespace sweetspot
