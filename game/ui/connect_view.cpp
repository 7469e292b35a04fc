#include "game/ui/connect_view.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>
#include <optional>

#include "game/modes/golf/round.hpp"
#include "game/modes/replay.hpp"
#include "game/render/renderer.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "game/ui/wrapped_text.hpp"
#include "physics/units.hpp"

namespace sweetspot {
namespace {

struct ConnectView {
  const Assets& assets;
  std::unique_ptr<ShotScene> scene;
  std::string scene_world;
  std::optional<ShotTable::Played> last;
  ReplayState replay;
  bool have_shot = false;

  void ensure_scene(const std::string& world_name, const std::optional<Vec3>& flag) {
    if (scene && scene_world == world_name) return;
    ShotSceneInput in;
    in.assets = &assets;
    in.world = world_name == "none" ? nullptr : assets.world(world_name);
    in.distance_unit = "yd";
    in.ball_radius = assets.equipment().ball("tour").radius;
    in.flag = flag;
    scene = std::make_unique<ShotScene>(in);
    scene_world = world_name;
  }
};

void row(const char* label, const char* unit, double device, std::optional<double> model) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(label);
  ImGui::TableNextColumn();
  ImGui::Text("%.1f %s", device, unit);
  ImGui::TableNextColumn();
  if (model) ImGui::Text("%.1f %s", *model, unit);
  else ImGui::TextDisabled("-");
}

void draw_panel(const ConnectServer& server, const ConnectView& v, const std::string& bind) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_Always);
  ImGui::Begin("Launch monitor", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::TextWrapped("Open Connect v1 on %s:%d", bind.c_str(), server.port());
  // While the last ball moves the panel shows that stroke; the next (hole, lie, distance,
  // club) once it stops, as a golfer reads the result when the ball comes to rest.
  const bool moving = v.last && v.last->result && v.replay.playing && v.replay.time < duration(v.last->result->trajectory);
  if (moving) {
    ImGui::TextWrapped("The ball is %s   shots: %d", v.replay.time < v.last->result->trajectory.summary.hang_time_s ? "in the air" : "running out",
                server.shots());
  } else {
    ImGui::TextWrapped("%s", server.table().where().c_str());
    ImGui::TextWrapped("Club expected: %s   shots: %d", server.table().club().c_str(), server.shots());
  }
  if (!v.last) {
    disabled_wrapped("Point your launch monitor's GSPro connector here and hit a shot.");
  } else {
    const nlohmann::json& j = v.last->line;
    const nlohmann::json& L = j["launch"];
    const nlohmann::json& F = j["flight"];
    ImGui::Separator();
    ImGui::TextWrapped("Shot %d (%s)  %s", j.value("shot_number", 0), j.value("device", std::string()).c_str(),
                j.value("club", std::string()).c_str());
    const bool model = j.contains("model");
    const nlohmann::json* M = model ? &j["model"]["launch"] : nullptr;
    const auto m = [&](const char* key, double scale) -> std::optional<double> {
      if (M == nullptr || !M->contains(key) || !(*M)[key].is_number()) return std::nullopt;
      return (*M)[key].get<double>() * scale;
    };
    if (ImGui::BeginTable("numbers", 3, ImGuiTableFlags_SizingFixedFit)) {
      ImGui::TableSetupColumn("");
      ImGui::TableSetupColumn("device");
      ImGui::TableSetupColumn(model ? "our model" : "");
      ImGui::TableHeadersRow();
      const double mph = 1.0 / kMpsPerMph;
      row("Ball speed", "mph", L["ball_speed_mps"].get<double>() * mph, m("ball_speed_mps", mph));
      row("Launch", "deg", L["vertical_angle_deg"].get<double>(), m("vertical_angle_deg", 1.0));
      row("Direction", "deg", L["horizontal_angle_deg"].get<double>(), m("horizontal_angle_deg", 1.0));
      row("Spin", "rpm", L["spin_rpm"].get<double>(), m("spin_rpm", 1.0));
      row("Spin axis", "deg", L["spin_axis_deg"].get<double>(), m("spin_axis_deg", 1.0));
      ImGui::EndTable();
    }
    if (j.contains("model_error")) ImGui::TextWrapped("club data: %s", j["model_error"].get<std::string>().c_str());
    // Left and right of the line the shot was aimed on, not the world's axis; the carry once
    // the ball lands, the total once it stops.
    const double side = j.value("side_m", F["lateral_m"].get<double>());
    const bool landed = !moving || v.replay.time >= v.last->result->trajectory.summary.hang_time_s;
    if (landed && moving)
      ImGui::TextWrapped("Carry %.1f yd   %.1f yd %s", m_to_yd(F["carry_m"].get<double>()), std::abs(m_to_yd(side)), side >= 0 ? "right" : "left");
    else if (landed)
      ImGui::TextWrapped("Carry %.1f yd   total %.1f yd   %.1f yd %s", m_to_yd(F["carry_m"].get<double>()),
                  m_to_yd(F["total_m"].get<double>()), std::abs(m_to_yd(side)), side >= 0 ? "right" : "left");
    if (j.contains("hole") && !moving) {
      const std::string end = j["end"].get<std::string>();
      const char* words = end == "holed" ? "In the hole!" : end == "water" ? "In the water: penalty stroke"
                          : end == "out_of_bounds" ? "Out of bounds: stroke and distance" : "at rest";
      ImGui::TextWrapped("Hole %d, stroke %d: %s, %.0f yd to the pin", j["hole"].get<int>(), j["hole_strokes"].get<int>(), words,
                  m_to_yd(j["to_pin_m"].get<double>()));
      if (j.value("picked_up", false)) ImGui::TextWrapped("Picked up at 10 strokes.");
      if (j.contains("next_hole"))
        ImGui::TextWrapped("Next: hole %d, %s, %.0f yd (told to the device)", j["next_hole"].get<int>(),
                    j["next_club"].get<std::string>().c_str(), m_to_yd(j["next_to_pin_m"].get<double>()));
    }
    if (j.value("round_over", false) && !moving)
      ImGui::TextWrapped("Round over: %d strokes (par %d). A new round starts.", j["round_strokes"].get<int>(), j["round_par"].get<int>());
  }
  disabled_wrapped("Space: replay the last shot   Esc: pause");
  ImGui::End();
}

