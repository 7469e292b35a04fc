#include "game/ui/lab_view.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "game/render/gl.hpp"
#include "game/render/renderer.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "game/ui/panels.hpp"

namespace sweetspot {
namespace {

// Mouse orbit on top of the chosen camera: yaw about the vertical through the target,
// pitch toward the zenith, zoom along the view line. Reset when the camera changes.
struct Orbit {
  double yaw = 0.0, pitch = 0.0, zoom = 1.0;
  void reset() { *this = Orbit{}; }
  Camera apply(Camera c) const {
    Vec3 off = c.eye - c.target;
    off = Eigen::AngleAxisd(yaw, Vec3::UnitY()) * off;
    const Vec3 side = off.cross(Vec3::UnitY());
    if (side.norm() > 1e-9) {
      const Vec3 pitched = Eigen::AngleAxisd(pitch, side.normalized()) * off;
      // Stop short of the zenith and the ground plane so the view never flips.
      const double elev = std::asin(std::clamp(pitched.normalized().y(), -1.0, 1.0));
      if (elev < 1.45 && elev > -0.05) off = pitched;
    }
    c.eye = c.target + off * zoom;
    return c;
  }
};

// The window behind the panels: the ImGui dark grey, so the columns read as one surface.
void clear_window(int w, int h) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, w, h);
  glClearColor(0.10f, 0.11f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

class LabView final : public ModeView {
 public:
  const ShotScene* clip_scene() const override { return scene_.get(); }
  LabView(const Assets& assets, std::unique_ptr<LabModel> lab) : assets_(assets), lab_(std::move(lab)) { new_shot(); }
  const char* title() const override { return "Lab"; }
  const char* restart_label() const override { return "Run the shot again"; }
  float pause_menu_right(int w, int h) const override {
    const Rect view = lay_out_panels(static_cast<float>(w), static_cast<float>(h), panels_hidden_).view;
    return view.x + view.w - 12.0f;
  }
  void send(const Intent& in) override {
    lab_->update({in}, in.time);
    if (lab_->shot_serial() != serial_) new_shot();
  }
  void frame(const ViewInput& in, Renderer& renderer) override;

 private:
  void new_shot() {
    const ResolvedShot& r = lab_->resolved();
    const ShotResult& res = lab_->result();
    const bool new_scene = !scene_ || r.world != world_ || r.sport != sport_ || res.impactor_mesh != mesh_;
    if (new_scene) {
      scene_ = std::make_unique<ShotScene>(scene_input_for(assets_, r, res));
      world_ = r.world;
      sport_ = r.sport;
      mesh_ = res.impactor_mesh;
    }
    scene_->set_shot(res.trajectory, impactor_placement(res));
    scene_->set_target_line(aim_line(res.aim));
    replay_.pre_roll = scene_->pre_roll();
    replay_.restart();
    serial_ = lab_->shot_serial();
  }

  static constexpr double kCameraGlide = 0.6;  // s a camera change glides from the last camera, eased
  const Assets& assets_;
  std::unique_ptr<LabModel> lab_;
  std::unique_ptr<ShotScene> scene_;
  const WorldAsset* world_ = nullptr;
  const SportProfile* sport_ = nullptr;
  std::string mesh_;
  int serial_ = -1;
  ReplayState replay_;
  CameraKind camera_ = CameraKind::Behind;
  Orbit orbit_;
  std::optional<Camera> last_camera_, glide_from_;
  double since_switch_ = kCameraGlide;
  std::string save_path_ = "my-shot.toml", note_;
  bool panels_hidden_ = false;
};

void LabView::frame(const ViewInput& in, Renderer& renderer) {
  Intents intents;
  for (const KeyPress& k : in.keys) {
    if (k.key == GLFW_KEY_H) panels_hidden_ = !panels_hidden_;
    if (k.key == GLFW_KEY_R) replay_.restart();
    if (k.key == GLFW_KEY_SPACE) intents.push_back({IntentKind::Swing, k.time, 0, 0.0, {}});
    // A camera key always resets that camera, the current one too (undoes a mouse orbit).
    if (k.key >= GLFW_KEY_1 && k.key <= GLFW_KEY_4) {
      camera_ = static_cast<CameraKind>(k.key - GLFW_KEY_1);
      orbit_.reset();
      glide_from_ = last_camera_;
      since_switch_ = 0.0;
    }
  }
  orbit_.yaw -= in.orbit_dx * 0.005;
  orbit_.pitch += in.orbit_dy * 0.005;
  if (in.zoom != 0.0) orbit_.zoom = std::clamp(orbit_.zoom * std::pow(0.9, in.zoom), 0.1, 5.0);

  const CameraKind before = camera_;
  const int w = in.width, h = in.height;
  const PanelLayout layout = lay_out_panels(static_cast<float>(w), static_cast<float>(h), panels_hidden_);
  PanelContext ctx{assets_, *lab_, intents, in.now, replay_, camera_, save_path_, note_};
  draw_panels(ctx, layout);
  if (camera_ != before) {
    orbit_.reset();
    glide_from_ = last_camera_;
    since_switch_ = 0.0;
  }
  since_switch_ += in.dt;
  // The model runs the changed shot in this frame, so the trail drawn below is the new one.
  lab_->update(intents, in.now);
  if (lab_->shot_serial() != serial_) new_shot();
  replay_.advance(in.dt, duration(lab_->result().trajectory));

  // The 3D view fills the layout's view rectangle only: nothing of the shot is under a
  // panel, and a software rasteriser shades no pixel a panel covers.
  const int vw = static_cast<int>(layout.view.w), vh = static_cast<int>(layout.view.h);
  if (w > 0 && h > 0 && vw >= 16 && vh >= 16) {
    fit_renderer(renderer, vw, vh, in.render_scale);
    Camera cam = scene_->keep_above_ground(orbit_.apply(scene_->camera(camera_, replay_.time, vw, vh)));
    if (glide_from_ && since_switch_ < kCameraGlide) {
      cam = scene_->keep_above_ground(blend_cameras(*glide_from_, cam, ease_in_out(since_switch_ / kCameraGlide)));
    }
    last_camera_ = cam;
    renderer.draw(scene_->build(cam, replay_.time, vw, vh), cam);
    clear_window(w, h);
    renderer.blit_to(0, static_cast<int>(layout.view.x), h - static_cast<int>(layout.view.y) - vh, vw, vh);
  }
}

}  // namespace

std::unique_ptr<ModeView> make_lab_view(const Assets& assets, std::unique_ptr<LabModel> model) {
  return std::make_unique<LabView>(assets, std::move(model));
}

}  // namespace sweetspot
