// F10 in the window: a clip of the shot on screen, rendered off-screen on its own thread (its
// own EGL context) while play goes on, and written as sweetspot_clip_N.mp4 (render --video's
// clip: the downswing, the strike in slow motion, the flight).
#pragma once

#include <filesystem>
#include <future>
#include <string>
#include <vector>

namespace sweetspot {

class ShotScene;

class ClipRecorder {
 public:
  explicit ClipRecorder(std::filesystem::path dir) : dir_(std::move(dir)) {}
  /// Waits for the clips still being made.
  ~ClipRecorder();
  ClipRecorder(const ClipRecorder&) = delete;
  ClipRecorder& operator=(const ClipRecorder&) = delete;

  /// Starts a clip of `scene`'s shot; returns the file it will be, or "" when there is no
  /// shot to show.
  std::string start(const ShotScene& scene);
  /// Whether a clip is still being made. One at a time: each is a whole off-screen render on
  /// its own thread, so F10 held down (key repeat) would start dozens, and the program's exit
  /// waits for them all.
  bool busy();
  /// Waits until every clip started is written (or has failed).
  void wait();
  /// One line for each clip finished since the last call ("clip: F (N frames)" or why not).
  std::vector<std::string> finished();

 private:
  std::filesystem::path dir_;
  int count_ = 0;
  std::vector<std::future<std::string>> jobs_;
};

}  // namespace sweetspot
