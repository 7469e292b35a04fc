// A game mode's view (DESIGN §1): it draws its model with the renderer and Dear ImGui and
// turns the frame's key presses into intents for the model; it never changes the model any
// other way and never runs physics. The app's one loop calls the active view once a frame
// and keeps the others, with their models, as they were.
#pragma once

#include <initializer_list>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "game/modes/intent.hpp"
#include "game/report/impact_sound.hpp"
#include "game/report/world_sounds.hpp"

namespace sweetspot {

class Renderer;
class ShotScene;

/// A window at least this tall (px) lists every key in a mode's panel at first; a shorter one
/// (the game allows 480) starts with the few a stroke or pitch needs: the full list's extra
/// four or five lines ran the golf panel under the meter and the cage's off the window's
/// bottom at 640x480. K brings the list either way.
inline constexpr int kAllKeysMinHeight = 600;

/// A key that went down: its GLFW key code and when (s, on the clock the view is given).
struct KeyPress {
  int key = 0;
  double time = 0.0;
};

/// The keys a view knows, each turned into its intent at the key's own time; other keys are
/// left out. `bindings`: (GLFW key code, intent) pairs.
inline Intents intents_from_keys(const std::vector<KeyPress>& keys,
                                 std::initializer_list<std::pair<int, IntentKind>> bindings) {
  Intents out;
  for (const KeyPress& k : keys)
    for (const auto& [key, kind] : bindings)
      if (k.key == key) {
        Intent in;
        in.kind = kind;
        in.time = k.time;
        out.push_back(in);
      }
  return out;
}

struct ViewInput {
  double now = 0.0;              ///< s on the mode's clock (stops while paused or in another mode)
  double dt = 0.0;               ///< s since this view's last frame, on that clock
  int width = 0, height = 0;     ///< px, the window's framebuffer
  std::vector<KeyPress> keys;    ///< on the mode's clock, in order (Tab and Esc are the app's)
  double orbit_dx = 0.0, orbit_dy = 0.0;  ///< px dragged with the left button
  double zoom = 0.0;             ///< scroll wheel clicks, + = in
  /// The share of the window's pixels per side the 3D view is rendered at, then scaled up
  /// (dynamic resolution: the loop lowers it when frames run over budget). HUD and panels
  /// stay at full resolution.
  double render_scale = 1.0;
  /// The pause menu is up: overlays drawn over every window (the foreground draw list) that
  /// stand where the menu does are left out, so they do not cover its buttons.
  bool paused = false;
};

/// Sizes `renderer` for a w x h view at `scale` (each side rounded, at least 16 px); the
/// view then builds its scene for w x h (so pixel-sized marks keep their size on screen)
/// and blits the image up to w x h.
void fit_renderer(Renderer& renderer, int w, int h, double scale);
/// A line of text centred across a `width` px window at `y` px, in a dark box over the view
/// (the cage's call, the golf replay's label).
void draw_banner(const char* text, int width, float y);
/// The same box, `scale` times the font's size, centred on `centre_x` px; returns its bottom (px).
/// `second`, when not empty, is a second line in the same box (one message, not two).
float draw_banner(const char* text, float centre_x, float y, float scale, const char* second = "");
/// px the text of such a banner spans (without its box's padding).
float banner_text_width(std::string_view text, float scale);
/// px the banner's box reaches below its `y` (its text's line and the box's padding).
inline constexpr float kBannerHeight = 24.0f;

class ModeView {
 public:
  virtual ~ModeView() = default;
  /// The mode's name for the pause menu ("Lab", "Golf", "Batting cage").
  virtual const char* title() const = 0;
  /// One frame: the keys become intents, the model is updated to `in.now`, the scene is
  /// drawn into the window's default framebuffer and the HUD into the ImGui frame.
  virtual void frame(const ViewInput& in, Renderer& renderer) = 0;
  /// An intent from the app (Esc's Cancel, the pause menu's Restart), applied at once.
  virtual void send(const Intent& intent) = 0;
  /// Something Esc takes back without pausing is under way (a swing on the meter).
  virtual bool busy() const { return false; }
  /// What the pause menu's restart does here ("Restart hole").
  virtual const char* restart_label() const { return "Restart"; }
  /// What that restart throws away, in the player's words ("this hole's 3 strokes"); empty
  /// when nothing is lost (the pause menu then restarts without asking).
  virtual std::string restart_loses() const { return {}; }
  /// What quitting throws away, likewise (the pause menu then asks before Q quits): by
  /// default what a restart would.
  virtual std::string quit_loses() const { return restart_loses(); }
  /// Where the pause menu's right edge goes in a `w` x `h` px window: at the right by
  /// default, clear of the centre where a mode shows what the player paused to read; the lab
  /// keeps it over its view, off the launch monitor's column.
  virtual float pause_menu_right(int w, int /*h*/) const { return static_cast<float>(w) - 12.0f; }
  /// True once an automated run (--exit-when-done) has seen what it came for.
  virtual bool done() const { return false; }
  /// What the mode prints when the window closes (the swings of a batting session).
  virtual void report(std::ostream& /*out*/) const {}
  /// The scene of the shot on screen, for a clip of it (F10); nullptr when there is none.
  virtual const ShotScene* clip_scene() const { return nullptr; }
  /// The strikes to sound since the last call (the app plays them), oldest first.
  std::vector<ImpactSoundInput> take_sounds() { return std::exchange(sounds_, {}); }
  /// Other sounds due since the last call (a holed ball's rattle), made at kImpactSampleRate.
  std::vector<std::vector<float>> take_clips() { return std::exchange(clips_, {}); }
  /// The ambience under the mode while it is shown (the app loops it).
  struct AmbienceSpec {
    Ambience kind = Ambience::None;
    double wind_speed = 0.0;  ///< m/s, a course's
    bool operator==(const AmbienceSpec&) const = default;
  };
  virtual AmbienceSpec ambience() const { return {}; }

 protected:
  /// A new strike was shown: its sound is due (a shot without one, a launch-only shot, adds
  /// nothing).
  void sound_strike(const ShotResult& shot) {
    const ShotSound s = impact_sound_of(shot);
    if (s.ok) sounds_.push_back(s.input);
  }
  void sound_strike(const ImpactSoundInput& in) {
    if (in.contact_time > 0.0 && in.normal_impulse > 0.0) sounds_.push_back(in);
  }
  void sound_clip(std::vector<float> samples) {
    if (!samples.empty()) clips_.push_back(std::move(samples));
  }

 private:
  std::vector<ImpactSoundInput> sounds_;
  std::vector<std::vector<float>> clips_;
};

}  // namespace sweetspot
