// `sweetspot render SCENARIO -o FILE.png`: an off-screen image of a shot (DESIGN §7).
//
// The shot is a scenario (with --set) or, without SCENARIO, the launch-monitor flags as a
// launch-only scenario (game/cli/launch_flags.hpp): either way the one ShotSpec path, so
// render draws every file `shot` accepts, on the world the shot flew on.
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "game/cli/command.hpp"
#include "game/render/image.hpp"
#include "game/cli/launch_flags.hpp"
#include "game/content/course_file.hpp"
#include "game/content/quantity_text.hpp"
#include "game/content/scenario.hpp"
#include "game/render/render_command.hpp"
#include "game/render/video_clip.hpp"
#include "game/render/render_error.hpp"
#include "game/render/shot_view.hpp"
#include "game/util/atomic_file.hpp"
#include "physics/error.hpp"
#include "game/rules/run_shot.hpp"
#include "physics/ground.hpp"

namespace sweetspot::cli {
namespace {

struct RenderOptions {
  std::string scenario;                 // built-in name or .toml; "" = launch flags
  std::vector<std::string> overrides;   // --set key=value
  LaunchFlags launch;
  std::string output;
  int width = 1280, height = 720;
  std::string camera = "behind";
  std::string at;  // time with its unit, e.g. 2.5s or 2500ms; "" = the shot's end
  std::string impactor;  // "" = the shot's own (or the sport's default for launch numbers)
  int samples = 0;
  std::string shadows = "auto";
  std::string course;  // a course (name, .toml or directory) for a hole's overview
  std::string video;   // an MP4 of the whole shot
  int fps = 30;
  double slow = 1.0;   // slow-motion factor over the strike
  int hole = 0;
};

// A hole's overview: its line from the tee to the cup drawn as the tracer, 1 m over the
// ground, labelled with its length where it meets the cup.
ShotTrajectory hole_line(const CourseHole& h) {
  ShotTrajectory t;
  const int n = 64;
  const double len = h.length();
  // Through the bends: the point u of the way along the line.
  std::vector<Vec3> line{h.tee};
  line.insert(line.end(), h.bends.begin(), h.bends.end());
  line.push_back(h.pin);
  const auto at = [&](double u) {
    double left = u * len;
    for (std::size_t k = 1; k < line.size(); ++k) {
      const double seg = std::hypot(line[k].x() - line[k - 1].x(), line[k].z() - line[k - 1].z());
      if (left <= seg || k + 1 == line.size()) return Vec3(line[k - 1] + (seg > 0.0 ? std::min(left / seg, 1.0) : 1.0) * (line[k] - line[k - 1]));
      left -= seg;
    }
    return h.pin;
  };
  for (int i = 0; i <= n; ++i) {
    const double u = static_cast<double>(i) / n;
    TrajectorySample s;
    s.t = u * 2.0;
    Vec3 p = at(u);
    SurfaceContact hit;
    const WorldDescription& d = h.world->description();
    if (ground_under(*h.world->world, p.x(), p.z(), d.bounds_max.y(), d.bounds_max.y() - d.bounds_min.y(), &hit)) p.y() = hit.point.y();
    s.position = p + Vec3(0.0, 1.0, 0.0);
    s.velocity = (h.pin - h.tee) / 2.0;
    t.samples.push_back(s);
  }
  t.samples.back().position = h.pin;
  t.samples.back().phase = Phase::Rest;
  t.summary.carry_m = t.summary.total_m = len;
  t.summary.hang_time_s = t.summary.total_time_s = 2.0;
  t.summary.landing_position = t.summary.rest_position = h.pin;
  return t;
}

RunFn setup_render(CLI::App& sub) {
  auto o = std::make_shared<RenderOptions>();
  sub.add_option("scenario", o->scenario, "built-in scenario name or .toml path (without it: the launch flags below)");
  sub.add_option("-o,--output", o->output, "PNG file to write (written atomically)");
  sub.add_option("--video", o->video, "MP4 (H.264) of the whole shot from the downswing, written atomically");
  const CLI::Option* fps = sub.add_option("--fps", o->fps, "--video: frames per second, 1..240")->capture_default_str();
  const CLI::Option* slow =
      sub.add_option("--slow-motion", o->slow,
                     "--video: play the strike (10 ms before to 40 ms after contact) this many times slower, 1..1000")
          ->capture_default_str();
  sub.add_option("--width", o->width, "image width in pixels (16..8192)")->check(int_range<int>(16, 8192))->capture_default_str();
  sub.add_option("--height", o->height, "image height in pixels (16..8192)")->check(int_range<int>(16, 8192))->capture_default_str();
  sub.add_option("--camera", o->camera, "behind, side, top or follow")->capture_default_str();
  sub.add_option("--at", o->at, "time since launch with its unit, e.g. 2.5s or 2500ms (default: the shot's end)");
  add_launch_flags(sub, o->launch, false);
  // The launch flags that describe a launch's setting; a SCENARIO brings its own.
  std::vector<const CLI::Option*> launch_only;
  for (const char* name : {"--sport", "--spin-axis", "--direction", "--aero", "--world"})
    launch_only.push_back(sub.get_option(name));
  sub.add_option("--impactor", o->impactor, "driver_head, iron_head, putter_head, bat or none (default: the shot's)")
      ->check(CLI::IsMember({"driver_head", "iron_head", "putter_head", "bat", "none"}));
  sub.add_option("--msaa", o->samples, "multisample count: 0 = auto (4 on a GPU, 1 on llvmpipe), 1, 2, 4, 8")
      ->capture_default_str()->check(CLI::IsMember({0, 1, 2, 4, 8}));
  sub.add_option("--course", o->course, "a course (name, .toml or a directory from course import): draw the overview of --hole");
  sub.add_option("--hole", o->hole, "the hole to overview with --course, 1..18")->check(int_range<int>(1, 18));
  sub.add_option("--shadows", o->shadows, "sun shadows: auto (on with a GPU, off on llvmpipe for speed), on or off")
      ->capture_default_str()->check(CLI::IsMember({"auto", "on", "off"}));
  return [o, launch_only, fps, slow](const Assets& assets) -> int {
    // The clip's settings without a clip would be ignored: said instead.
    for (const CLI::Option* clip_only : {fps, slow})
      if (o->video.empty() && clip_only->count() > 0)
        throw InputError(clip_only->get_name() + ": a setting of the clip; give it with --video F.mp4");
    RenderRequest r;
    r.camera = parse_camera_kind(o->camera);
    std::optional<double> at;
    if (!o->at.empty()) {
      try {
        at = read_quantity(o->at, Dimension::Time);
      } catch (const InputError& e) {
        throw InputError(std::string("--at ") + o->at + ": " + e.what());
      }
    }
    if (o->output.empty() && o->video.empty()) throw InputError("render: no output named: give -o F.png (--output), --video F.mp4, or both");
    if (!o->output.empty()) check_png_output(o->output, "-o");
    if (!o->video.empty()) {
      check_output_path(o->video, "--video");
      std::string ext = std::filesystem::path(o->video).extension().string();
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (ext != ".mp4") throw InputError("--video " + o->video + ": the clip is an MP4 (H.264); name it FILE.mp4");
      if (!o->output.empty() && same_output_file(o->output, o->video))
        throw InputError("-o " + o->output + " --video " + o->video + ": the image and the clip would overwrite each other");
      if (at) throw InputError("--at picks one frame for -o; --video renders the whole shot (leave --at out)");
      if (!o->course.empty()) throw InputError("--video: a hole's overview (--course) is a still image; use -o");
      clip_frame_times(ClipTiming{0.0, 0.0, o->fps, o->slow});  // --fps and --slow-motion in range
    }
    if (!o->course.empty() || o->hole > 0) {
      if (o->course.empty() || o->hole == 0) throw InputError("render: --course and --hole go together (a hole's overview)");
      if (!o->scenario.empty() || has_launch_numbers(o->launch))
        throw InputError("render: --course draws a hole's overview; give no SCENARIO or launch flags with it");
      const Course c = load_course(assets, o->course);
      if (o->hole > static_cast<int>(c.holes.size()))
        throw InputError("--hole " + std::to_string(o->hole) + ": the course has " + std::to_string(c.holes.size()) + " holes");
      const CourseHole& h = c.holes[static_cast<std::size_t>(o->hole - 1)];
      RenderRequest r;
      r.assets = &assets;
      r.world = h.world;
      r.flag = h.pin;
      r.tee = true;
      r.camera = parse_camera_kind(o->camera);
      r.width = o->width;
      r.height = o->height;
      r.samples = o->samples;
      r.shadows = o->shadows == "on" ? 1 : o->shadows == "off" ? 0 : -1;
      try {
        render_shot_png(hole_line(h), r, o->output);
      } catch (const RenderUnavailable& e) {
        std::cerr << "sweetspot render: " << e.what() << "\n";
        return 3;
      } catch (const RenderError& e) {
        std::cerr << "sweetspot render: " << e.what() << "\n";
        return 3;
      }
      std::cout << "sweetspot render: wrote " << o->output << " (" << c.name << ", hole " << h.number << ", par " << h.par
                << ", camera " << to_string(r.camera) << ")\n";
      return 0;
    }
    Scenario scenario;
    if (!o->scenario.empty()) {
      if (has_launch_numbers(o->launch))
        throw InputError("render: give a SCENARIO or the launch flags (--ball-speed, --launch-angle, --spin), not both");
      for (const CLI::Option* opt : launch_only)
        if (opt->count() > 0)
          throw InputError(opt->get_name() + ": a launch flag; the scenario " + o->scenario +
                           " sets its own (change it with --set, e.g. --set world.name=...)");
      refuse_output_over_input(o->output, resolve_scenario(assets, o->scenario), "-o");
      refuse_output_over_input(o->video, resolve_scenario(assets, o->scenario), "--video");
      scenario = load_scenario(assets, o->scenario, o->launch.sets);
    } else {
      scenario = launch_scenario(assets, o->launch, "render");
    }
    const ShotResult result = run_scenario(scenario);
    r = render_request_for(assets, scenario.resolved, result);
    r.camera = parse_camera_kind(o->camera);
    r.at_seconds = at;
    r.width = o->width;
    r.height = o->height;
    r.samples = o->samples;
    r.shadows = o->shadows == "on" ? 1 : o->shadows == "off" ? 0 : -1;
    const bool bat = scenario.resolved.sport->impactor == ImpactorKind::Bat;
    if (!r.impactor) {
      // Launch numbers only: draw the sport's impactor in an illustrative pose.
      const EquipmentCatalog& eq = assets.equipment();
      const std::string& name = scenario.resolved.sport->default_impactor;
      r.impactor_mesh = bat ? eq.bat_info_of(name).mesh : eq.club_info_of(name).mesh;
      r.impactor = nominal_impactor(bat, result.launch_state, scenario.resolved.ball.radius,
                                    bat ? eq.bat(name).length : 0.84);
    }
    if (!o->impactor.empty()) r.impactor_mesh = o->impactor == "none" ? "" : o->impactor;
    if (r.impactor_mesh.empty()) r.impactor.reset();
    // A clip too large to draw is refused before the image is written: nothing half done.
    if (!o->video.empty()) video_frame_times(result.trajectory, r, VideoRequest{o->fps, o->slow});
    try {
      // The image and the clip are replaced together, or neither is.
      OutputBatch outputs;
      if (!o->output.empty()) render_shot_png(result.trajectory, r, o->output);
      int frames = 0;
      if (!o->video.empty()) frames = render_shot_video(result.trajectory, r, VideoRequest{o->fps, o->slow}, o->video);
      outputs.commit();
      if (!o->video.empty())
        std::cout << "sweetspot render: wrote " << o->video << " (" << r.width << "x" << r.height << ", " << frames
                  << " frames at " << o->fps << " fps, camera " << to_string(r.camera) << ")\n";
    } catch (const RenderUnavailable& e) {
      std::cerr << "sweetspot render: " << e.what() << "\n"
                << "sweetspot render: rendering needs EGL with Mesa (libegl-mesa0, libgl1-mesa-dri) or a GPU driver\n";
      return 3;
    } catch (const RenderError& e) {
      std::cerr << "sweetspot render: " << e.what() << "\n";
      return 3;
    }
    if (!o->output.empty())
      std::cout << "sweetspot render: wrote " << o->output << " (" << r.width << "x" << r.height << ", camera "
                << to_string(r.camera) << ")\n";
    return 0;
  };
}

const CommandRegistrar render_command{40, "render", "render a shot to a PNG off-screen (EGL; llvmpipe without a GPU)", setup_render};

}  // namespace
}  // namespace sweetspot::cli
