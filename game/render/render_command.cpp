#include "game/render/render_command.hpp"

#include <chrono>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <string>

#include "game/render/image.hpp"
#include "game/render/renderer.hpp"
#include "game/render/render_paths.hpp"
#include "game/render/swing_pose.hpp"
#include "game/render/synthetic_shot.hpp"
#include "game/render/video_clip.hpp"
#include "physics/error.hpp"

namespace sweetspot {

namespace {

void check_size(const RenderRequest& request) {
  if (request.width < 16 || request.width > 8192 || request.height < 16 || request.height > 8192) {
    throw InputError("image size " + std::to_string(request.width) + "x" + std::to_string(request.height) +
                     " is outside 16..8192 pixels per side");
  }
}

// The shot's scene and a renderer of the request's size, on an off-screen context.
struct ShotFrames {
  OffscreenContext context;
  ShotScene scene;
  Renderer renderer;
  const RenderRequest& request;

  ShotFrames(const ShotTrajectory& trajectory, const RenderRequest& r)
      : context(r.platform), scene(scene_input_of(r)), renderer(r.width, r.height, renderer_options(r)), request(r) {
    scene.set_shot(trajectory, r.impactor);
  }
  static RendererOptions renderer_options(const RenderRequest& r) {
    RendererOptions options;
    options.samples = r.samples;
    options.shadows = r.shadows;
    return options;
  }
  std::vector<std::uint8_t> at(double t) {
    const Camera camera = scene.camera(request.camera, t, request.width, request.height);
    renderer.draw(scene.build(camera, t, request.width, request.height), camera);
    return renderer.read_pixels();
  }
};

}  // namespace

namespace {
// What a request and a scene's input both say of the scene, in one list for both directions.
template <class From, class To>
void copy_scene_fields(const From& f, To& t) {
  t.assets = f.assets;
  t.world = f.world;
  t.distance_unit = f.distance_unit;
  t.tee = f.tee;
  t.ball_radius = f.ball_radius;
  t.impactor = f.impactor;
  t.impactor_mesh = f.impactor_mesh;
  t.flag = f.flag;
  t.tee_markers = f.tee_markers;
  t.wind = f.wind;
  t.target_line = f.target_line;
  t.people = f.people;
}
}  // namespace

ShotSceneInput scene_input_of(const RenderRequest& r) {
  ShotSceneInput input;
  copy_scene_fields(r, input);
  return input;
}

RenderRequest render_request_of(const ShotSceneInput& in) {
  RenderRequest r;
  copy_scene_fields(in, r);
  return r;
}

std::vector<std::uint8_t> render_shot_rgba(const ShotTrajectory& trajectory, const RenderRequest& request) {
  if (trajectory.samples.empty()) throw InputError("render: the shot has no trajectory samples");
  const double end = trajectory.samples.back().t;
  const double t = request.at_seconds.value_or(end);
  // Before launch only as far back as the downswing the scene can show.
  const double start = -swing_pre_roll(request.impactor, request.impactor_mesh);
  if (!std::isfinite(t) || t < start || t > end + 1e-9) {
    const auto shown = [](double v) {  // %g: 1e308 is not written out as 309 digits
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", v);
      return std::string(buf);
    };
    throw InputError("--at " + shown(t) + " s is outside the shot (" + shown(start) + ".." + shown(end) + " s)");
  }
  check_size(request);
  ShotFrames frames(trajectory, request);
  return frames.at(t);
}

std::vector<double> video_frame_times(const ShotTrajectory& trajectory, const RenderRequest& request,
                                      const VideoRequest& video) {
  if (trajectory.samples.empty()) throw InputError("render: the shot has no trajectory samples");
  check_size(request);
  ClipTiming timing;
  timing.start = -swing_pre_roll(request.impactor, request.impactor_mesh);
  timing.end = trajectory.samples.back().t;
  timing.fps = video.fps;
  timing.slow = video.slow;
  std::vector<double> times = clip_frame_times(timing);
  const double pixels = static_cast<double>(times.size()) * request.width * request.height;
  if (pixels > kMaxClipPixels) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "--video: %zu frames of %dx%d (--fps %d, --slow-motion %g) draw %.3g pixels, more than the %.3g a "
                  "clip may (~4 min of software rendering); lower --fps, --slow-motion or the size",
                  times.size(), request.width, request.height, video.fps, video.slow, pixels, kMaxClipPixels);
    throw InputError(text);
  }
  return times;
}

int render_shot_video(const ShotTrajectory& trajectory, const RenderRequest& request, const VideoRequest& video,
                      const std::filesystem::path& out) {
  const std::vector<double> times = video_frame_times(trajectory, request, video);
  Mp4Writer writer(request.width, request.height, video.fps);
  ShotFrames frames(trajectory, request);
  for (double t : times) writer.add_frame(frames.at(t));
  writer.finish(out);
  return writer.frames();
}

void render_shot_png(const ShotTrajectory& trajectory, const RenderRequest& request, const std::filesystem::path& out) {
  const auto rgba = render_shot_rgba(trajectory, request);
  write_png_atomic(out, request.width, request.height, rgba);
}

double measure_frame_ms(const Assets& assets, int w, int h, int frames, int shadows) {
  if (frames < 1) throw InputError("frames " + std::to_string(frames) + " must be at least 1");
  OffscreenContext context;
  ShotSceneInput input;
  input.assets = &assets;
  input.world = assets.world("golf_hole");
  input.tee = true;
  input.impactor_mesh = "driver_head";
  ShotScene scene(input);
  ImpactorPlacement club;
  club.position = Vec3(-0.0214, 0.0214, 0.0);
  scene.set_shot(synthetic_shot(), club);
  RendererOptions options;
  options.shadows = shadows;
  Renderer renderer(w, h, options);
  const double end = scene.trajectory().samples.back().t;
  auto frame = [&](int i) {
    const double t = end * (0.5 + 0.5 * (i % 8) / 8.0);  // the trail changes as in a replay
    const Camera camera = scene.camera(CameraKind::Behind, t, w, h);
    renderer.draw(scene.build(camera, t, w, h), camera);
    return renderer.read_pixels();  // waits for the GPU, as writing an image does
  };
  for (int i = 0; i < 3; ++i) frame(i);
  const auto start = std::chrono::steady_clock::now();
  std::size_t guard = 0;
  for (int i = 0; i < frames; ++i) guard += frame(i)[0];
  const auto stop = std::chrono::steady_clock::now();
  (void)guard;
  return std::chrono::duration<double, std::milli>(stop - start).count() / frames;
}

}  // namespace sweetspot
