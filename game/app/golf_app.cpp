#include "game/app/golf_app.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "game/content/course_file.hpp"
#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/meter_clock.hpp"
#include "game/render/image.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "game/report/round_json.hpp"
#include "game/ui/replay.hpp"
#include "physics/units.hpp"
#include "game/core/shot_result.hpp"

namespace sweetspot {
namespace {

using Clock = std::chrono::steady_clock;

// A trajectory of one sample: the ball at rest where it lies (the scene draws it there).
ShotTrajectory resting(const Vec3& centre) {
  ShotTrajectory t;
  TrajectorySample s;
  s.position = centre;
  s.phase = Phase::Rest;
  t.samples = {s, s};
  t.summary.landing_position = t.summary.rest_position = centre;
  return t;
}

// Downhill arrows on the green around the cup: where the ground tilts and how much.
struct SlopeArrow {
  Vec3 at, downhill;  // downhill: horizontal unit, scaled by the slope (rise over run)
};
std::vector<SlopeArrow> green_slopes(const WorldAsset& w, const Vec3& ball, const Vec3& pin) {
  std::vector<SlopeArrow> out;
  const Vec3 mid = 0.5 * (ball + pin);
  const double span = std::clamp(0.6 * std::hypot(pin.x() - ball.x(), pin.z() - ball.z()) + 3.0, 4.0, 14.0);
  for (double dx = -span; dx <= span + 1e-9; dx += span / 5.0) {
    for (double dz = -span; dz <= span + 1e-9; dz += span / 5.0) {
      SurfaceContact hit;
      if (!ground_under(*w.world, mid.x() + dx, mid.z() + dz, 400.0, 420.0, &hit)) continue;
      if (w.world->material(hit.material).kind != SurfaceKind::Green) continue;
      const Vec3& n = hit.normal;
      const Vec3 flat(n.x(), 0.0, n.z());
      out.push_back({hit.point, flat / std::max(n.y(), 1e-6)});
    }
  }
  return out;
}

struct GolfView {
  enum class Stage { Aiming, Swinging, Flying, HoleOver, RoundOver };
  GolfView(const Assets& a, const Course& c, const GolferSkill& skill)
      : assets(a), round(a, c, skill), caddie(a, skill, 1) {}

  const Assets& assets;
  GolfRound round;
  GolfBot caddie;
  std::vector<int> bot_strokes;  // the opponent: a bot of the same skill, played before we start
  std::unique_ptr<ShotScene> scene;
  std::size_t scene_hole = 99;
  std::string scene_mesh;
  bool scene_tee = false;
  Stage stage = Stage::Aiming;
  std::size_t club = 0;  // index in golf_bag()
  double aim = 0.0;      // rad right of the pin line
  std::optional<MeterClock> meter;
  ReplayState replay;
  ShotResult last;
  std::string message;
  std::vector<SlopeArrow> slopes;
  int done_frames = 0;

