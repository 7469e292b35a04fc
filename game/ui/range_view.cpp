#include "game/ui/range_view.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "game/modes/golf/golfer.hpp"
#include "game/modes/replay.hpp"
#include "game/render/renderer.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "game/ui/golf_draw.hpp"
#include "game/ui/wrapped_text.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/units.hpp"

namespace sweetspot {

Intents range_intents(const std::vector<KeyPress>& keys) {
  return intents_from_keys(keys, {{GLFW_KEY_SPACE, IntentKind::Swing},
                                  {GLFW_KEY_UP, IntentKind::ClubUp},
                                  {GLFW_KEY_DOWN, IntentKind::ClubDown},
                                  {GLFW_KEY_B, IntentKind::CaddiePlays},
                                  {GLFW_KEY_ENTER, IntentKind::Continue},
                                  {GLFW_KEY_KP_ENTER, IntentKind::Continue}});
}

namespace {

class RangeView final : public ModeView {
 public:
  const ShotScene* clip_scene() const override { return scene_.get(); }
  RangeView(const Assets& a, std::unique_ptr<RangePlay> m, const RangeViewOptions& o) : assets_(a), play_(std::move(m)), options_(o) {
    units_.imperial = o.imperial;
  }
  const char* title() const override { return "Range"; }
  AmbienceSpec ambience() const override { return {Ambience::Course, 0.0}; }
  const char* restart_label() const override { return "New session"; }
  std::string restart_loses() const override {
    const std::size_t n = play_->session().shots().size();
    return n == 0 ? std::string() : "this session's " + std::to_string(n) + (n == 1 ? " shot" : " shots");
  }
  bool done() const override { return false; }
  void send(const Intent& in) override { play_->update({in}, in.time); }
  bool busy() const override { return play_->stage() == RangePlay::Stage::Swinging; }
  void frame(const ViewInput& in, Renderer& renderer) override;
  void report(std::ostream& out) const override {
    const std::size_t shots = play_->session().shots().size(), clubs = play_->session().bag("you").clubs.size();
    out << "range: " << shots << (shots == 1 ? " shot, " : " shots, ") << clubs << (clubs == 1 ? " club\n" : " clubs\n");
  }

 private:
  /// `in_air`: the last ball has not landed yet; its carry stays out of the table until it has.
  /// Returns the panel's bottom edge (px).
  float draw_panel(int w, bool in_air);
  void save_bag();