class ConnectModeView final : public ModeView {
 public:
  const ShotScene* clip_scene() const override { return v_.scene.get(); }
  ConnectModeView(const Assets& assets, ConnectServer& server, std::string bind, std::string range_world)
      : server_(server), bind_(std::move(bind)), range_world_(std::move(range_world)), v_{assets, nullptr, {}, std::nullopt, {}, false} {
    server_.on_shot([this](const ShotTable::Played& p) {
      v_.last = p;
      v_.have_shot = true;
    });
  }
  const char* title() const override { return "Launch monitor"; }
  void send(const Intent& in) override {
    if (in.kind == IntentKind::Replay && v_.last) v_.replay.restart();
  }
  // A signal, or max_shots answered and the last one drawn.
  bool done() const override { return server_.stopped() && !v_.replay.playing; }
  void frame(const ViewInput& in, Renderer& renderer) override {
    server_.poll();
    for (const KeyPress& k : in.keys)
      if (k.key == GLFW_KEY_SPACE && v_.last) v_.replay.restart();
    if (v_.have_shot) {
      // A new shot: its world (the round's hole changes), its flight from the start.
      const ShotResult& r = *v_.last->result;
      const GolfRound* round = server_.table().round();
      std::optional<Vec3> flag;
      if (round != nullptr && !round->finished()) flag = round->hole().pin;
      v_.scene.reset();
      v_.ensure_scene(r.world.empty() ? "none" : r.world, flag);
      v_.scene->set_shot(r.trajectory, impactor_placement(r));
      v_.scene->set_target_line(aim_line(r.aim));
      sound_strike(r);  // a monitor's ball data alone has no strike to sound
      v_.replay.restart();
      v_.have_shot = false;
    }
    if (!v_.scene) {
      const GolfRound* round = server_.table().round();
      const std::string world = round != nullptr ? round->hole().world_name : range_world_;
      v_.ensure_scene(world, round != nullptr ? std::optional<Vec3>(round->hole().pin) : std::nullopt);
      ShotTrajectory t;
      TrajectorySample s;
      const Vec3 ground = round != nullptr ? round->ball() : Vec3::Zero();
      const double y = v_.scene->ground_height(ground.x(), ground.z()).value_or(0.0);
      s.position = Vec3(ground.x(), y + 0.021335, ground.z());
      s.phase = Phase::Rest;
      t.samples = {s, s};
      t.summary.landing_position = t.summary.rest_position = s.position;
      v_.scene->set_shot(t, std::nullopt);
    }
    if (v_.last) v_.replay.advance(in.dt, duration(v_.scene->trajectory()));
    const int w = in.width, h = in.height;
    if (w > 0 && h > 0) {
      fit_renderer(renderer, w, h, in.render_scale);
      const Camera cam = v_.scene->camera(v_.last ? CameraKind::Follow : CameraKind::Behind, v_.replay.time, w, h);
      renderer.draw(v_.scene->build(cam, v_.replay.time, w, h), cam);
      renderer.blit_to(0, w, h);
    }
    draw_panel(server_, v_, bind_);
  }

 private:
  ConnectServer& server_;
  std::string bind_, range_world_;
  ConnectView v_;
};

}  // namespace

std::unique_ptr<ModeView> make_connect_view(const Assets& assets, ConnectServer& server, const std::string& bind,
                                            const std::string& range_world) {
  return std::make_unique<ConnectModeView>(assets, server, bind, range_world);
}

}  // namespace sweetspot
