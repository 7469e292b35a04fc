// The game's window: GLFW with an OpenGL 3.3 core context and Dear ImGui (Debian's GLFW +
// OpenGL3 backends). It owns nothing of the simulation; the app draws the renderer's
// framebuffer into it each frame and lays the panels on top.
#pragma once

#include <string>
#include <vector>

#include "game/ui/mode_view.hpp"

struct GLFWwindow;

namespace sweetspot {

struct WindowOptions {
  int width = 1280;          ///< px, window client area; panels are laid out for 1280×800
  int height = 800;          ///< px
  std::string title = "Sweetspot";
  bool vsync = true;         ///< off for automation (--frames) so frames are not throttled
};

/// Mouse and keyboard input of one frame that the scene (not ImGui) should act on.
struct FrameInput {
  double orbit_dx = 0.0;         ///< px dragged with the left button this frame
  double orbit_dy = 0.0;
  double zoom = 0.0;             ///< scroll wheel clicks, + = in
  /// Every key pressed since the last frame, in order, each with the time it went down
  /// (s on the window's clock, read in the key callback).
  std::vector<KeyPress> keys;
};

class GameWindow {
 public:
  /// Opens the window and initialises ImGui. Throws std::runtime_error naming what failed
  /// (no display, no GL 3.3 context).
  explicit GameWindow(const WindowOptions& options);
  ~GameWindow();
  GameWindow(const GameWindow&) = delete;
  GameWindow& operator=(const GameWindow&) = delete;

  bool should_close() const;
  /// Polls events and starts an ImGui frame; returns the input the scene should use
  /// (nothing is reported while ImGui has the mouse or keyboard).
  FrameInput begin_frame();
  /// Renders ImGui over whatever was drawn into the default framebuffer.
  void render_ui();
  /// Reads the default framebuffer's back buffer (after render_ui, before present) as
  /// top-down RGBA.
  void read_pixels(int& width, int& height, std::vector<unsigned char>& rgba) const;
  /// Swaps buffers.
  void present();

  int framebuffer_width() const;
  int framebuffer_height() const;
  GLFWwindow* handle() const { return window_; }
  /// s since the window opened: the clock key presses are stamped with.
  double clock() const;
  /// Called by the GLFW callbacks: queue one key press (stamped now) / scroll step for the next frame.
  void queue_key(int key) { keys_.push_back({key, clock()}); }
  void queue_scroll(double dy) { scroll_ += dy; }

 private:
  GLFWwindow* window_ = nullptr;
  double last_x_ = 0.0, last_y_ = 0.0;
  bool dragging_ = false;
  std::vector<KeyPress> keys_;
  double epoch_ = 0.0;  ///< steady clock (s) when the window opened
  double scroll_ = 0.0;
};

}  // namespace sweetspot
