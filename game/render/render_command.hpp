// One call from a shot to a PNG (the `sweetspot render` command and the bench use these).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "game/render/camera.hpp"
#include "game/render/offscreen_context.hpp"
#include "game/render/shot_scene.hpp"
#include "physics/trajectory.hpp"

namespace sweetspot {

struct RenderRequest {
  const Assets* assets = nullptr;   ///< required: meshes
  const WorldAsset* world = nullptr;///< drawn and asked for heights; nullptr = a grass plane
  std::string distance_unit = "yd"; ///< "yd" golf stripes, "ft" baseball fence marks
  bool tee = false;                 ///< the ball was teed up
  double ball_radius = 0.021335;    ///< m
  std::optional<ImpactorPlacement> impactor;  ///< club/bat mesh frame -> world at impact
  std::string impactor_mesh;        ///< "driver_head", "iron_head", "putter_head", "bat", a path, or ""
  std::optional<Vec3> flag;         ///< m; see ShotSceneInput::flag
  std::vector<std::pair<Vec3, Eigen::Vector3f>> tee_markers;  ///< see ShotSceneInput::tee_markers
  Vec3 wind = Vec3::Zero();         ///< m/s; see ShotSceneInput::wind
  Vec3 target_line = Vec3::UnitX(); ///< see ShotSceneInput::target_line
  PeopleFn people;                  ///< see ShotSceneInput::people
  int width = 1280, height = 720;   ///< px, 16..8192
  CameraKind camera = CameraKind::Behind;
  std::optional<double> at_seconds; ///< s since launch, 0..end; nothing = the shot's end
  int samples = 0;                  ///< MSAA samples, 0 = auto (see RendererOptions)
  int shadows = -1;                 ///< sun shadows: 1 on, 0 off, -1 auto (see RendererOptions)
  EglPlatform platform = EglPlatform::Auto;
};

/// The scene a request draws (what it names of the shot, its world and its impactor), and
/// back: the request that draws a scene's input again (size and camera left at their defaults).
ShotSceneInput scene_input_of(const RenderRequest& request);
RenderRequest render_request_of(const ShotSceneInput& input);

/// Renders the shot off-screen and returns RGBA8 pixels, top row first. Throws InputError
/// for bad request values (size, time outside 0..end, unknown world/mesh/sport),
/// RenderUnavailable when no GL context can be made, RenderError for shader/mesh failures.
std::vector<std::uint8_t> render_shot_rgba(const ShotTrajectory& trajectory, const RenderRequest& request);

/// A clip of the shot (render --video): from the downswing to the shot's end at `fps`, the
/// strike slowed `slow` times (game/render/video_clip.hpp). `request.at_seconds` is ignored.
struct VideoRequest {
  int fps = 30;
  double slow = 1.0;
};
/// Pixels a clip may draw in all (frames x width x height): 4e9, ~4 min of llvmpipe at its
/// measured ~16 Mpx/s (the default 1280x720 clip of a drive, ~350 frames, is 3.2e8 in 20 s),
/// e.g. 1080p at 30 fps for a minute.
inline constexpr double kMaxClipPixels = 4e9;
/// The clip's frame times; throws InputError (naming --fps, --slow-motion and the size)
/// when they would draw more than kMaxClipPixels, before anything is drawn or written.
std::vector<double> video_frame_times(const ShotTrajectory& trajectory, const RenderRequest& request,
                                      const VideoRequest& video);
/// Renders every frame off-screen and writes them as an H.264 MP4 to `out`, atomically.
/// Returns the number of frames. Throws as render_shot_rgba and video_frame_times.
int render_shot_video(const ShotTrajectory& trajectory, const RenderRequest& request, const VideoRequest& video,
                      const std::filesystem::path& out);

/// render_shot_rgba, then write_png_atomic(out, ...).
void render_shot_png(const ShotTrajectory& trajectory, const RenderRequest& request, const std::filesystem::path& out);

/// Mean ms per warm w x h off-screen frame — scene build + draw + MSAA resolve + read-back —
/// over `frames` frames after 3 warm-up frames, for a synthetic drive on the golf_hole world.
/// Throws RenderUnavailable without EGL. `shadows` as RendererOptions::shadows.
double measure_frame_ms(const Assets& assets, int w, int h, int frames, int shadows = -1);

}  // namespace sweetspot