  const Assets& assets_;
  std::unique_ptr<RangePlay> play_;
  RangeViewOptions options_;
  GolfUnits units_;
  bool scene_imperial_ = true;  ///< the units the scene's labels were drawn in
  std::unique_ptr<ShotScene> scene_;
  std::string scene_mesh_;
  double shown_struck_ = -1.0;
  bool addressed_ = false;  ///< the scene shows the golfer at address, not the last shot
  std::string note_;
};

void RangeView::save_bag() {
  try {
    Bag bag = play_->session().bag("you");
    if (bag.clubs.empty()) {
      note_ = "Nothing to save yet: hit some shots first";
      return;
    }
    write_file_atomic(options_.bag_path, bag_toml(bag));
    note_ = "Bag saved to " + options_.bag_path + "\nplay it: play --bag FILE, round --bag FILE";
  } catch (const std::exception& e) {
    note_ = std::string("Not saved: ") + e.what();
  }
}

float RangeView::draw_panel(int w, bool in_air) {
  // The ball still in the air is left out until it lands.
  const std::size_t shots = play_->session().shots().size();
  const std::size_t counted = in_air && shots > 0 ? shots - 1 : shots;
  const Bag bag = play_->session().bag("you", counted);
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(520, 0), ImGuiCond_Always);
  ImGui::Begin("Practice range", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::Text("Bag gapping: %d shots a club (%s speed)", play_->shots_per_club(), play_->skill().name.c_str());
  if (play_->shots_with_club() < play_->shots_per_club())
    ImGui::Text("Club: %s   shot %d of %d", club_name(play_->club()).c_str(), play_->shots_with_club() + 1, play_->shots_per_club());
  else  // back to a club already gapped: its row keeps counting, it is not shot 5 of 5 again
    ImGui::Text("Club: %s   %d shots, done (more add to its row)", club_name(play_->club()).c_str(), play_->shots_with_club());
  if (ImGui::BeginTable("bag", 7, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    // What a golfer gaps a bag by: carry and total, how far the carries spread, and which way
    // the club misses ("6 L ± 9": the landings' mean left or right of the target line, and
    // their standard deviation about it). The club's column as wide as the longest name in
    // the bag ("pitching wedge" read whole); the figures share the rest.
    float club_width = ImGui::CalcTextSize("club").x;
    for (const auto& c : bag.clubs) club_width = std::max(club_width, ImGui::CalcTextSize(club_name(c.club).c_str()).x);
    ImGui::TableSetupColumn("club", ImGuiTableColumnFlags_WidthFixed, club_width);
    ImGui::TableSetupColumn("shots", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("shots").x);
    for (const char* c : {"carry", "total", "spread", "side", "gap"}) ImGui::TableSetupColumn(c, ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableHeadersRow();
    const double unit = units_.imperial ? 0.9144 : 1.0;
    for (std::size_t k = 0; k < bag.clubs.size(); ++k) {
      const BagClub& c = bag.clubs[k];
      const RangeSession::SideMiss miss = play_->session().side_miss(c.club, counted);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(club_name(c.club).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%d", c.shots);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(units_.distance(c.carry).c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(units_.distance(c.total).c_str());
      ImGui::TableNextColumn();
      // One ball has no spread yet: a dash, not "± 0 yd".
      if (c.shots > 1) ImGui::Text("± %s", units_.distance(c.carry_sd).c_str());
      else ImGui::TextUnformatted("-");
      ImGui::TableNextColumn();
      const long by = std::lround(std::abs(miss.mean) / unit);
      const std::string way = by == 0 ? "on line" : std::to_string(by) + (miss.mean < 0.0 ? " L" : " R");
      if (miss.shots > 1) ImGui::Text("%s ± %ld", way.c_str(), std::lround(miss.sd / unit));
      else ImGui::TextUnformatted(way.c_str());
      ImGui::TableNextColumn();
      if (k + 1 < bag.clubs.size()) ImGui::TextUnformatted(units_.distance(c.carry - bag.clubs[k + 1].carry).c_str());
    }
    ImGui::EndTable();
  }
  disabled_wrapped("spread: the carries' standard deviation; side: where it lands on average, left (L) or right (R) of the "
                   "line, ± its standard deviation");
  ImGui::TextDisabled("Space: swing (3 clicks)  B: a swing with your skill's errors");
  ImGui::TextDisabled("Up/Down club  Enter: skip the flight  S: save the bag  U: units");
  ImGui::TextDisabled("Esc: pause  Tab: next mode");
  if (!play_->message().empty()) ImGui::TextWrapped("%s", play_->message().c_str());
  if (!note_.empty()) ImGui::TextWrapped("%s", note_.c_str());
  const float bottom = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y;
  ImGui::End();
  (void)w;
  return bottom;
}

void RangeView::frame(const ViewInput& in, Renderer& renderer) {
  for (const KeyPress& k : in.keys) {
    if (k.key == GLFW_KEY_S) save_bag();
    if (k.key == GLFW_KEY_U) units_.imperial = !units_.imperial;
  }
  play_->update(range_intents(in.keys), in.now);
  const int w = in.width, h = in.height;
  const EquipmentCatalog& eq = assets_.equipment();
  const std::string mesh = eq.club_info_of(play_->club()).mesh;
  if (!scene_ || scene_mesh_ != mesh || scene_imperial_ != units_.imperial) {
    // The same club in other units (U): the new scene shows the shot on view again, silently.
    const bool relabel = scene_ && scene_mesh_ == mesh;
    ShotSceneInput si;
    si.assets = &assets_;
    si.world = nullptr;  // the flat range
    si.distance_unit = units_.imperial ? "yd" : "m";
    si.ball_radius = eq.ball("tour").radius;
    si.tee = true;
    si.impactor_mesh = mesh;
    scene_ = std::make_unique<ShotScene>(si);
    scene_->set_stripe_numbers(false);  // the flags say the distances (drawn below)
    scene_mesh_ = mesh;
    scene_imperial_ = units_.imperial;
    addressed_ = false;
    if (relabel && shown_struck_ >= 0.0) {
      scene_->set_shot(play_->last_shot().trajectory, impactor_placement(play_->last_shot()));
      scene_->set_target_line(aim_line(play_->last_shot().aim));
    } else {
      shown_struck_ = -1.0;
    }
  }
  const bool flying = play_->stage() == RangePlay::Stage::Flying;
  const bool hit = play_->struck_at() > 0.0 || !play_->session().shots().empty();
  if (hit && shown_struck_ != play_->struck_at()) {
    scene_->set_shot(play_->last_shot().trajectory, impactor_placement(play_->last_shot()));
    scene_->set_address(std::nullopt);
    scene_->set_target_line(aim_line(play_->last_shot().aim));
    if (play_->struck_at() > 0.0) sound_strike(play_->last_shot());
    shown_struck_ = play_->struck_at();
    addressed_ = false;
  }
  const double end = hit ? duration(play_->last_shot().trajectory) : 0.0;
  // The last ball stays on view where it stopped a moment, then the golfer addresses the
  // next on the tee (at once when he starts his swing).
  constexpr double kShowLanded = 2.5;  // s
  const bool address = !flying && (!hit || play_->stage() == RangePlay::Stage::Swinging ||
                                   in.now - play_->struck_at() > end + kShowLanded);
  if (address && !addressed_) {
    const double radius = eq.ball("tour").radius;
    const Vec3 ball(0.0, radius + eq.club_info_of(play_->club()).tee_height, 0.0);
    scene_->set_shot(ball_at_rest(ball), std::nullopt);
    scene_->set_address(club_at_address(ball, Vec3::UnitX(), radius));
    addressed_ = true;
  }
  // The backswing follows the meter's marker, as on the course (game/ui/golf_view.cpp).
  const auto& meter = play_->meter();
  scene_->set_backswing(address && meter && play_->stage() == RangePlay::Stage::Swinging ? meter->position(in.now) : 0.0);
  const double t = address ? 0.0 : flying ? std::clamp(in.now - play_->struck_at(), 0.0, end) : end;
  if (w > 0 && h > 0) {
    fit_renderer(renderer, w, h, in.render_scale);
    Camera cam;
    if (flying) {
      cam = scene_->camera(CameraKind::Follow, t, w, h);
    } else {
      // Behind the golfer on the tee, as the course's full-shot view stands: the flags out to
      // 250 yd just below the horizon.
      cam = full_shot_address_camera(Vec3::Zero(), Vec3::UnitX());
    }
    const Scene view = scene_->build(cam, t, w, h);
    renderer.draw(view, cam);
    renderer.blit_to(0, w, h);
    // The range's scene has no flag meshes: each flag drawn whole, with its distance where
    // it leaves the shot's own labels clear.
    for (const Vec3& p : RangePlay::targets(units_.imperial))
      draw_cup_and_flag(cam, p, w, h, false, units_.distance(p.x()), view.label_boxes);
  }
  const float panel_bottom = draw_panel(w, flying && t < play_->last_shot().trajectory.summary.hang_time_s);
  // The last ball's numbers, its carry once it lands: beside the range's panel (10..530 px),
  // or under it where the window is too narrow for both (at 640 px it covered the table's
  // side and gap columns).
  constexpr float kPanelRight = 530.0f, kLaunchPanelWide = 250.0f;
  const float top = static_cast<float>(w) - kLaunchPanelWide < kPanelRight + 10.0f ? panel_bottom + 10.0f : 10.0f;
  if (hit) draw_launch_panel(play_->last_shot(), units_, w, t, false, top);
  if (play_->stage() != RangePlay::Stage::Flying) {
    const MeterBar bar =
        draw_meter_bar(play_->meter(), play_->next_meter(), play_->last_click(), w, h, in.now);
    draw_meter_caption(bar, full_swing_caption(play_->meter(), in.now, play_->club() + ": Space to swing"));
  }
}

}  // namespace

std::unique_ptr<ModeView> make_range_view(const Assets& assets, std::unique_ptr<RangePlay> model, const RangeViewOptions& o) {
  return std::make_unique<RangeView>(assets, std::move(model), o);
}

}  // namespace sweetspot
