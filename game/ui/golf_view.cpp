#include "game/ui/golf_view.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "game/modes/replay.hpp"
#include "game/render/renderer.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "game/report/round_json.hpp"
#include "physics/units.hpp"

namespace sweetspot {

Intents golf_intents(const std::vector<KeyPress>& keys) {
  return intents_from_keys(keys, {{GLFW_KEY_SPACE, IntentKind::Swing},
                                  {GLFW_KEY_LEFT, IntentKind::AimLeft},
                                  {GLFW_KEY_RIGHT, IntentKind::AimRight},
                                  {GLFW_KEY_UP, IntentKind::ClubUp},
                                  {GLFW_KEY_DOWN, IntentKind::ClubDown},
                                  {GLFW_KEY_C, IntentKind::CaddieClub},
                                  {GLFW_KEY_B, IntentKind::CaddiePlays},
                                  {GLFW_KEY_ENTER, IntentKind::Continue},
                                  {GLFW_KEY_KP_ENTER, IntentKind::Continue}});
}

namespace {

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

class GolfView final : public ModeView {
 public:
  GolfView(const Assets& a, std::unique_ptr<GolfPlay> m, const GolfViewOptions& o, std::ostream& out)
      : assets_(a), play_(std::move(m)), options_(o), out_(out) {}

  const char* title() const override { return "Golf"; }
  const char* restart_label() const override { return "Restart hole"; }
  bool done() const override { return options_.exit_when_done && done_frames_ >= 10; }
  void send(const Intent& in) override { play_->update({in}, in.time); }
  void frame(const ViewInput& in, Renderer& renderer) override;
  void report(std::ostream& out) const override {
    const GolfRound& r = play_->round();
    out << "golf: hole " << std::min(r.hole_index() + 1, r.course().holes.size()) << " of " << r.course().holes.size() << ", "
        << r.total_strokes() << " strokes, " << play_->cancelled() << " swings cancelled, " << to_string(play_->stage()) << "\n";
  }

 private:
  void ensure_scene();
  Camera address_camera() const;
  Camera green_camera() const;
  void draw_hud(int w, int h, double now);
  void draw_card(int w, bool final) const;
  void draw_overlays(const Camera& cam, int w, int h) const;

  const Assets& assets_;
  std::unique_ptr<GolfPlay> play_;
  GolfViewOptions options_;
  std::ostream& out_;
  std::unique_ptr<ShotScene> scene_;
  std::size_t scene_hole_ = 99;
  std::string scene_mesh_;
  bool scene_tee_ = false;
  bool flight_shown_ = false;      // the scene holds the last stroke's flight
  std::size_t slopes_for_ = 99;    // card size the slopes were read for
  Vec3 slopes_ball_ = Vec3::Zero();
  std::vector<SlopeArrow> slopes_;
  int done_frames_ = 0;
};

void GolfView::ensure_scene() {
  const GolfRound& r = play_->round();
  const EquipmentCatalog& eq = assets_.equipment();
  const std::string mesh = eq.club_info_of(play_->club()).mesh;
  const bool tee = r.teed() && r.lie() == "tee";
  if (scene_ && scene_hole_ == r.hole_index() && scene_mesh_ == mesh && scene_tee_ == tee) return;
  ShotSceneInput in;
  in.assets = &assets_;
  in.world = r.hole().world;
  in.distance_unit = "yd";
  in.ball_radius = eq.ball("tour").radius;
  in.tee = tee;
  in.impactor_mesh = mesh;
  in.flag = r.hole().pin;
  scene_ = std::make_unique<ShotScene>(in);
  scene_hole_ = r.hole_index();
  scene_mesh_ = mesh;
  scene_tee_ = tee;
}

// Between holes: looking down on the green of the hole just played.
Camera GolfView::green_camera() const {
  const Course& course = play_->round().course();
  const CourseHole& h = course.holes[std::min(scene_hole_, course.holes.size() - 1)];
  Vec3 d(h.pin.x() - h.tee.x(), 0.0, h.pin.z() - h.tee.z());
  d.normalize();
  Camera c;
  c.eye = h.pin - 30.0 * d + Vec3(0.0, 22.0, 0.0);
  c.target = h.pin;
  c.fov_y = deg_to_rad(40.0);
  return c;
}

Camera GolfView::address_camera() const {
  const GolfRound& r = play_->round();
  Camera c;
  const Vec3 b = play_->ball_centre();
  const bool putt = r.lie() == "green";
  const Vec3 d = play_->aim_direction();
  // Behind the ball looking down the aim line: low and close for a putt, higher and
  // farther back for a full shot so the target area sits in the upper half of the view.
  const double reach = std::min(r.to_pin(), 220.0);
  c.eye = b - (putt ? 2.6 : 14.0) * d + Vec3(0.0, putt ? 1.5 : 5.0, 0.0);
  c.target = b + (putt ? std::min(r.to_pin(), 12.0) + 0.5 : 0.8 * reach) * d;
  c.target.y() = b.y() + (putt ? -0.3 : -2.0);
  c.fov_y = deg_to_rad(putt ? 50.0 : 26.0);
  return c;
}

void GolfView::draw_hud(int w, int h, double now) {
  const GolfRound& r = play_->round();
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
    const std::string& club = play_->club();
    double carry = 0.0;
    for (const GolfBot::Stock& s : play_->caddie().stock())
      if (s.club == club) carry = s.carry;
    if (club == "putter") ImGui::Text("Club: putter");
    else ImGui::Text("Club: %s (full carry %.0f m)", club.c_str(), carry);
    ImGui::Text("Aim: %.1f deg %s of the pin", std::abs(rad_to_deg(play_->aim())), play_->aim() >= 0 ? "right" : "left");
    ImGui::TextDisabled("Up/Down club  Left/Right aim  C caddie's club");
    ImGui::TextDisabled("Space: swing (3 clicks; putts 2)  B: caddie plays");
    ImGui::TextDisabled("Esc: cancel the swing, pause  Tab: next mode");
    int total = 0, par = 0;
    for (const HoleCard& c : r.card())
      if (&c != &r.card().back()) {
        total += c.strokes;
        par += c.par;
      }
    if (par > 0) ImGui::Text("Score: %d (%+d)", total, total - par);
  }
  if (!play_->message().empty()) ImGui::TextWrapped("%s", play_->message().c_str());
  ImGui::End();

