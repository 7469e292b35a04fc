#include "game/ui/golf_view.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "game/content/settings_file.hpp"
#include "game/modes/golf/latency_calibration.hpp"
#include "game/modes/replay.hpp"
#include "game/render/renderer.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "game/render/video_clip.hpp"
#include "game/report/report.hpp"
#include "game/report/round_json.hpp"
#include "game/report/round_save.hpp"
#include "game/ui/golf_draw.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"
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
                                  {GLFW_KEY_H, IntentKind::Concede},
                                  {GLFW_KEY_G, IntentKind::ReadGreen},
                                  {GLFW_KEY_N, IntentKind::NewRound},
                                  {GLFW_KEY_ENTER, IntentKind::Continue},
                                  {GLFW_KEY_KP_ENTER, IntentKind::Continue}});
}

namespace {

/// The view of a stroke at address: behind ball `b` down the aim line `d` (unit, flat). A
/// putt, and a chip from where golfers count feet (GolfUnits::kNear), take the putt's view:
/// near, beside the golfer and looking down at the cup; the full shot's, 9 m back at his
/// shoulders' height, would stand him between the camera and a flag a few yards off.
Camera address_camera_at(const Vec3& b, const Vec3& d, bool putt, double to_pin) {
  return putt || to_pin <= GolfUnits::kNear ? putt_address_camera(b, d, to_pin) : full_shot_address_camera(b, d);
}

Vec3 flat_unit(const Vec3& from, const Vec3& to) {
  Vec3 d(to.x() - from.x(), 0.0, to.z() - from.z());
  const double n = d.norm();
  return n > 1e-9 ? Vec3(d / n) : Vec3(Vec3::UnitX());
}

/// The ball's rest is held on screen this long before the next player's view (s).
constexpr double kSettle = GolfPlay::kRestShown;

class GolfView final : public ModeView {
 public:
  const ShotScene* clip_scene() const override;
  /// The last stroke's scene as it was struck, shot set (nothing when its world or club mesh
  /// cannot be loaded again): the replay's and F10's clip.
  std::unique_ptr<ShotScene> stroke_scene() const;
  GolfView(const Assets& a, std::unique_ptr<GolfPlay> m, const GolfViewOptions& o, std::ostream& out)
      : assets_(a), play_(std::move(m)), options_(o), out_(out) {
    units_.imperial = o.imperial;
  }

  const char* title() const override { return "Golf"; }
  AmbienceSpec ambience() const override { return {Ambience::Course, play_->round().wind().speed}; }
  // After the last hole the pause menu's restart starts a new round (GolfPlay::apply).
  const char* restart_label() const override {
    return play_->stage() == GolfPlay::Stage::RoundOver ? "New round" : "Restart hole";
  }
  std::string restart_loses() const override {
    const int n = play_->strokes_a_restart_loses();
    if (n == 0) return {};
    // With others in the group the count is everyone's: said so, not taken for the player's own.
    const bool group = play_->group().players().size() > 1;
    return "this hole's " + std::to_string(n) + (n == 1 ? " stroke" : " strokes") + (group ? " (the whole group's)" : "");
  }
  // Quitting leaves the whole round, not the hole: unless it was just saved (S), it goes.
  std::string quit_loses() const override {
    const std::size_t turns = play_->group().events().size();
    if (play_->stage() == GolfPlay::Stage::RoundOver || turns == 0 || saved_turns_ == turns) return {};
    return "the round so far (S in play saves it to finish later)";
  }
  // A swing or a latency calibration under way: Esc takes it back instead of pausing.
  bool busy() const override { return play_->stage() == GolfPlay::Stage::Swinging || calibration_.has_value(); }
  bool done() const override { return options_.exit_when_done && done_frames_ >= 10; }
  void send(const Intent& in) override {
    replay_.reset();  // Esc (and the pause menu) ends a replay
    if (in.kind == IntentKind::Cancel && calibration_) {
      calibration_.reset();
      note("Calibration cancelled; nothing changed (L to try again)");
      return;
    }
    play_->update({in}, in.time);
    // A restart throws the stroke on screen away with the rest: the view goes to the ball at
    // address at once, not on through the discarded flight's landing.
    if (in.kind == IntentKind::Restart) flight_shown_ = false;
  }
  void frame(const ViewInput& in, Renderer& renderer) override;
  void report(std::ostream& out) const override {
    const GolfGroup& g = play_->group();
    const GolfRound& r = g.round(0);
    // Once the round is over, the holes it took (a match decided 2&1 on the 2nd of 3); else
    // the hole being played.
    out << "golf: hole " << (g.finished() ? g.hole_index() : std::min(g.hole_index() + 1, r.course().holes.size())) << " of "
        << r.course().holes.size() << ", " << r.total_strokes() << (r.total_strokes() == 1 ? " stroke, " : " strokes, ") << play_->cancelled()
        << (play_->cancelled() == 1 ? " swing" : " swings") << " cancelled, " << to_string(play_->stage()) << "\n";
  }