  const std::string& club_name() const { return golf_bag()[club]; }
  void choose_club() {
    const std::string want = round.lie() == "green" ? "putter" : caddie.suggest(round.to_pin(), round.teed());
    club = static_cast<std::size_t>(std::find(golf_bag().begin(), golf_bag().end(), want) - golf_bag().begin());
    aim = 0.0;
    slopes = round.lie() == "green" ? green_slopes(*round.hole().world, round.ball(), round.hole().pin)
                                    : std::vector<SlopeArrow>{};
  }
  // The scene of the current hole with the current club's head; rebuilt only when they change.
  void ensure_scene(const Assets& a) {
    const EquipmentCatalog& eq = a.equipment();
    const std::string mesh = eq.club_info_of(club_name()).mesh;
    const bool tee = round.teed() && round.lie() == "tee";
    if (scene && scene_hole == round.hole_index() && scene_mesh == mesh && scene_tee == tee) return;
    ShotSceneInput in;
    in.assets = &a;
    in.world = round.hole().world;
    in.distance_unit = "yd";
    in.ball_radius = eq.ball("tour").radius;
    in.tee = tee;
    in.impactor_mesh = mesh;
    in.flag = round.hole().pin;
    scene = std::make_unique<ShotScene>(in);
    scene_hole = round.hole_index();
    scene_mesh = mesh;
    scene_tee = tee;
  }
  Vec3 ball_centre() const {
    const double tee = round.teed() && round.lie() == "tee" ? assets.equipment().club_info_of(club_name()).tee_height : 0.0;
    return round.ball() + Vec3(0.0, 0.021335 + tee, 0.0);
  }
  Vec3 aim_dir() const {
    const double a = round.line_to_pin() + aim;
    return Vec3(std::cos(a), 0.0, std::sin(a));
  }
  // Between holes: looking down on the green of the hole just played.
  Camera green_camera() const {
    const CourseHole& h = round.course().holes[std::min(scene_hole, round.course().holes.size() - 1)];
    Vec3 d(h.pin.x() - h.tee.x(), 0.0, h.pin.z() - h.tee.z());
    d.normalize();
    Camera c;
    c.eye = h.pin - 30.0 * d + Vec3(0.0, 22.0, 0.0);
    c.target = h.pin;
    c.fov_y = deg_to_rad(40.0);
    return c;
  }
  Camera address_camera(int w, int h) const {
    (void)w;
    (void)h;
    Camera c;
    const Vec3 b = ball_centre();
    const bool putt = round.lie() == "green";
    const Vec3 d = aim_dir();
    // Behind the ball looking down the aim line: low and close for a putt, higher and
    // farther back for a full shot so the target area sits in the upper half of the view.
    const double reach = std::min(round.to_pin(), 220.0);
    c.eye = b - (putt ? 2.6 : 14.0) * d + Vec3(0.0, putt ? 1.5 : 5.0, 0.0);
    c.target = b + (putt ? std::min(round.to_pin(), 12.0) + 0.5 : 0.8 * reach) * d;
    c.target.y() = b.y() + (putt ? -0.3 : -2.0);
    c.fov_y = deg_to_rad(putt ? 50.0 : 26.0);
    return c;
  }
};

void draw_hud(GolfView& v, int w, int h, double now) {
  const GolfRound& r = v.round;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_Always);
  ImGui::Begin("Play", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  if (!r.finished()) {
    const CourseHole& hole = r.hole();
    ImGui::Text("%s", r.course().name.c_str());
    ImGui::Text("Hole %d   Par %d   %.0f m (%.0f yd)", hole.number, hole.par, hole.length(), m_to_yd(hole.length()));
    const HoleCard& card = r.card().back();
    ImGui::Text("Stroke %d   lie: %s", card.strokes + 1, r.lie().c_str());
    ImGui::Text("To the pin: %.1f m (%.0f yd)", r.to_pin(), m_to_yd(r.to_pin()));
    ImGui::Text("Wind: calm");
    ImGui::Separator();
    const std::string& club = v.club_name();
    double carry = 0.0;
    for (const GolfBot::Stock& s : v.caddie.stock())
      if (s.club == club) carry = s.carry;
    if (club == "putter") ImGui::Text("Club: putter");
    else ImGui::Text("Club: %s (full carry %.0f m)", club.c_str(), carry);
    ImGui::Text("Aim: %.1f deg %s of the pin", std::abs(rad_to_deg(v.aim)), v.aim >= 0 ? "right" : "left");
    ImGui::TextDisabled("Up/Down club  Left/Right aim  C caddie's club");
    ImGui::TextDisabled("Space: swing (3 clicks; putts 2)  B: caddie plays");
    ImGui::TextDisabled("Tab: batting cage");
    int total = 0, par = 0;
    for (const HoleCard& c : r.card())
      if (&c != &r.card().back()) {
        total += c.strokes;
        par += c.par;
      }
    if (par > 0) ImGui::Text("Score: %d (%+d)", total, total - par);
  }
  if (!v.message.empty()) ImGui::TextWrapped("%s", v.message.c_str());
  ImGui::End();

  // The meter, bottom centre: 0 (the accuracy mark) to 110 %.
  if (v.stage == GolfView::Stage::Aiming || v.stage == GolfView::Stage::Swinging) {
    const float bw = 520.0f, bh = 26.0f;
    const float x0 = 0.5f * (static_cast<float>(w) - bw), y0 = static_cast<float>(h) - 70.0f;
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const float span = bw / 1.25f;  // −15 % .. 110 %
    const auto at = [&](double f) { return x0 + static_cast<float>((f + 0.15) * span); };
    dl->AddRectFilled(ImVec2(x0, y0), ImVec2(x0 + bw, y0 + bh), IM_COL32(20, 24, 30, 220), 4.0f);
    dl->AddRectFilled(ImVec2(at(-0.03), y0), ImVec2(at(0.03), y0 + bh), IM_COL32(60, 170, 80, 230));   // the mark
    dl->AddLine(ImVec2(at(1.0), y0 - 4), ImVec2(at(1.0), y0 + bh + 4), IM_COL32(250, 250, 250, 255), 2.0f);
    if (v.meter) {
      const double p = v.meter->position(now);
      if (v.meter->phase() == MeterClock::Phase::Backswing)
        dl->AddRectFilled(ImVec2(at(0.0), y0 + 4), ImVec2(at(p), y0 + bh - 4), IM_COL32(230, 180, 40, 255));
      if (v.meter->phase() == MeterClock::Phase::Downswing) {
        dl->AddRectFilled(ImVec2(at(0.0), y0 + 4), ImVec2(at(v.meter->power()), y0 + bh - 4), IM_COL32(230, 180, 40, 120));
        dl->AddLine(ImVec2(at(p), y0 - 6), ImVec2(at(p), y0 + bh + 6), IM_COL32(255, 80, 60, 255), 3.0f);
      }
    }
    char label[96];
    if (v.meter) std::snprintf(label, sizeof label, "power %.0f %%", 100.0 * v.meter->position(now));
    else std::snprintf(label, sizeof label, "%s: Space to swing", v.club_name().c_str());
    dl->AddText(ImVec2(x0, y0 - 22), IM_COL32(255, 255, 255, 255), label);
  }
}

void draw_card(const GolfView& v, int w, bool final) {
  ImGui::SetNextWindowPos(ImVec2(0.5f * static_cast<float>(w) - 230, 160), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(460, 0), ImGuiCond_Always);
  ImGui::Begin(final ? "Final scorecard" : "Scorecard", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::Text("%-6s %4s %8s %6s %9s %8s", "hole", "par", "strokes", "putts", "penalties", "bot");
  int total = 0, par = 0, bot = 0;
  for (std::size_t i = 0; i < v.round.card().size(); ++i) {
    const HoleCard& c = v.round.card()[i];
    if (!final && &c == &v.round.card().back() && !v.round.finished() && c.strokes == 0) continue;
    const int b = i < v.bot_strokes.size() ? v.bot_strokes[i] : 0;
    ImGui::Text("%-6d %4d %8d %6d %9d %8d", c.number, c.par, c.strokes, c.putts, c.penalties, b);
    total += c.strokes;
    par += c.par;
    bot += b;
  }
  ImGui::Separator();
  ImGui::Text("%-6s %4d %8d %+6d %18d", "total", par, total, total - par, bot);
  ImGui::TextDisabled(final ? "Enter: play again   Tab: Lab" : "Enter: next hole");
  ImGui::End();
}

// Aim line and green slopes, drawn over the 3-D view.
void draw_overlays(const GolfView& v, const Camera& cam, int w, int h) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const Vec3 b = v.ball_centre();
  const double len = v.round.lie() == "green" ? v.round.to_pin() + 1.0 : std::min(v.round.to_pin(), 250.0);
  auto p0 = cam.project(b, w, h);
  auto p1 = cam.project(b + len * v.aim_dir(), w, h);
  if (p0 && p1)
    dl->AddLine(ImVec2(static_cast<float>((*p0)(0)), static_cast<float>((*p0)(1))),
                ImVec2(static_cast<float>((*p1)(0)), static_cast<float>((*p1)(1))), IM_COL32(255, 255, 255, 160), 2.0f);
  for (const SlopeArrow& a : v.slopes) {
    const double s = a.downhill.norm();
    const Vec3 dir = s > 1e-6 ? Vec3(0.6 * a.downhill / s) : Vec3(Vec3::Zero());
    const Vec3 tip = a.at + Vec3(0, 0.01, 0) + dir;
    auto q0 = cam.project(a.at + Vec3(0, 0.01, 0), w, h), q1 = cam.project(tip, w, h);
    if (!q0 || !q1) continue;
    const int red = static_cast<int>(std::clamp(s / 0.04, 0.0, 1.0) * 255);
    dl->AddLine(ImVec2(static_cast<float>((*q0)(0)), static_cast<float>((*q0)(1))),
                ImVec2(static_cast<float>((*q1)(0)), static_cast<float>((*q1)(1))), IM_COL32(red, 255 - red / 2, 255 - red, 220),
                2.0f);
    dl->AddCircleFilled(ImVec2(static_cast<float>((*q1)(0)), static_cast<float>((*q1)(1))), 2.5f,
                        IM_COL32(red, 255 - red / 2, 255 - red, 220));
  }
}

}  // namespace

bool end_frame(GameWindow& win, const PlayOptions& o, FrameStats& stats, double frame_ms, std::ostream& out,
               bool force_last) {
  ++stats.frames;
  stats.ms_total += frame_ms;
  stats.frame_ms.push_back(frame_ms);
  const bool last = force_last || (o.frames > 0 && stats.frames >= o.frames);
  if (last && !o.screenshot.empty()) {
    int sw = 0, sh = 0;
    std::vector<unsigned char> rgba;
    win.read_pixels(sw, sh, rgba);
    write_png_atomic(o.screenshot, sw, sh, rgba);
    out << "screenshot: " << o.screenshot << " (" << sw << "x" << sh << ")\n";
  }
  win.present();
  return last;
}

WindowNext run_golf_loop(const Assets& assets, GameWindow& win, Renderer& renderer, const PlayOptions& o,
                         FrameStats& stats, std::ostream& out) {
  Course course = load_course(assets, o.course);
  if (o.holes > 0 && static_cast<std::size_t>(o.holes) < course.holes.size()) course.holes.resize(static_cast<std::size_t>(o.holes));
  const GolferSkill& skill = golfer_skill(o.skill);
  auto v = std::make_unique<GolfView>(assets, course, skill);
  {
    // The opponent: a bot of the same skill plays the course first (seeded, so the same card each time).
    GolfRound bot_round(assets, course, skill);
    GolfBot bot(assets, skill, 7);
    while (!bot_round.finished()) bot_round.play(bot.plan(bot_round));
    for (const HoleCard& c : bot_round.card()) v->bot_strokes.push_back(c.strokes);
  }
  v->choose_club();
  const auto t_origin = Clock::now();
  auto last = t_origin;
  while (!win.should_close()) {
    const auto t0 = Clock::now();
    const double now = std::chrono::duration<double>(t0 - t_origin).count();
    const double dt = std::chrono::duration<double>(t0 - last).count();
    last = t0;
    const FrameInput in = win.begin_frame();
    GolfView& g = *v;
    for (const int key : in.keys) {
      if (key == GLFW_KEY_TAB) return WindowNext::Baseball;
      switch (g.stage) {
        case GolfView::Stage::Aiming:
          if (key == GLFW_KEY_LEFT) g.aim -= deg_to_rad(g.club_name() == "putter" ? 0.25 : 1.0);
          if (key == GLFW_KEY_RIGHT) g.aim += deg_to_rad(g.club_name() == "putter" ? 0.25 : 1.0);
          g.aim = std::clamp(g.aim, StrokeInput::kAim.min, StrokeInput::kAim.max);
          if (key == GLFW_KEY_UP && g.club > 0) --g.club;
          if (key == GLFW_KEY_DOWN && g.club + 1 < golf_bag().size()) ++g.club;
          if (key == GLFW_KEY_C) g.choose_club();
          if (key == GLFW_KEY_SPACE) {
            const double length = assets.equipment().club(g.club_name()).length;
            g.meter.emplace(MeterClock::tempo_for(length, g.club_name() == "putter"), g.club_name() == "putter");
            g.meter->click(now);
            g.stage = GolfView::Stage::Swinging;
          }
          if (key == GLFW_KEY_B) {  // the caddie plays this one (the bot's swing, same skill)
            StrokeInput s = g.caddie.plan(g.round);
            g.club = static_cast<std::size_t>(std::find(golf_bag().begin(), golf_bag().end(), s.club) - golf_bag().begin());
            g.aim = s.aim;
            g.meter.emplace(1.0, s.club == "putter");
            g.stage = GolfView::Stage::Swinging;
            // Played at once below with the bot's meter.
            g.message = "caddie: " + s.club;
            const std::size_t hole_before = g.round.hole_index();
            g.ensure_scene(assets);
            const StrokeRecord rec = g.round.play(s, &g.last);
            g.meter.reset();
            g.scene->set_shot(g.last.trajectory, impactor_placement(g.last));
            g.replay.restart();
            g.stage = GolfView::Stage::Flying;
            g.message = std::string(to_string(rec.end)) + (rec.penalty ? " (penalty)" : "");
            (void)hole_before;
          }
          break;
        case GolfView::Stage::Swinging:
          if (key == GLFW_KEY_SPACE && g.meter) g.meter->click(now);
          break;
        case GolfView::Stage::Flying:
          if (key == GLFW_KEY_SPACE || key == GLFW_KEY_ENTER) g.replay.time = duration(g.last.trajectory);
          break;
        case GolfView::Stage::HoleOver:
          if (key == GLFW_KEY_ENTER || key == GLFW_KEY_SPACE) {
            g.stage = GolfView::Stage::Aiming;
            g.choose_club();
            g.message.clear();
          }
          break;
        case GolfView::Stage::RoundOver:
          if (key == GLFW_KEY_ENTER && o.exit_when_done == false) {
            v = std::make_unique<GolfView>(assets, course, skill);
            v->choose_club();
          }
          break;
      }
    }
    GolfView& gv = *v;
    if (gv.stage == GolfView::Stage::Swinging && gv.meter) {
      gv.meter->update(now);
      if (const auto m = gv.meter->result()) {
        StrokeInput s;
        s.club = gv.club_name();
        s.aim = gv.aim;
        s.meter = *m;
        gv.ensure_scene(assets);
        const StrokeRecord rec = gv.round.play(s, &gv.last);
        char msg[160];
        std::snprintf(msg, sizeof msg, "%s: power %.0f %%, %+.0f ms -> %s%s", s.club.c_str(), 100.0 * m->power, m->accuracy_ms,
                      to_string(rec.end), rec.penalty ? " (penalty stroke)" : "");
        gv.message = msg;
        gv.meter.reset();
        gv.scene->set_shot(gv.last.trajectory, impactor_placement(gv.last));
        gv.replay.restart();
        gv.stage = GolfView::Stage::Flying;
      }
    }
    if (gv.stage == GolfView::Stage::Flying) {
      gv.replay.advance(dt, duration(gv.last.trajectory));
      if (!gv.replay.playing) {
        const bool hole_done = gv.round.finished() || gv.round.card().back().shots.empty();
        if (gv.round.finished()) gv.stage = GolfView::Stage::RoundOver;
        else if (hole_done) gv.stage = GolfView::Stage::HoleOver;
        else {
          gv.stage = GolfView::Stage::Aiming;
          gv.choose_club();
        }
      }
    }

    // Draw: the hole, the ball where it lies (or flying), the overlays, the panels.
    const int w = win.framebuffer_width(), h = win.framebuffer_height();
    if (gv.stage == GolfView::Stage::Aiming || gv.stage == GolfView::Stage::Swinging) {
      gv.ensure_scene(assets);
      gv.scene->set_shot(resting(gv.ball_centre()), std::nullopt);
      // The 50 yd lines run from the ball along the player's aim: the aiming aid.
      gv.scene->set_aim(gv.aim_dir());
    } else if (gv.scene) {
      gv.scene->set_aim(std::nullopt);  // the shot's own line from where it was hit
    }
    if (w > 0 && h > 0 && gv.scene) {
      if (w != renderer.width() || h != renderer.height()) renderer.resize(w, h);
      const bool flying = gv.stage == GolfView::Stage::Flying;
      const Camera cam = flying ? gv.scene->camera(CameraKind::Follow, gv.replay.time, w, h)
                       : gv.stage == GolfView::Stage::Aiming || gv.stage == GolfView::Stage::Swinging
                           ? gv.address_camera(w, h)
                           : gv.green_camera();
      const bool over = gv.stage == GolfView::Stage::HoleOver || gv.stage == GolfView::Stage::RoundOver;
      renderer.draw(gv.scene->build(cam, flying ? gv.replay.time : over ? duration(gv.last.trajectory) : 0.0, w, h), cam);
      renderer.blit_to(0, w, h);
      if (gv.stage == GolfView::Stage::Aiming || gv.stage == GolfView::Stage::Swinging) draw_overlays(gv, cam, w, h);
    }
    draw_hud(gv, w, h, now);
    if (gv.stage == GolfView::Stage::HoleOver) draw_card(gv, w, false);
    if (gv.stage == GolfView::Stage::RoundOver) draw_card(gv, w, true);
    win.render_ui();
    bool finish = false;
    if (gv.stage == GolfView::Stage::RoundOver) {
      if (gv.done_frames == 0) out << round_table(gv.round, skill.name + " player");
      ++gv.done_frames;
      finish = o.exit_when_done && gv.done_frames >= 10;
    }
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    if (end_frame(win, o, stats, ms, out, finish)) return WindowNext::Quit;
  }
  return WindowNext::Quit;
}

}  // namespace sweetspot