  // The meter, bottom centre: 0 (the accuracy mark) to 110 %.
  const GolfPlay::Stage stage = play_->stage();
  if (stage == GolfPlay::Stage::Aiming || stage == GolfPlay::Stage::Swinging) {
    const float bw = 520.0f, bh = 26.0f;
    const float x0 = 0.5f * (static_cast<float>(w) - bw), y0 = static_cast<float>(h) - 70.0f;
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const float span = bw / 1.25f;  // −15 % .. 110 %
    const auto at = [&](double f) { return x0 + static_cast<float>((f + 0.15) * span); };
    dl->AddRectFilled(ImVec2(x0, y0), ImVec2(x0 + bw, y0 + bh), IM_COL32(20, 24, 30, 220), 4.0f);
    dl->AddRectFilled(ImVec2(at(-0.03), y0), ImVec2(at(0.03), y0 + bh), IM_COL32(60, 170, 80, 230));  // the mark
    dl->AddLine(ImVec2(at(1.0), y0 - 4), ImVec2(at(1.0), y0 + bh + 4), IM_COL32(250, 250, 250, 255), 2.0f);
    const auto& meter = play_->meter();
    if (meter) {
      const double p = meter->position(now);
      if (meter->phase() == MeterClock::Phase::Backswing)
        dl->AddRectFilled(ImVec2(at(0.0), y0 + 4), ImVec2(at(p), y0 + bh - 4), IM_COL32(230, 180, 40, 255));
      if (meter->phase() == MeterClock::Phase::Downswing) {
        dl->AddRectFilled(ImVec2(at(0.0), y0 + 4), ImVec2(at(meter->power()), y0 + bh - 4), IM_COL32(230, 180, 40, 120));
        dl->AddLine(ImVec2(at(p), y0 - 6), ImVec2(at(p), y0 + bh + 6), IM_COL32(255, 80, 60, 255), 3.0f);
      }
    }
    char label[96];
    if (meter) std::snprintf(label, sizeof label, "power %.0f %%   Esc: cancel", 100.0 * meter->position(now));
    else std::snprintf(label, sizeof label, "%s: Space to swing", play_->club().c_str());
    dl->AddText(ImVec2(x0, y0 - 22), IM_COL32(255, 255, 255, 255), label);
  }
}

void GolfView::draw_card(int w, bool final) const {
  const GolfRound& r = play_->round();
  const std::vector<int>& opponent = play_->opponent_strokes();
  ImGui::SetNextWindowPos(ImVec2(0.5f * static_cast<float>(w) - 230, 160), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(460, 0), ImGuiCond_Always);
  ImGui::Begin(final ? "Final scorecard" : "Scorecard", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::Text("%-6s %4s %8s %6s %9s %8s", "hole", "par", "strokes", "putts", "penalties", "bot");
  int total = 0, par = 0, bot = 0;
  for (std::size_t i = 0; i < r.card().size(); ++i) {
    const HoleCard& c = r.card()[i];
    if (!final && &c == &r.card().back() && !r.finished() && c.strokes == 0) continue;
    const int b = i < opponent.size() ? opponent[i] : 0;
    ImGui::Text("%-6d %4d %8d %6d %9d %8d", c.number, c.par, c.strokes, c.putts, c.penalties, b);
    total += c.strokes;
    par += c.par;
    bot += b;
  }
  ImGui::Separator();
  ImGui::Text("%-6s %4d %8d %+6d %18d", "total", par, total, total - par, bot);
  ImGui::TextDisabled(final ? "Enter: play again   Tab: next mode" : "Enter: next hole");
  ImGui::End();
}

// Aim line and green slopes, drawn over the 3-D view.
void GolfView::draw_overlays(const Camera& cam, int w, int h) const {
  const GolfRound& r = play_->round();
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const Vec3 b = play_->ball_centre();
  const double len = r.lie() == "green" ? r.to_pin() + 1.0 : std::min(r.to_pin(), 250.0);
  auto p0 = cam.project(b, w, h);
  auto p1 = cam.project(b + len * play_->aim_direction(), w, h);
  if (p0 && p1)
    dl->AddLine(ImVec2(static_cast<float>((*p0)(0)), static_cast<float>((*p0)(1))),
                ImVec2(static_cast<float>((*p1)(0)), static_cast<float>((*p1)(1))), IM_COL32(255, 255, 255, 160), 2.0f);
  for (const SlopeArrow& a : slopes_) {
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

void GolfView::frame(const ViewInput& in, Renderer& renderer) {
  play_->update(golf_intents(in.keys), in.now);
  const GolfPlay::Stage stage = play_->stage();
  const GolfRound& r = play_->round();
  const int w = in.width, h = in.height;
  const bool addressing = stage == GolfPlay::Stage::Aiming || stage == GolfPlay::Stage::Swinging;
  const bool flying = stage == GolfPlay::Stage::Flying;
  const bool over = stage == GolfPlay::Stage::HoleOver || stage == GolfPlay::Stage::RoundOver;
  if (addressing) {
    ensure_scene();
    scene_->set_shot(resting(play_->ball_centre()), std::nullopt);
    // The 50 yd lines run from the ball along the player's aim: the aiming aid.
    scene_->set_aim(play_->aim_direction());
    flight_shown_ = false;
    const bool green = r.lie() == "green";
    if (green && (slopes_for_ != r.card().size() || slopes_ball_ != r.ball())) {
      slopes_ = green_slopes(*r.hole().world, r.ball(), r.hole().pin);
      slopes_for_ = r.card().size();
      slopes_ball_ = r.ball();
    } else if (!green) {
      slopes_.clear();
    }
  } else if (scene_) {
    scene_->set_aim(std::nullopt);  // the shot's own line from where it was hit
    if (!flight_shown_) {
      scene_->set_shot(play_->last_shot().trajectory, impactor_placement(play_->last_shot()));
      flight_shown_ = true;
    }
  }
  const double end = duration(play_->last_shot().trajectory);
  const double t = flying ? std::clamp(in.now - play_->struck_at(), 0.0, end) : over ? end : 0.0;
  if (w > 0 && h > 0 && scene_) {
    if (w != renderer.width() || h != renderer.height()) renderer.resize(w, h);
    const Camera cam = flying ? scene_->camera(CameraKind::Follow, t, w, h) : addressing ? address_camera() : green_camera();
    renderer.draw(scene_->build(cam, t, w, h), cam);
    renderer.blit_to(0, w, h);
    if (addressing) draw_overlays(cam, w, h);
  }
  draw_hud(w, h, in.now);
  if (stage == GolfPlay::Stage::HoleOver) draw_card(w, false);
  if (stage == GolfPlay::Stage::RoundOver) {
    draw_card(w, true);
    if (done_frames_ == 0) out_ << round_table(r, play_->skill().name + " player");
    ++done_frames_;
  } else {
    done_frames_ = 0;
  }
}

}  // namespace

std::unique_ptr<ModeView> make_golf_view(const Assets& assets, std::unique_ptr<GolfPlay> model, const GolfViewOptions& o,
                                         std::ostream& out) {
  return std::make_unique<GolfView>(assets, std::move(model), o, out);
}

}  // namespace sweetspot