 private:
  void view_keys(const std::vector<KeyPress>& keys);
  /// The scene of the hole being played, its impactor `mesh` (the club at address, or the
  /// club of the stroke in flight: its swing shape draws the follow-through).
  void ensure_scene(const std::string& mesh);
  bool can_replay() const;
  void start_replay(double now);
  /// Draws the replay at mode time `now`; false once it has run its course.
  bool draw_replay(const ViewInput& in, Renderer& renderer);
  Camera address_camera() const;
  /// The address camera moved sideways, in a window so small that the play panel reaches
  /// down over the golfer, until he stands clear of it (w x h px).
  Camera golfer_clear_of_panel(const Camera& c, int w, int h) const;
  Camera high_camera() const;
  Camera map_camera() const;
  Camera green_camera(bool from_pin) const;
  Camera flyover_camera(double progress) const;
  void save_round();
  /// L: the tap calibration; returns the keys left for the game.
  std::vector<KeyPress> calibration_keys(const std::vector<KeyPress>& keys, double now);
  void draw_calibration(int w, int h, double now) const;

  const Assets& assets_;
  std::unique_ptr<GolfPlay> play_;
  GolfViewOptions options_;
  std::ostream& out_;
  GolfUnits units_;
  int camera_ = 1;                 // 1 player, 2 high, 3 map (M), 4 green
  std::optional<Camera> address_view_;  // the last view at address, held as a stroke starts
  // The last stroke as it was struck: its scene (club, tee, markers) and the view from
  // behind its golfer, for R's replay.
  std::optional<ShotSceneInput> stroke_input_;
  // F10's clip: the stroke last played, built from its own scene (by then the view may hold
  // the ball at address for the next one, a shot of one frame); made again for each stroke.
  mutable std::unique_ptr<ShotScene> clip_;
  mutable double clip_struck_ = -1.0;
  std::optional<Camera> stroke_view_;
  // R at rest: the stroke again, its strike slowed, from behind the golfer, alongside the
  // flight and after the ball to where it stopped.
  struct Replay {
    std::unique_ptr<ShotScene> scene;
    std::vector<double> times;  // the shot's time at each 1/60 s of the replay
    double from = 0.0;          // mode time it started
    bool struck = false;        // its strike has sounded
    std::string whose;          // whose stroke it shows: "scratch bot, stroke 2 on hole 1, 3-wood"
  };
  std::optional<Replay> replay_;
  static constexpr double kReplayFps = 60.0, kReplaySlow = 8.0;
  // s the player's camera holds after the strike (the follow-through, the ball leaving), then
  // s it takes to reach the ball's follow camera.
  static constexpr double kHoldAddress = 0.6, kLeaveAddress = 0.6;
  int camera_before_map_ = 1;
  std::unique_ptr<ShotScene> scene_;
  std::size_t scene_hole_ = 99;
  const WorldAsset* scene_world_ = nullptr;
  std::string scene_mesh_;
  bool scene_tee_ = false;
  bool scene_imperial_ = true;
  bool flight_shown_ = false;      // the scene holds the last stroke's flight
  bool rattle_due_ = false;        // the stroke shown was holed: its rattle plays as it drops
  double flight_struck_ = -1.0;    // which flight
  std::size_t slopes_for_ = 99;
  Vec3 slopes_ball_ = Vec3::Zero();
  std::vector<GroundArrow> slopes_;  // the green's slopes round the ball, as the scene draws them
  std::size_t saved_turns_ = static_cast<std::size_t>(-1);  // the group's turns when last saved (none yet)
  std::string saved_note_;
  double saved_note_at_ = -1.0;  // mode time it was first shown; -1 until then
  // A note shown for kNoteShown s from its first frame.
  void note(std::string text) {
    saved_note_ = std::move(text);
    saved_note_at_ = -1.0;
  }
  static constexpr double kNoteShown = 8.0;  // s a note (round saved, latency) stays on screen
  std::optional<LatencyCalibration> calibration_;
  TapQuiet after_taps_;  // the calibration's taps that run on past its end
  int done_frames_ = 0;
  // Every key on the first hole (in a window kAllKeysMinHeight tall), then the few a stroke
  // needs; K switches (held for the round).
  std::optional<bool> all_keys_;
  int view_height_ = kAllKeysMinHeight;
  Eigen::Vector4f hud_box_ = Eigen::Vector4f::Zero();  // the play panel, as last drawn (x0, y0, x1, y1 px)
  bool all_keys() const { return all_keys_.value_or(play_->group().hole_index() == 0 && view_height_ >= kAllKeysMinHeight); }
};

void GolfView::view_keys(const std::vector<KeyPress>& keys) {
  for (const KeyPress& k : keys) {
    switch (k.key) {
      case GLFW_KEY_M:
        if (camera_ == 3) {
          camera_ = camera_before_map_;
        } else {
          camera_before_map_ = camera_;
          camera_ = 3;
        }
        break;
      case GLFW_KEY_1: camera_ = 1; break;
      case GLFW_KEY_2: camera_ = 2; break;
      case GLFW_KEY_3: camera_ = 3; break;
      case GLFW_KEY_4: camera_ = 4; break;
      case GLFW_KEY_U: units_.imperial = !units_.imperial; break;
      case GLFW_KEY_K:
      case GLFW_KEY_F1:  // where a newcomer looks for help first
        // On the green as off it: the panel's putt lines say which way K switches.
        all_keys_ = !all_keys();
        break;
      case GLFW_KEY_S: save_round(); break;
      case GLFW_KEY_R:
        if (replay_) replay_.reset();
        else if (can_replay()) start_replay(k.time);
        break;
      default: break;
    }
  }
}

std::vector<KeyPress> GolfView::calibration_keys(const std::vector<KeyPress>& keys, double now) {
  std::vector<KeyPress> rest;
  for (const KeyPress& k : keys) {
    if (!calibration_ && k.key == GLFW_KEY_L && play_->stage() == GolfPlay::Stage::Aiming) {
      calibration_.emplace(k.time);
      continue;
    }
    if (calibration_ && k.key == GLFW_KEY_SPACE) {
      calibration_->tap(k.time);
      continue;
    }
    // A tap or two past the last beat belongs to the calibration's rhythm, not to a swing.
    if (!calibration_ && k.key == GLFW_KEY_SPACE && after_taps_.swallow(k.time)) continue;
    if (!calibration_) rest.push_back(k);
  }
  if (calibration_ && calibration_->done(now)) {
    if (const auto latency = calibration_->latency()) {
      play_->set_input_latency(*latency);
      char buf[200];
      const std::filesystem::path path = settings_path();
      try {
        std::filesystem::create_directories(path.parent_path());
        Settings settings = load_settings(path);
        settings.input_latency = *latency;
        write_file_atomic(path, settings_toml(settings), OverInput::Allow);
        std::snprintf(buf, sizeof buf, "Input latency %.0f ms: the meter takes it off your clicks (saved to %s)", 1000.0 * *latency,
                      path.string().c_str());
      } catch (const std::exception& e) {
        std::snprintf(buf, sizeof buf, "Input latency %.0f ms for this session (not saved: %s)", 1000.0 * *latency, e.what());
      }
      note(buf);
    } else {
      note("Calibration: too few taps in time with the beat; nothing changed (L to try again)");
    }
    calibration_.reset();
    after_taps_.start(now);
  }
  return rest;
}

void GolfView::draw_calibration(int w, int h, double now) const {
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const ImVec2 c(0.5f * static_cast<float>(w), 0.5f * static_cast<float>(h));
  const int glow = static_cast<int>(255.0 * calibration_->flash(now));
  dl->AddRectFilled(ImVec2(c.x - 260, c.y - 150), ImVec2(c.x + 260, c.y + 130), IM_COL32(20, 24, 30, 230), 8.0f);
  dl->AddCircleFilled(c, 60.0f, IM_COL32(60 + glow * 3 / 4, 60 + glow * 3 / 4, 60, 255));
  char text[96], counted[96];
  std::snprintf(text, sizeof text, "Tap Space on each flash: beat %d of %d", calibration_->beats_shown(now),
                LatencyCalibration::kBeats);
  std::snprintf(counted, sizeof counted, "%d taps counted (the first %d beats only set the rhythm)", calibration_->counted(),
                LatencyCalibration::kLeadIn);
  dl->AddText(ImVec2(c.x - 240, c.y - 130), IM_COL32(255, 255, 255, 255), "Input latency calibration");
  dl->AddText(ImVec2(c.x - 240, c.y + 86), IM_COL32(220, 220, 220, 255), text);
  dl->AddText(ImVec2(c.x - 240, c.y + 106), IM_COL32(180, 180, 180, 255), counted);
}

void GolfView::save_round() {
  try {
    const GolfGroup& g = play_->group();
    write_file_atomic(options_.save_path,
                      json_text(round_save_json(g, std::filesystem::absolute(g.course().source).string(), play_->restarts(),
                                                play_->cancelled())) +
                          "\n",
                      OverInput::Allow);
    note("Round saved to " + options_.save_path + " (play --mode golf --resume FILE)");
    saved_turns_ = g.events().size();
  } catch (const std::exception& e) {
    note(std::string("Not saved: ") + e.what());
  }
}

namespace {

// The tee box's markers: 3 m either side of the tee spot across the line to the hole's first
// bend or cup, half a metre ahead of it, in the tee set's colour (white for a hole's own tee).
std::vector<std::pair<Vec3, Eigen::Vector3f>> tee_markers(const CourseHole& h, const std::string& set) {
  Vec3 ahead = (h.bends.empty() ? h.pin : h.bends.front()) - h.tee;
  ahead.y() = 0.0;
  if (ahead.norm() < 1e-6) return {};
  ahead.normalize();
  const Vec3 across(-ahead.z(), 0.0, ahead.x());
  Eigen::Vector3f colour(0.95f, 0.95f, 0.95f);
  if (set == "blue") colour = {0.15f, 0.30f, 0.85f};
  else if (set == "red") colour = {0.85f, 0.15f, 0.12f};
  else if (set == "gold" || set == "yellow") colour = {0.95f, 0.78f, 0.15f};
  else if (set == "black") colour = {0.08f, 0.08f, 0.08f};
  else if (set == "green") colour = {0.15f, 0.60f, 0.20f};
  const Vec3 base = h.tee + 0.5 * ahead;
  return {{base + 3.0 * across, colour}, {base - 3.0 * across, colour}};
}

}  // namespace

void GolfView::ensure_scene(const std::string& mesh) {
  const GolfRound& r = play_->round();
  // A stroke on show is on the hole it was struck on (hole_shown): the putt that holes out
  // has already moved the round to the next tee, whose pin and tee it must not take.
  const bool stroke = play_->after_stroke();
  if (r.finished() && !stroke) return;
  const std::size_t shown = play_->hole_shown();
  const CourseHole& hole = play_->group().course().holes.at(shown);
  const EquipmentCatalog& eq = assets_.equipment();
  const bool tee = stroke ? play_->last_record().lie == "tee" : r.teed() && r.lie() == "tee";
  if (scene_ && scene_hole_ == shown && scene_world_ == hole.world && scene_mesh_ == mesh && scene_tee_ == tee &&
      scene_imperial_ == units_.imperial)
    return;
  ShotSceneInput in;
  in.assets = &assets_;
  in.world = hole.world;
  in.distance_unit = units_.imperial ? "yd" : "m";
  in.ball_radius = eq.ball("tour").radius;
  in.tee = tee;
  in.impactor_mesh = mesh;
  in.flag = hole.pin;
  if (tee) in.tee_markers = tee_markers(hole, play_->group().course().setup.tees);
  scene_ = std::make_unique<ShotScene>(in);
  scene_hole_ = shown;
  scene_world_ = hole.world;
  scene_mesh_ = mesh;
  scene_tee_ = tee;
  scene_imperial_ = units_.imperial;
}

// Between holes: looking down on the green of the hole just played.
Camera GolfView::green_camera(bool from_pin) const {
  const Course& course = play_->group().course();
  const CourseHole& h = course.holes[std::min(scene_hole_, course.holes.size() - 1)];
  Camera c;
  if (from_pin && !play_->round().finished()) {
    // Camera 4: from behind the cup looking back at the ball, the putt's line in view.
    const Vec3 ball = play_->ball_centre();
    const Vec3 d = flat_unit(ball, h.pin);
    const double dist = play_->round().to_pin();
    // A little to the side of the line, as a broadcast's reverse angle stands: straight down
    // it, the flagstick rising from the cup would cover the whole line to the ball.
    const Vec3 side(-d.z(), 0.0, d.x());
    c.eye = h.pin + std::clamp(0.3 * dist, 4.0, 25.0) * d + std::clamp(0.1 * dist, 0.8, 3.0) * side +
            Vec3(0.0, std::clamp(0.15 * dist, 2.0, 20.0), 0.0);
    c.target = dist < 60.0 ? Vec3(0.5 * (ball + h.pin)) : h.pin;
    c.fov_y = deg_to_rad(45.0);
    return c;
  }
  const Vec3 d = flat_unit(h.tee, h.pin);
  c.eye = h.pin - 30.0 * d + Vec3(0.0, 22.0, 0.0);
  c.target = h.pin;
  c.fov_y = deg_to_rad(40.0);
  return c;
}

Camera GolfView::address_camera() const {
  const GolfRound& r = play_->round();
  const Vec3 ball = play_->ball_centre();
  const Camera c = address_camera_at(ball, play_->aim_direction(), r.lie() == "green", r.to_pin());
  // A tree (or a bank) between the golfer and the camera would fill the view.
  if (r.finished()) return c;
  return clear_view_of(c, ball, *r.hole().world->world);
}

Camera GolfView::golfer_clear_of_panel(const Camera& c, int w, int h) const {
  if (hud_box_[2] <= 0.0f) return c;  // no panel drawn yet
  // The golfer stands about a metre left of the ball's line, his head ~1.7 m up and his
  // trail elbow ~0.4 m beyond that: his image's left edge and top.
  const Vec3 ball = play_->ball_centre(), aim = play_->aim_direction();
  const Vec3 left(aim.z(), 0.0, -aim.x());
  const Vec3 head = ball + 1.0 * left + Vec3(0.0, 1.7, 0.0);
  const auto at = c.project(head, w, h);
  if (!at) return c;
  const double mpp = c.metres_per_pixel(head, h);
  const double body_left = (*at)(0) - 0.4 / mpp, top = (*at)(1) - 0.15 / mpp;
  // Only a panel that reaches below his head covers him; beside or above him it does not.
  if (hud_box_[3] <= top || hud_box_[2] <= body_left) return c;
  const double shift_px = std::min(hud_box_[2] + 12.0 - body_left, 0.3 * w);
  // Turned left about the eye, the whole picture slides right alike (the aim line still runs
  // up to the flag), as a camera operator frames a golfer off centre.
  const double focal_px = 0.5 * h / std::tan(0.5 * c.fov_y);
  const double turn = std::atan2(shift_px, focal_px);
  const Vec3 look = c.target - c.eye;
  Camera turned = c;
  turned.target = c.eye + Eigen::AngleAxisd(turn, Vec3::UnitY()) * look;
  return turned;
}

Camera GolfView::high_camera() const {
  const GolfRound& r = play_->round();
  const Vec3 b = play_->ball_centre();
  const Vec3 d = play_->aim_direction();
  const double reach = std::min(r.to_pin(), 300.0);
  Camera c;
  c.eye = b - (0.15 * reach + 10.0) * d + Vec3(0.0, 0.2 * reach + 12.0, 0.0);
  c.target = b + 0.7 * reach * d;
  c.fov_y = deg_to_rad(45.0);
  return c;
}

Camera GolfView::map_camera() const {
  // The hole from above, up the picture from its tee toward its cup (so the map keeps its
  // way up however the ball lies, past the cup included), framing the ball and the cup: the
  // lowest of them 80 % of the way down the picture (above the meter), the highest 15 % from
  // its top, so the green behind the flag is on the map. In flight, and while the ball
  // settles, the stroke from where it was struck to where it stops.
  const GolfRound& r = play_->round();
  const std::size_t shown = std::min(play_->hole_shown(), r.course().holes.size() - 1);
  const CourseHole& hole = r.course().holes[shown];
  const Vec3& pin = hole.pin;
  const Vec3 d = flat_unit(hole.tee, pin);
  std::vector<Vec3> points;
  const bool after_stroke = play_->after_stroke() || r.finished() || r.hole_index() != shown;
  if (after_stroke || (flight_shown_ && play_->last_shot().trajectory.samples.size() >= 2)) {
    points.push_back(play_->last_shot().launch_state.position);
    points.push_back(play_->last_shot().trajectory.summary.rest_position);
  }
  if (!r.finished() && r.hole_index() == shown) points.push_back(r.ball());
  if (points.empty()) points.push_back(hole.tee);
  double lo = 0.0, hi = 0.0;  // m along d from the cup
  for (const Vec3& p : points) {
    const double a = (p.x() - pin.x()) * d.x() + (p.z() - pin.z()) * d.z();
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  Camera c;
  c.fov_y = deg_to_rad(40.0);
  constexpr double kLowestAt = 0.80, kHighestAt = 0.15;
  const double span = std::max(hi - lo, 30.0) / (kLowestAt - kHighestAt);  // m from the picture's top to its bottom
  const double height = 0.5 * span / std::tan(0.5 * c.fov_y);
  const Vec3 mid = pin + (lo + (kLowestAt - 0.5) * span) * d;
  c.target = mid;
  c.eye = mid + Vec3(0.0, height, 0.0) - 0.02 * height * d;
  c.up = d;
  // A chart seen from a kilometre up: the depth range hugs the ground (no seams from a
  // near plane 0.5 m away), and the view lifts its haze (frame()).
  c.near_m = 0.5 * height;
  c.far_m = height + 2000.0;
  return c;
}

Camera GolfView::flyover_camera(double progress) const {
  // From the tee up and along the hole to the green, settling behind the cup's flag.
  const GolfRound& r = play_->round();
  const CourseHole& h = r.hole();
  const double s = progress * progress * (3.0 - 2.0 * progress);  // smoothstep
  const Vec3 d = flat_unit(h.tee, h.pin);
  const double len = h.length();
  Camera c;
  const Vec3 along = h.tee + s * (h.pin - h.tee);
  c.eye = along - (20.0 + 0.1 * len * (1.0 - s)) * d + Vec3(0.0, 35.0 - 12.0 * s, 0.0);
  c.target = h.pin + (1.0 - s) * 0.2 * (h.tee - h.pin);
  c.fov_y = deg_to_rad(50.0);
  return c;
}

namespace {
// The rest pin's label: a putt's is what it leaves ("6 ft to the cup"; beside the cup its
// length read as that), none once holed; any other stroke's is its total.
std::optional<std::string> rest_label(const StrokeRecord& r, const GolfUnits& units) {
  if (r.club != "putter") return std::nullopt;
  if (r.end == StrokeEnd::Holed) return std::string();
  return units.course(r.to_pin_m) + " to the cup";
}
}  // namespace

std::unique_ptr<ShotScene> GolfView::stroke_scene() const {
  std::unique_ptr<ShotScene> scene;
  try {
    scene = std::make_unique<ShotScene>(*stroke_input_);  // its club, tee, markers and target line
  } catch (const std::exception&) {
    return nullptr;  // the stroke's world or club mesh cannot be loaded again
  }
  const ShotResult& shot = play_->last_shot();
  scene->set_shot(shot.trajectory, impactor_placement(shot));
  scene->set_rest_label(rest_label(play_->last_record(), units_));
  return scene;
}

const ShotScene* GolfView::clip_scene() const {
  if (!stroke_input_ || play_->last_shot().trajectory.samples.size() < 2) return nullptr;  // nothing played yet
  if (!clip_ || clip_struck_ != play_->struck_at()) {
    clip_ = stroke_scene();
    if (!clip_) return nullptr;
    clip_struck_ = play_->struck_at();
  }
  return clip_.get();
}

bool GolfView::can_replay() const {
  const GolfPlay::Stage stage = play_->stage();
  const bool at_rest = stage == GolfPlay::Stage::Aiming || stage == GolfPlay::Stage::HoleOver ||
                       stage == GolfPlay::Stage::RoundOver;
  return at_rest && stroke_input_ && play_->last_shot().trajectory.samples.size() >= 2;
}

void GolfView::start_replay(double now) {
  Replay r;
  r.scene = stroke_scene();
  if (!r.scene) return;  // no replay
  const ShotResult& shot = play_->last_shot();
  ClipTiming timing;
  timing.start = -r.scene->pre_roll();
  timing.end = duration(shot.trajectory);
  timing.fps = static_cast<int>(kReplayFps);
  timing.slow = kReplaySlow;
  r.times = clip_frame_times(timing);
  r.from = now;
  // Whose stroke: the last one struck, which may be another player's.
  const GolfGroup& g = play_->group();
  const int who = play_->shooter();
  if (who >= 0 && who < static_cast<int>(g.players().size())) {
    // The last stroke swung (a conceded putt after it was not).
    const HoleCard* card = nullptr;
    std::size_t stroke = 0;
    for (const HoleCard& c : g.round(who).card())
      for (std::size_t k = 0; k < c.shots.size(); ++k)
        if (!c.shots[k].conceded) card = &c, stroke = k + 1;
    r.whose = g.players()[static_cast<std::size_t>(who)].name;
    if (card != nullptr) r.whose += ", stroke " + std::to_string(stroke) + " on hole " + std::to_string(card->number);
    r.whose += ", " + play_->last_record().club;
  }
  replay_ = std::move(r);
}

bool GolfView::draw_replay(const ViewInput& in, Renderer& renderer) {
  Replay& r = *replay_;
  const auto frame = static_cast<std::size_t>(std::max(0.0, in.now - r.from) * kReplayFps);
  if (r.times.empty() || frame >= r.times.size() + static_cast<std::size_t>(kReplayFps)) return false;  // 1 s at rest, then done
  const double t = r.times[std::min(frame, r.times.size() - 1)];
  const double end = r.times.back();
  if (!r.struck && t >= 0.0) {
    sound_strike(play_->last_shot());
    r.struck = true;
  }
  const int w = in.width, h = in.height;
  if (w <= 0 || h <= 0) return true;
  fit_renderer(renderer, w, h, in.render_scale);
  // Behind the golfer through the strike, then alongside the whole flight, then after the
  // ball for its last second.
  const Camera behind = stroke_view_ ? *stroke_view_ : r.scene->camera(CameraKind::Behind, t, w, h);
  Camera cam = blend_cameras(behind, r.scene->camera(CameraKind::Side, t, w, h),
                             ease_in_out(std::clamp((t - kHoldAddress) / kLeaveAddress, 0.0, 1.0)));
  const double follow_from = std::max(kHoldAddress + kLeaveAddress, end - 1.5);
  cam = blend_cameras(cam, r.scene->camera(CameraKind::Follow, t, w, h),
                      ease_in_out(std::clamp((t - follow_from) / 0.5, 0.0, 1.0)));
  renderer.draw(r.scene->build(cam, t, w, h), cam);
  renderer.blit_to(0, w, h);
  draw_banner(("Replay" + (r.whose.empty() ? std::string() : ": " + r.whose) + "   R: stop").c_str(), w, 20.0f);
  draw_launch_panel(play_->last_shot(), units_, w, std::max(t, 0.0), play_->last_hit_tree());
  return true;
}

void GolfView::frame(const ViewInput& in, Renderer& renderer) {
  const std::vector<KeyPress> keys = calibration_keys(in.keys, in.now);
  view_keys(keys);
  if (replay_ && !can_replay()) replay_.reset();
  if (replay_) {
    // The game waits while the stroke is shown again; its keys (but R) wait too.
    play_->update({}, in.now);
    if (draw_replay(in, renderer)) return;
    replay_.reset();
  }
  play_->update(golf_intents(keys), in.now);
  const GolfPlay::Stage stage = play_->stage();
  const int w = in.width, h = in.height;
  view_height_ = h;
  const bool flying = stage == GolfPlay::Stage::Flying;
  // The ball's rest stays on screen a moment before the next player's view.
  // (A hole's end shows its card at once: the card stands over the green it was played to.)
  const bool settling = stage == GolfPlay::Stage::Aiming && flight_shown_ && play_->last_shot().trajectory.samples.size() >= 2 &&
                        in.now - play_->landed_at() < kSettle;
  const bool addressing = !settling && (stage == GolfPlay::Stage::Aiming || stage == GolfPlay::Stage::Swinging);
  const bool flyover = stage == GolfPlay::Stage::Flyover;
  const bool over = !settling && (stage == GolfPlay::Stage::HoleOver || stage == GolfPlay::Stage::RoundOver);
  if (flying && flight_struck_ != play_->struck_at()) flight_shown_ = false;
  // A round resumed already over has drawn no scene yet: its last green.
  if (over && !scene_) ensure_scene(assets_.equipment().club_info_of("putter").mesh);
  if (addressing || flyover) {
    ensure_scene(assets_.equipment().club_info_of(play_->club()).mesh);
    if (scene_) {
      scene_->set_shot(ball_at_rest(play_->ball_centre()), std::nullopt);
      scene_->set_aim(addressing ? std::optional<Vec3>(play_->aim_direction()) : std::nullopt);
      // The stripes' numbers around where the chosen club carries come first.
      const GolfBot::Stock* stock = addressing ? play_->caddie().stock_of(play_->club()) : nullptr;
      scene_->set_focus(stock ? std::optional<double>(stock->carry) : std::nullopt);
      // The player at address: his club square behind the ball along his aim.
      std::optional<ImpactorPlacement> club;
      if (addressing) club = club_at_address(play_->ball_centre(), play_->aim_direction(), assets_.equipment().ball("tour").radius);
      scene_->set_address(club);
      // The player's backswing follows the meter's marker up and back down (a full swing at
      // 100 % is the top); at rest or between clicks, at the ball.
      const auto& meter = play_->meter();
      scene_->set_backswing(addressing && meter && stage == GolfPlay::Stage::Swinging ? meter->position(in.now) : 0.0);
      const HoleWind wind = play_->round().wind();
      scene_->set_wind(wind.speed * Vec3(std::cos(wind.toward), 0.0, std::sin(wind.toward)));
    }
    flight_shown_ = false;
    const GolfRound& r = play_->round();
    const bool green = !r.finished() && r.lie() == "green";
    if (green && (slopes_for_ != r.card().size() || slopes_ball_ != r.ball())) {
      slopes_ = slope_arrows(green_slopes(*r.hole().world, r.ball(), r.hole().pin));
      slopes_for_ = r.card().size();
      slopes_ball_ = r.ball();
    } else if (!green) {
      slopes_.clear();
    }
    if (scene_) scene_->set_ground_arrows(addressing ? slopes_ : std::vector<GroundArrow>{});
  } else if (scene_) {
    scene_->set_aim(std::nullopt);  // the shot's own line from where it was hit
    scene_->set_ground_arrows({});
    scene_->set_focus(std::nullopt);
    if (!flight_shown_ && !play_->last_shot_on_hole_shown()) {
      flight_shown_ = true;  // a hole given up unplayed: no stroke of it to show or sound
    } else if (!flight_shown_) {
      // A bot may strike before his address was drawn: the scene still holds the last
      // player's club, whose full finish a putt must not take.
      if (!play_->last_shot().impactor_mesh.empty()) ensure_scene(play_->last_shot().impactor_mesh);
      scene_->set_shot(play_->last_shot().trajectory, impactor_placement(play_->last_shot()));
      scene_->set_rest_label(rest_label(play_->last_record(), units_));
      scene_->set_target_line(aim_line(play_->last_shot().aim));  // the high camera and the replay's side view
      sound_strike(play_->last_shot());
      rattle_due_ = play_->last_shot().end == ShotEnd::Holed;
      stroke_input_ = scene_->input();
      // A stroke struck before its player's address was ever drawn (Enter lets a bot play at
      // once) would hold the last view at address, the previous player's, for the swing:
      // a chip watched from the tee 150 m away. Then the view from behind this ball instead.
      // So is a view that looks another way: the previous player's, aimed down his own line
      // from a ball beside this one (the ball would leave the picture sideways).
      const Vec3 launch = play_->last_shot().launch_state.position;
      const Vec3 leaves = play_->last_shot().launch_state.velocity;
      constexpr double kAddressReach = 15.0;  // m: the full-shot view stands ~9.4 m from the ball
      constexpr double kAddressTurn = 0.52;   // rad (30°): more than any start line strays from the aim
      const auto looks_along = [&](const Camera& c) {
        const Vec3 f = c.forward();
        const double a = std::atan2(f.z(), f.x()), b = std::atan2(leaves.z(), leaves.x());
        return std::abs(std::remainder(a - b, 2.0 * kPi)) < kAddressTurn || std::hypot(leaves.x(), leaves.z()) < 1e-9;
      };
      if (w > 0 && h > 0 &&
          (!address_view_ || (address_view_->eye - launch).norm() > kAddressReach || !looks_along(*address_view_))) {
        // The view this stroke's address would have had: behind its ball, down the line it
        // left on (the scene's Behind camera looks down the world's +x, a range's line).
        Vec3 line(leaves.x(), 0.0, leaves.z());
        line = line.norm() > 1e-9 ? line.normalized() : play_->aim_direction();
        // (A putt's view reaches as far as this putt rolled: the round may be over, no cup.)
        address_view_ = address_camera_at(launch, line, play_->last_record().club == "putter",
                                          play_->last_shot().trajectory.summary.total_m);
      }
      stroke_view_ = address_view_;
      flight_shown_ = true;
      flight_struck_ = play_->struck_at();
    }
  }
  const double end = duration(play_->last_shot().trajectory);
  const double t = flying ? std::clamp(in.now - play_->struck_at(), 0.0, end) : (over || settling) ? end : 0.0;
  // The holed ball drops into the cup as its flight ends: the rattle, at the speed it came in.
  if (rattle_due_ && (!flying || t >= end)) {
    sound_clip(synthesize_cup_drop(cup_entry_speed(play_->last_shot().trajectory)));
    rattle_due_ = false;
  }
  Camera cam;
  if (w > 0 && h > 0 && scene_) {
    fit_renderer(renderer, w, h, in.render_scale);
    if (flyover) {
      cam = flyover_camera(play_->flyover_progress(in.now));
    } else if (flying || settling) {
      // After each shot the camera goes with the ball and shows where it stopped.
      cam = camera_ == 3   ? map_camera()
            : camera_ == 2 ? scene_->camera(CameraKind::Behind, t, w, h)
            : camera_ == 4 ? green_camera(false)
                           : scene_->camera(CameraKind::Follow, t, w, h);
      // The player's camera stays behind the golfer while he swings through and the ball
      // leaves, then goes after the ball.
      // A putt is watched as television shows one: from behind the ball down its line with
      // the cup in the picture, to the end (a chase camera rises over a rolling ball and
      // loses the cup).
      const bool putt = play_->last_record().club == "putter";
      if (camera_ == 1 && putt && address_view_)
        cam = *address_view_;
      else if (camera_ == 1 && flying && address_view_)
        cam = blend_cameras(*address_view_, cam, ease_in_out(std::clamp((t - kHoldAddress) / kLeaveAddress, 0.0, 1.0)));
    } else if (addressing) {
      cam = camera_ == 2   ? high_camera()
            : camera_ == 3 ? map_camera()
            : camera_ == 4 ? green_camera(true)
                           : golfer_clear_of_panel(address_camera(), w, h);
      address_view_ = cam;
    } else {
      cam = green_camera(false);
    }
    Scene view = scene_->build(cam, t, w, h);
    // From above, the map reads as a chart: the distance haze of a view along the ground
    // (2.5 km) would wash a long hole seen from a kilometre up half out.
    if (camera_ == 3 && !flyover) view.haze_range = std::max(view.haze_range, static_cast<float>(20.0 * (cam.eye - cam.target).norm()));
    renderer.draw(view, cam);
    renderer.blit_to(0, w, h);
    const GolfRound& r = play_->round();
    // The cup of the hole on show: a holing putt's until its ball has dropped and settled.
    if (flying || settling)
      draw_cup_and_flag(cam, play_->group().course().holes.at(play_->hole_shown()).pin, w, h, true, {}, view.label_boxes);
    // Addressing a far pin, the flag says how far it is: a stripe's "250" drawn beside a pin
    // 395 yd away reads as the pin's.
    else if (!r.finished() && !over)
      // (Not kept clear of the image's labels: their boxes hold the room beside this flag for
      // it, and while addressing no shot is labelled. Clear of the play panel, last frame's.)
      draw_cup_and_flag(cam, r.hole().pin, w, h, true, addressing && r.lie() != "green" ? units_.course(r.to_pin()) : std::string(),
                        {hud_box_});
    if (addressing) {
      draw_aim(*play_, cam, w, h);
      draw_putt_read(*play_, cam, w, h);  // over the aim line it starts along
      if (camera_ != 3) draw_other_balls(*play_, cam, w, h, {hud_box_, wind_area(w)});  // the map marks its own
    }
    if (addressing && camera_ == 3) {
      std::vector<Eigen::Vector4f> taken = view.label_boxes;
      taken.push_back(meter_area(w, h));  // the meter and its caption stand over the map
      taken.push_back(hud_box_);
      taken.push_back(wind_area(w));
      draw_map_marks(*play_, units_, cam, w, h, r.hole().world->trees, taken);
    }
  }
  hud_box_ = draw_golf_hud(*play_, units_, camera_, settling, t, all_keys());
  // Shown over the course as the ball flies too (S pressed mid-flight is answered at once);
  // its time starts when it is first seen, so a note behind a card is not spent unread.
  const bool note_shows = addressing || flying || settling;
  if (!saved_note_.empty() && note_shows && saved_note_at_ < 0.0) saved_note_at_ = in.now;
  if (!saved_note_.empty() && saved_note_at_ >= 0.0 && in.now - saved_note_at_ > kNoteShown) saved_note_.clear();
  if (!saved_note_.empty() && note_shows) {
    // Top, between the play panel (430 px) and the launch monitor (250 px from the right):
    // clear of the trail's legend and the meter at the bottom.
    constexpr float kLeft = 440.0f, kRightPanel = 260.0f;
    const float room = std::max(200.0f, static_cast<float>(w) - kLeft - kRightPanel);
    ImGui::SetNextWindowPos(ImVec2(kLeft, 10), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(room, 400));
    ImGui::Begin("saved", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushTextWrapPos(room - 16.0f);  // window-local
    ImGui::TextUnformatted(saved_note_.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
  }
  const bool card_up = (stage == GolfPlay::Stage::HoleOver || stage == GolfPlay::Stage::RoundOver) && !settling;
  if (flying || settling) draw_launch_panel(play_->last_shot(), units_, w, flying ? t : end, play_->last_hit_tree());
  else if (!in.paused && !(card_up && golf_card_covers_wind(w)))  // the menu stands there; a narrow window's card
    draw_wind(*play_, units_, w, screen_up_heading(cam));
  if (!settling) draw_golf_meter(*play_, units_, w, h, in.now);
  if (calibration_) draw_calibration(w, h, in.now);
  if (stage == GolfPlay::Stage::HoleOver && !settling) draw_golf_card(*play_, w, false);
  if (stage == GolfPlay::Stage::RoundOver && !settling) {
    draw_golf_card(*play_, w, true);
    if (done_frames_ == 0) out_ << group_table(play_->group(), play_->restarts());
    ++done_frames_;
  } else if (stage != GolfPlay::Stage::RoundOver) {
    done_frames_ = 0;
  }
}

}  // namespace

std::unique_ptr<ModeView> make_golf_view(const Assets& assets, std::unique_ptr<GolfPlay> model, const GolfViewOptions& o,
                                         std::ostream& out) {
  return std::make_unique<GolfView>(assets, std::move(model), o, out);
}

}  // namespace sweetspot
