#include "game/app/clip_recorder.hpp"

#include <algorithm>
#include <chrono>
#include <exception>

#include "game/render/render_command.hpp"
#include "game/render/shot_scene.hpp"

namespace sweetspot {
namespace {
// 960x540 at 30 fps with the strike 40 times slower: shareable, and made in tens of seconds
// on llvmpipe beside the game.
constexpr int kClipWidth = 960, kClipHeight = 540, kClipFps = 30;
constexpr double kClipSlow = 40.0;
}  // namespace

ClipRecorder::~ClipRecorder() { wait(); }

bool ClipRecorder::busy() {
  return std::any_of(jobs_.begin(), jobs_.end(), [](std::future<std::string>& j) {
    return j.valid() && j.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
  });
}

void ClipRecorder::wait() {
  for (auto& j : jobs_)
    if (j.valid()) j.wait();
}

std::string ClipRecorder::start(const ShotScene& scene) {
  if (scene.trajectory().samples.size() < 2) return "";
  RenderRequest r = render_request_of(scene.input());
  r.impactor = scene.impactor();  // the shot's own club or bat, not the scene's first
  r.width = kClipWidth;
  r.height = kClipHeight;
  if (!r.impactor) r.impactor_mesh.clear();
  // The next number not taken: a clip never replaces an earlier one.
  std::filesystem::path path;
  std::error_code ec;
  do {
    path = dir_ / ("sweetspot_clip_" + std::to_string(++count_) + ".mp4");
  } while (std::filesystem::exists(path, ec) && count_ < 100000);
  jobs_.push_back(std::async(std::launch::async, [r, t = scene.trajectory(), path]() -> std::string {
    try {
      const int frames = render_shot_video(t, r, VideoRequest{kClipFps, kClipSlow}, path);
      return "clip: " + path.string() + " (" + std::to_string(frames) + " frames at " + std::to_string(kClipFps) + " fps)";
    } catch (const std::exception& e) {
      return "clip not written: " + std::string(e.what());
    }
  }));
  return path.string();
}

std::vector<std::string> ClipRecorder::finished() {
  std::vector<std::string> out;
  std::erase_if(jobs_, [&](std::future<std::string>& j) {
    if (j.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
    out.push_back(j.get());
    return true;
  });
  return out;
}

}  // namespace sweetspot
