// Off-screen rendering end to end on whatever EGL offers (llvmpipe on CI: no display, no
// GPU). The scene is the synthetic drive on tests/render/test_range.obj, so these images do
// not change when the flight model or the asset worlds change.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "game/content/world_asset.hpp"
#include "game/render/camera.hpp"
#include "game/render/image.hpp"
#include "game/render/offscreen_context.hpp"
#include "game/render/render_command.hpp"
#include "game/render/render_error.hpp"
#include "game/render/render_paths.hpp"
#include "game/render/renderer.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "game/render/synthetic_shot.hpp"
#include "game/render/trail_geometry.hpp"
#include "physics/error.hpp"
#include "physics/world.hpp"
#include "support/test_assets.hpp"

#include <map>
#include <memory>

using namespace sweetspot;

namespace {

const std::filesystem::path kSource = SWEETSPOT_SOURCE_DIR;

// The render tests' own worlds (tests/render, made by scripts/gen_meshes.py), so their
// images do not change when the shipped worlds do.
const WorldAsset& test_world(const char* file) {
  static std::map<std::string, std::unique_ptr<WorldAsset>> cache;
  auto& slot = cache[file];
  if (!slot) {
    slot = std::make_unique<WorldAsset>(load_world_asset(kSource / "tests/render", (kSource / "tests/render" / file).string(),
                                                         test::assets().materials()));
    if (std::string(file) == "test_park.obj") {
      // The park's fence, as gen_meshes.py builds it: 330 ft at the poles, 400 ft to centre.
      for (int i = 0; i <= 36; ++i) {
        const double deg = -45.0 + 90.0 * i / 36, t = std::abs(deg) / 45.0;
        const double r = (400.0 - 70.0 * t * t) * 0.3048;
        slot->fence_line.emplace_back(r * std::cos(deg_to_rad(deg)), 0.0, r * std::sin(deg_to_rad(deg)));
      }
      slot->fence_height = 3.05;
    }
  }
  return *slot;
}

RenderRequest range_request(int w, int h, CameraKind camera) {
  RenderRequest r;
  r.assets = &test::assets();
  r.distance_unit = "yd";
  r.world = &test_world("test_range.obj");
  r.width = w;
  r.height = h;
  r.camera = camera;
  r.samples = 4;  // exercise the multisampled FBO and its resolve (auto is 1 on llvmpipe)
  return r;
}

struct Rgb {
  int r, g, b;
};
Rgb pixel(const std::vector<std::uint8_t>& img, int w, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 4;
  return {img[i], img[i + 1], img[i + 2]};
}
int colour_distance(Rgb a, const Eigen::Vector3f& c) {
  return std::max({std::abs(a.r - int(std::lround(c.x() * 255))), std::abs(a.g - int(std::lround(c.y() * 255))),
                   std::abs(a.b - int(std::lround(c.z() * 255)))});
}

}  // namespace

TEST_CASE("off-screen render has the requested size, a sky above and grass below", "[render]") {
  const int w = 320, h = 180;
  const auto img = render_shot_rgba(synthetic_shot(), range_request(w, h, CameraKind::Behind));
  REQUIRE(img.size() == std::size_t(w) * h * 4);
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < img.size(); i += 4) colours.insert(img[i] << 16 | img[i + 1] << 8 | img[i + 2]);
  CHECK(colours.size() > 200);  // shaded terrain, sky gradient, trail, labels — not a blank clear
  for (int x : {5, w / 2, w - 5}) {
    const Rgb sky = pixel(img, w, x, 2);
    CHECK(sky.b > sky.r + 40);  // blue at the top
    const Rgb ground = pixel(img, w, x, h - 3);
    CHECK(ground.g > ground.r + 30);  // green grass at the bottom
    CHECK(ground.g > ground.b + 30);
  }
  for (std::size_t i = 3; i < img.size(); i += 4) REQUIRE(img[i] == 255);  // opaque
}

TEST_CASE("a projected trajectory point lands on the trail's phase colour", "[render]") {
  const int w = 640, h = 360;
  const ShotTrajectory shot = synthetic_shot();
  const auto img = render_shot_rgba(shot, range_request(w, h, CameraKind::Side));
  const double end = shot.samples.back().t;
  const Camera cam = frame_shot(CameraKind::Side, shot, end, w, h);
  // Flight at a quarter, half and three quarters of the arc; the first bounce's top.
  std::vector<std::pair<std::size_t, Phase>> probes = {{65, Phase::Flight}, {130, Phase::Flight}, {195, Phase::Flight}};
  for (std::size_t i = 0; i < shot.samples.size(); ++i) {
    if (shot.samples[i].phase == Phase::Bounce) {
      probes.emplace_back(i + 15, Phase::Bounce);  // middle of the first bounce arc
      break;
    }
  }
  for (const auto& [index, phase] : probes) {
    REQUIRE(shot.samples[index].phase == phase);
    const auto p = cam.project(shot.samples[index].position, w, h);
    REQUIRE(p);
    const int x = static_cast<int>(p->x()), y = static_cast<int>(p->y());
    REQUIRE(x >= 0);
    REQUIRE(x < w);
    REQUIRE(y >= 0);
    REQUIRE(y < h);
    INFO("sample " << index << " at pixel " << x << "," << y);
    CHECK(colour_distance(pixel(img, w, x, y), phase_color(phase)) <= 12);
    // 25 px straight above the flight points is sky, not trail.
    if (phase == Phase::Flight) CHECK(colour_distance(pixel(img, w, x, y - 25), phase_color(phase)) > 60);
  }
}

TEST_CASE("--at shows the trail only up to that time", "[render]") {
  const int w = 640, h = 360;
  const ShotTrajectory shot = synthetic_shot();
  RenderRequest r = range_request(w, h, CameraKind::Side);
  r.at_seconds = 2.0;  // about a third of the flight
  const auto img = render_shot_rgba(shot, r);
  const Camera cam = frame_shot(CameraKind::Side, shot, 2.0, w, h);
  const auto early = cam.project(shot.samples[40].position, w, h);   // t = 1.0 s
  const auto late = cam.project(shot.samples[200].position, w, h);   // t = 5.0 s
  REQUIRE(early);
  REQUIRE(late);
  CHECK(colour_distance(pixel(img, w, int(early->x()), int(early->y())), phase_color(Phase::Flight)) <= 12);
  CHECK(colour_distance(pixel(img, w, int(late->x()), int(late->y())), phase_color(Phase::Flight)) > 60);
  r.at_seconds = shot.samples.back().t + 1.0;
  CHECK_THROWS_AS(render_shot_rgba(shot, r), InputError);
}

// Golden images. Rasterisers differ slightly between Mesa versions and GPUs: an edge may move
// by a pixel, MSAA coverage and shading may round differently by a few counts. The metric
// absorbs exactly that and nothing more:
//  - a pixel "differs" when any channel is off by more than 32 (of 255); at most 2 % of the
//    pixels may differ (an edge moving by one pixel touches well under 1 % of this image);
//  - the mean colour of every 16x16 block must agree within 10 per channel, so a change in a
//    region (a missing trail or marker, wrong terrain colour, a moved camera) fails even if
//    it touches few pixels overall.
// SWEETSPOT_UPDATE_GOLDEN=1 rewrites the golden images instead (look at them before committing).
void check_golden(const std::vector<std::uint8_t>& img, int w, int h, const std::string& name) {
  const auto golden_path = kSource / "tests/render" / (name + ".png");
  const char* update = std::getenv("SWEETSPOT_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    write_png_atomic(golden_path, w, h, img);
    WARN("rewrote " << golden_path.string());
    return;
  }
  int gw = 0, gh = 0;
  const auto golden = read_png_rgba(golden_path, &gw, &gh);
  REQUIRE(gw == w);
  REQUIRE(gh == h);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < img.size(); i += 4) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(img[i + c]) - int(golden[i + c])));
    if (d > 32) ++differing;
  }
  const double fraction = double(differing) / (w * h);
  INFO("differing pixels: " << differing << " (" << 100 * fraction << " %)");
  double worst_block = 0;
  for (int by = 0; by + 16 <= h; by += 16) {
    for (int bx = 0; bx + 16 <= w; bx += 16) {
      for (int c = 0; c < 3; ++c) {
        double a = 0, b = 0;
        for (int y = by; y < by + 16; ++y) {
          for (int x = bx; x < bx + 16; ++x) {
            const std::size_t i = (std::size_t(y) * w + x) * 4 + c;
            a += img[i];
            b += golden[i];
          }
        }
        worst_block = std::max(worst_block, std::abs(a - b) / 256.0);
      }
    }
  }
  INFO("worst 16x16 block mean difference: " << worst_block);
  if (fraction > 0.02 || worst_block > 10.0) {
    const auto actual = std::filesystem::temp_directory_path() / ("sweetspot_" + name + "_actual.png");
    write_png_atomic(actual, w, h, img);
    WARN("actual image written to " << actual.string());
  }
  CHECK(fraction <= 0.02);
  CHECK(worst_block <= 10.0);
}

TEST_CASE("the side view matches the golden image within the rasteriser tolerance", "[render]") {
  const int w = 480, h = 272;
  RenderRequest r = range_request(w, h, CameraKind::Side);
  r.impactor_mesh = "driver_head";
  r.impactor = ImpactorPlacement{Vec3(-0.0214, 0.0214, 0.0), Quat::Identity()};
  check_golden(render_shot_rgba(synthetic_shot(), r), w, h, "golden_side");
}

// The people: a golfer 5 m off, 0.06 s into his follow-through with a delivered driver,
// shadows off (the image must not depend on the shadow map's filtering). The figure, the
// club in his hands and the ball leaving are all in it.
TEST_CASE("the golfer's follow-through matches its golden image within the rasteriser tolerance", "[render]") {
  const int w = 480, h = 272;
  OffscreenContext context;
  ShotSceneInput in;
  in.assets = &test::assets();
  in.world = &test_world("test_range.obj");
  in.tee = true;
  in.impactor_mesh = "driver_head";
  ShotScene scene(in);
  ImpactorPlacement club;
  club.position = Vec3(-0.0214, 0.0214, 0.0);
  club.orientation = Quat(Eigen::AngleAxisd(deg_to_rad(10.4), Vec3::UnitZ()));
  club.velocity = 50.5 * Vec3(std::cos(deg_to_rad(-1.3)), std::sin(deg_to_rad(-1.3)), 0.0);
  scene.set_shot(synthetic_shot(), club);
  Camera cam;
  cam.eye = Vec3(-1.5, 1.6, 4.5);
  cam.target = Vec3(0.3, 1.0, 0.0);
  cam.fov_y = deg_to_rad(50.0);
  RendererOptions options;
  options.shadows = 0;
  Renderer renderer(w, h, options);
  renderer.draw(scene.build(cam, 0.06, w, h), cam);
  check_golden(renderer.read_pixels(), w, h, "golden_golfer");
}

TEST_CASE("every camera frames the shot: the launch and rest points are in the image", "[render]") {
  const int w = 320, h = 180;
  const ShotTrajectory shot = synthetic_shot();
  for (CameraKind k : {CameraKind::Behind, CameraKind::Side, CameraKind::Top, CameraKind::Follow}) {
    INFO(to_string(k));
    const auto img = render_shot_rgba(shot, range_request(w, h, k));
    REQUIRE(img.size() == std::size_t(w) * h * 4);
    if (k == CameraKind::Follow) continue;  // follows the ball, not the whole shot
    const Camera cam = frame_shot(k, shot, shot.samples.back().t, w, h);
    for (const Vec3& p : {shot.samples.front().position, shot.summary.rest_position}) {
      const auto q = cam.project(p, w, h);
      REQUIRE(q);
      CHECK(q->x() > 0);
      CHECK(q->x() < w);
      CHECK(q->y() > 0);
      CHECK(q->y() < h);
    }
  }
}

TEST_CASE("a ballpark shows the fence distances where the foul lines and gaps meet the wall", "[render]") {
  // A baseball drive to centre-right; the fence labels are drawn in their own yellow.
  ShotTrajectory shot = synthetic_shot({110.0, 30.0, 10.0, 0.0369, 0.0});
  for (auto& s : shot.samples) s.position.y() += 0.9;  // contact above the plate
  RenderRequest r = range_request(640, 360, CameraKind::Top);
  r.distance_unit = "ft";
  r.world = &test_world("test_park.obj");
  r.ball_radius = 0.0369;
  auto count_fence_yellow = [](const std::vector<std::uint8_t>& img) {
    std::size_t n = 0;
    // (255, 235, 77); the flight trail (255, 219, 26) is told apart by its green and blue.
    for (std::size_t i = 0; i < img.size(); i += 4)
      n += img[i] > 240 && img[i + 1] > 228 && img[i + 1] < 242 && img[i + 2] > 60 && img[i + 2] < 95;
    return n;
  };
  const auto park = render_shot_rgba(shot, r);
  // Five labels ("330 ft" x2, "382 ft" x2, "400 ft"), 8 px tall at this size: each has
  // ~60 lit font cells of about one pixel, some softened by MSAA; 163 counted when written.
  CHECK(count_fence_yellow(park) > 5 * 20);
  r.distance_unit = "yd";  // the same world as a golf hole: 50 yd lines instead, no fence labels
  CHECK(count_fence_yellow(render_shot_rgba(shot, r)) < 20);
}

TEST_CASE("a fly caught at the wall is labelled beside the fence's sign, never in its place", "[render]") {
  // A ball to dead centre landing a metre short of the 400 ft wall, seen from behind the
  // plate: the sign's "400 ft" and the carry's label both stand, apart (the carry took the
  // sign's place, and the sign then read as the carry).
  OffscreenContext context;
  ShotSceneInput in;
  in.assets = &test::assets();
  in.world = &test_world("test_park.obj");
  in.distance_unit = "ft";
  ShotScene scene(in);
  SyntheticShotSpec spec;
  spec.carry = 400.0 * 0.3048 - 1.0;
  spec.apex = 30.0;
  spec.lateral = 0.0;
  spec.ball_radius = 0.0369;
  ShotTrajectory shot = synthetic_shot(spec);
  for (auto& p : shot.samples) p.position.y() += 0.9;  // contact above the plate
  shot.summary.landing_position.y() += 0.9;
  scene.set_shot(shot, std::nullopt);
  const int w = 640, h = 360;
  const double land = shot.summary.hang_time_s;
  const Camera cam = scene.camera(CameraKind::Behind, land, w, h);
  const Scene view = scene.build(cam, land, w, h);
  // The legend, the five fence signs and the carry: every one placed, none over another.
  REQUIRE(view.label_boxes.size() == 7);
  for (std::size_t i = 0; i < view.label_boxes.size(); ++i)
    for (std::size_t j = i + 1; j < view.label_boxes.size(); ++j) {
      const Eigen::Vector4f& a = view.label_boxes[i];
      const Eigen::Vector4f& b = view.label_boxes[j];
      CHECK_FALSE((a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]));
    }
  // The cage leaves a ground ball's first-hop carry unlabelled: the rest is the same.
  scene.set_carry_label(false);
  CHECK(scene.build(cam, land, w, h).label_boxes.size() == 6);
}

TEST_CASE("a distance stripe at the flag gives up its number: a '50' under a 53 yd pin reads as the pin's", "[render]") {
  OffscreenContext context;
  const double yd = 0.9144;
  const auto boxes_with_flag_at = [&](double flag_yd, bool numbers = true) {
    ShotSceneInput in;
    in.assets = &test::assets();
    in.world = &test_world("test_range.obj");
    in.flag = Vec3(flag_yd * yd, 0.0, 0.0);
    ShotScene scene(in);
    scene.set_stripe_numbers(numbers);
    SyntheticShotSpec spec;
    spec.carry = 20.0;
    spec.apex = 6.0;
    spec.lateral = 0.0;
    scene.set_shot(synthetic_shot(spec), std::nullopt);
    const int w = 640, h = 360;
    const Camera cam = scene.camera(CameraKind::Behind, 0.0, w, h);
    const std::vector<Eigen::Vector4f> boxes = scene.build(cam, 0.0, w, h).label_boxes;
    // The image's label boxes are its labels: the room it keeps for the game's flag is not
    // one (the game's flagstick keeps clear of them, draw_cup_and_flag, and left a gap where
    // it stands).
    const auto base = cam.project(*in.flag, w, h);
    REQUIRE(base);
    const float x = static_cast<float>(base->x()), y = static_cast<float>(base->y()) - 10.0f;  // on the pole
    for (const Eigen::Vector4f& b : boxes) CHECK_FALSE((x > b[0] && x < b[2] && y > b[1] && y < b[3]));
    return boxes.size();
  };
  // Both pins leave one stripe (50 yd) to draw; 20 yd clear of the flag it keeps its number.
  CHECK(boxes_with_flag_at(53.0) + 1 == boxes_with_flag_at(70.0));
  // A range, whose flags say their distances, turns the numbers off: none is written.
  CHECK(boxes_with_flag_at(70.0, false) == boxes_with_flag_at(53.0));
}

TEST_CASE("a ball that stops within its carry's last figure is labelled once, at the landing ring", "[render]") {
  OffscreenContext context;
  const auto boxes_with_rest_past_landing = [&](double past_m) {
    ShotSceneInput in;
    in.assets = &test::assets();
    in.world = &test_world("test_range.obj");
    ShotScene scene(in);
    SyntheticShotSpec spec;
    spec.carry = 100.2;
    spec.apex = 25.0;
    spec.lateral = 0.0;
    ShotTrajectory shot = synthetic_shot(spec);
    // The ball runs out `past_m` beyond where it landed, and stops there.
    auto& s = shot.summary;
    s.rest_position = s.landing_position + Vec3(past_m, 0.0, 0.0);
    s.total_m = std::hypot(s.rest_position.x(), s.rest_position.z());
    shot.samples.back().position = s.rest_position;
    const int w = 640, h = 360;
    const double end = shot.samples.back().t;
    scene.set_shot(shot, std::nullopt);
    const Camera cam = scene.camera(CameraKind::Behind, end, w, h);
    return scene.build(cam, end, w, h).label_boxes.size();
  };
  // 100.2 m carried, 100.8 m at rest: both read "110 yd"; the rest pin stands without a
  // second "110 yd" beside the first. Ten metres on, the rest has its own figure (both clear of the
  // stripes, whose numbers give way beside a shot's label).
  CHECK(boxes_with_rest_past_landing(0.6) + 1 == boxes_with_rest_past_landing(10.0));
}

TEST_CASE("a missing or broken shader names the file and the compiler log", "[render]") {
  OffscreenContext context;
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_render_shader_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  RendererOptions options;
  options.shader_dir = dir;
  try {
    Renderer r(64, 64, options);
    FAIL("no error for a missing shader");
  } catch (const RenderError& e) {
    CHECK_THAT(e.what(), Catch::Contains((dir / "lit.vert").string()));
  }
  for (const char* f : {"lit.vert", "lit.frag", "flat.vert", "flat.frag", "sky.vert", "sky.frag", "depth.vert", "depth.frag"}) {
    std::filesystem::copy_file(shader_dir() / f, dir / f);
  }
  {
    std::ofstream broken(dir / "flat.frag", std::ios::trunc);
    broken << "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(undeclared_thing, 1.0); }\n";
  }
  try {
    Renderer r(64, 64, options);
    FAIL("no error for a broken shader");
  } catch (const RenderError& e) {
    CHECK_THAT(e.what(), Catch::Contains((dir / "flat.frag").string()));
    CHECK_THAT(e.what(), Catch::Contains("undeclared_thing"));  // the compiler's log
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("auto sample count: 4 on a GPU, 1 on a software rasteriser; explicit counts are kept", "[render]") {
  OffscreenContext context;
  Renderer automatic(64, 64);
  CHECK(automatic.samples() == (automatic.software() ? 1 : 4));
  RendererOptions four;
  four.samples = 4;
  CHECK(Renderer(64, 64, four).samples() == 4);
  // The same shot with and without multisampling differs only along edges.
  const ShotTrajectory shot = synthetic_shot();
  RenderRequest a = range_request(320, 180, CameraKind::Side), b = a;
  b.samples = 1;
  const auto img_a = render_shot_rgba(shot, a), img_b = render_shot_rgba(shot, b);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < img_a.size(); i += 4) differing += img_a[i] != img_b[i] || img_a[i + 1] != img_b[i + 1];
  CHECK(differing > 0);                    // the resolve did something
  CHECK(differing < img_a.size() / 4 / 5);  // ...but only at edges (< 20 % of pixels)
}

TEST_CASE("bad render requests are input errors naming the value", "[render]") {
  const ShotTrajectory shot = synthetic_shot();
  RenderRequest r = range_request(8, 8, CameraKind::Side);
  CHECK_THROWS_WITH(render_shot_rgba(shot, r), Catch::Contains("8x8"));
  r = range_request(64, 64, CameraKind::Side);
  r.distance_unit = "furlong";
  CHECK_THROWS_WITH(render_shot_rgba(shot, r), Catch::Contains("furlong"));
  r = range_request(64, 64, CameraKind::Side);
  r.impactor_mesh = "spoon_head";
  CHECK_THROWS_WITH(render_shot_rgba(shot, r), Catch::Contains("spoon_head"));
}

TEST_CASE("an invalid EGL platform override is an input error, not a crash", "[render]") {
  ::setenv("SWEETSPOT_EGL_PLATFORM", "vulkan", 1);
  CHECK_THROWS_WITH(OffscreenContext(), Catch::Contains("SWEETSPOT_EGL_PLATFORM") && Catch::Contains("surfaceless"));
  ::unsetenv("SWEETSPOT_EGL_PLATFORM");
  // Forcing the device platform either finds a hardware GPU or says why not.
  try {
    OffscreenContext c(EglPlatform::Device);
    CHECK(c.platform() == EglPlatform::Device);
  } catch (const RenderUnavailable& e) {
    CHECK_THAT(e.what(), Catch::Contains("device"));
  }
}

// Run by the ctest `render_no_egl` with __EGL_VENDOR_LIBRARY_FILENAMES pointing nowhere, so
// GLVND's libEGL has no vendor at all: the machine "has no EGL".
TEST_CASE("without an EGL vendor the context fails with a clear RenderUnavailable", "[.][no_egl]") {
  try {
    OffscreenContext c;
    FAIL("an EGL context was created although no EGL vendor is installed: " << c.description());
  } catch (const RenderUnavailable& e) {
    CHECK_THAT(e.what(), Catch::Contains("cannot create an off-screen OpenGL context"));
  }
  CHECK_THROWS_AS(render_shot_rgba(synthetic_shot(), range_request(64, 64, CameraKind::Side)), RenderUnavailable);
}

TEST_CASE("no camera looks from under the ground: framings and a mouse orbit are lifted above it", "[render]") {
  OffscreenContext context;
  ShotSceneInput input;
  input.assets = &test::assets();
  input.world = &test_world("test_range.obj");
  ShotScene scene(input);
  const ShotTrajectory shot = synthetic_shot();
  scene.set_shot(shot, std::nullopt);
  for (CameraKind k : {CameraKind::Behind, CameraKind::Side, CameraKind::Top, CameraKind::Follow}) {
    for (double t : {0.0, 2.0, shot.samples.back().t}) {
      INFO(to_string(k) << " t=" << t);
      const Camera c = scene.camera(k, t, 640, 360);
      const double ground = scene.ground_height(c.eye.x(), c.eye.z()).value_or(-1e9);
      CHECK(c.eye.y() >= ground + 0.3 - 1e-9);
    }
  }
  // A camera dragged 5 m under the turf (where a 40 px mouse drag can put it) comes back up
  // to 1 m above it, still looking at its target.
  Camera under = scene.camera(CameraKind::Behind, 0.0, 640, 360);
  const Vec3 target = under.target;
  under.eye.y() = scene.ground_height(under.eye.x(), under.eye.z()).value() - 5.0;
  const Camera lifted = scene.keep_above_ground(under);
  CHECK(lifted.eye.y() == Approx(scene.ground_height(lifted.eye.x(), lifted.eye.z()).value() + 1.0));
  CHECK(lifted.target == target);
}

TEST_CASE("sun shadows: the flag and the club shade the turf and nothing gets brighter", "[render]") {
  // Close behind the ball at impact (follow at t = 0), the driver head and shaft at address.
  const int w = 960, h = 540;
  RenderRequest r = range_request(w, h, CameraKind::Follow);
  r.samples = 1;
  r.impactor_mesh = "driver_head";
  r.impactor = ImpactorPlacement{Vec3(-0.0214, 0.0214, 0.0), Quat::Identity()};
  r.at_seconds = 0.0;
  r.flag = Vec3(5.0, 0.0, 1.0);  // a flagstick just ahead: its cloth and pole cast a clear shadow
  r.shadows = 0;
  const auto off = render_shot_rgba(synthetic_shot(), r);
  r.shadows = 1;
  const auto on = render_shot_rgba(synthetic_shot(), r);
  std::size_t darker = 0, brighter = 0;
  for (std::size_t i = 0; i < on.size(); i += 4) {
    int sum_on = 0, sum_off = 0, up = 0;
    for (int c = 0; c < 3; ++c) {
      sum_on += on[i + c];
      sum_off += off[i + c];
      up = std::max(up, int(on[i + c]) - int(off[i + c]));
    }
    if (sum_on < 0.8 * sum_off) ++darker;
    if (up > 8) ++brighter;
  }
  INFO("darker " << darker << ", brighter " << brighter);
  // The flag's, the head's and the shaft's shadows on the turf: ~260 px at this size (the
  // low camera foreshortens them); half of that is a clear margin over zero.
  CHECK(darker > 120);
  CHECK(brighter == 0);    // a shadow only ever takes light away
  // Forced off, the image is the auto image on a software rasteriser (auto = off there).
  r.shadows = -1;
  OffscreenContext probe;
  Renderer auto_renderer(64, 64);
  if (auto_renderer.software()) CHECK(render_shot_rgba(synthetic_shot(), r) == off);
}

namespace {
// A tree's face as a wall from `from` to `to` at ground level, `tall` m high, both faces
// solid: a trunk round a golfer, or the side of a crown across a ball's flight.
struct TreeWall {
  Vec3 from, to;
  double tall = 6.0;
};
// Flat turf from x = -50 m to `reach` (and 50 m either side) with those walls on it.
WorldDescription turf_and_tree_walls(double reach, const std::vector<TreeWall>& walls) {
  WorldDescription d;
  d.name = "trees";
  SurfaceMaterial tree = default_fairway();
  tree.name = "tree";
  tree.kind = SurfaceKind::Tree;
  d.materials = {default_fairway(), tree};
  WorldMesh turf;
  turf.material = 0;
  turf.vertices = {Vec3(-50, 0, -50), Vec3(reach, 0, -50), Vec3(reach, 0, 50), Vec3(-50, 0, 50)};
  turf.indices = {0, 2, 1, 0, 3, 2};
  d.meshes = {turf};
  for (const TreeWall& w : walls) {
    WorldMesh face;
    face.material = 1;
    const Vec3 up(0, w.tall, 0);
    face.vertices = {w.from, w.to, w.to + up, w.from + up};
    face.indices = {0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2};
    d.meshes.push_back(face);
  }
  d.bounds_min = Vec3(-50, -5, -50);
  d.bounds_max = Vec3(reach, 100, 50);
  return d;
}
// The same as a golf world asset a scene can draw.
std::unique_ptr<WorldAsset> tree_walls_asset(const std::vector<TreeWall>& walls) {
  auto a = std::make_unique<WorldAsset>();
  a->name = "trees";
  a->sport = "golf";
  a->world = std::make_unique<World>(turf_and_tree_walls(300.0, walls));
  return a;
}
}  // namespace

TEST_CASE("the address camera comes out in front of a tree, goes round it, or over the golfer when hemmed in", "[render][camera]") {
  // Flat turf and trees' trunks: walls 6 m tall (both faces), each from `from` to `to` at
  // ground level, round a golfer addressing a ball at the origin toward +x, the camera 9 m
  // behind him.
  const auto world_with = [](const std::vector<TreeWall>& walls) { return turf_and_tree_walls(50.0, walls); };
  const Vec3 ball(0.0, 0.021, 0.0), head = ball + Vec3(0.0, 1.7, 0.0);
  const Camera behind = full_shot_address_camera(ball, Vec3::UnitX());
  // Within the image (vertically, and across at the window's 16:10): the angle off the view's
  // axis in each direction.
  const auto in_view = [](const Camera& c, const Vec3& p) {
    const Vec3 d = p - c.eye;
    const double ahead = d.dot(c.forward());
    if (ahead <= 0.0) return false;
    const double half_v = std::tan(0.5 * c.fov_y), half_h = 1.6 * half_v;
    return std::abs(d.dot(c.true_up()) / ahead) < half_v && std::abs(d.dot(c.right()) / ahead) < half_h;
  };
  const auto clear = [&](const World& w, const Camera& c) {
    SurfaceContact hit;
    return !w.sweep(head, c.eye, 0.1, &hit, nullptr);
  };
  SECTION("nothing in the way: unchanged") {
    const World open(world_with({TreeWall{Vec3(-30, 0, -2), Vec3(-30, 0, 2)}}));
    const Camera c = clear_view_of(behind, ball, open);
    CHECK((c.eye - behind.eye).norm() < 1e-12);
    CHECK((c.target - behind.target).norm() < 1e-12);
  }
  SECTION("a trunk 6 m back: in front of it, still looking down his line") {
    const World w(world_with({TreeWall{Vec3(-6, 0, -2), Vec3(-6, 0, 2)}}));
    const Camera c = clear_view_of(behind, ball, w);
    CHECK(clear(w, c));
    CHECK(c.eye.x() > -6.0);
    CHECK(c.eye.x() < -3.0);
    // Down the same line (the target area where it was), the lens widened to keep the ball.
    CHECK(((c.target - c.eye).normalized() - (behind.target - behind.eye).normalized()).norm() < 1e-9);
    CHECK(c.fov_y > behind.fov_y);
    CHECK(c.fov_y < deg_to_rad(75.0));
    CHECK(in_view(c, ball));
    CHECK(in_view(c, head));
  }
  SECTION("a trunk 2 m back: swung round him as little as clears it, then turned back toward his line") {
    const World w(world_with({TreeWall{Vec3(-2, 0, -2), Vec3(-2, 0, 2)}}));
    const Camera c = clear_view_of(behind, ball, w);
    CHECK(clear(w, c));
    CHECK((c.eye - head).norm() >= 3.0);
    CHECK(c.eye.y() == Approx(behind.eye.y()).epsilon(0.2));
    // Every smaller swing meets the trunk within 3 m (its edge 2.5 m off the line with the
    // sweep's margin); 60° passes it at 3.5 m.
    const double swing = std::atan2(std::abs(c.eye.z()), -c.eye.x());
    CHECK(rad_to_deg(swing) == Approx(60.0).margin(1e-6));
    // The golfer, the ball and where he aims (150 m down the line) all in the picture, the
    // view turned from the swung eye's 60° off the line to under 45°, the lens at most 75°.
    for (const Vec3& p : {ball, head, Vec3(ball + 150.0 * Vec3::UnitX())}) CHECK(in_view(c, p));
    const double off_line = std::atan2(std::abs(c.forward().z()), c.forward().x());
    CHECK(rad_to_deg(off_line) < 45.0);
    CHECK(c.fov_y <= deg_to_rad(75.0) + 1e-9);
  }
  SECTION("trees 6 m round him, open ahead: in front of the trees behind, down his line") {
    const World w(world_with({TreeWall{Vec3(-6, 0, -6), Vec3(-6, 0, 6)}, TreeWall{Vec3(-6, 0, 6), Vec3(6, 0, 6)},
                              TreeWall{Vec3(-6, 0, -6), Vec3(6, 0, -6)}}));
    const Camera c = clear_view_of(behind, ball, w);
    CHECK(clear(w, c));
    CHECK((c.eye - head).norm() >= 3.0);
    CHECK((c.eye - head).norm() < (behind.eye - head).norm());
    CHECK(((c.target - c.eye).normalized() - (behind.target - behind.eye).normalized()).norm() < 1e-9);
    CHECK(in_view(c, ball));
    CHECK(in_view(c, head));
  }
  SECTION("hemmed in 2 m round: over his head, looking down past him at the ball") {
    const World w(world_with({TreeWall{Vec3(-2, 0, -2), Vec3(-2, 0, 2)}, TreeWall{Vec3(-2, 0, 2), Vec3(2, 0, 2)},
                              TreeWall{Vec3(-2, 0, -2), Vec3(2, 0, -2)}}));
    const Camera c = clear_view_of(behind, ball, w);
    CHECK(c.eye.x() > -2.0);
    CHECK(c.eye.y() > head.y() + 2.0);
    CHECK(in_view(c, ball));
    CHECK(in_view(c, head));
    CHECK(c.forward().x() > 0.0);  // still facing down the line
  }
}

TEST_CASE("the follow camera looks over a tree between it and the ball, or stands in front of it, never in its crown",
          "[render][camera]") {
  // Flat turf and, when asked, a crown's face: a wall 60 m wide (and 60 m tall unless told)
  // across the flight half way between the ball and where the chase camera would stand.
  const auto world_with_wall = [](std::optional<double> wall_x, double tall = 60.0) {
    std::vector<TreeWall> walls;
    if (wall_x) walls.push_back(TreeWall{Vec3(*wall_x, 0, -30), Vec3(*wall_x, 0, 30), tall});
    return tree_walls_asset(walls);
  };
  OffscreenContext context;
  SyntheticShotSpec spec;
  spec.lateral = 0.0;
  const ShotTrajectory shot = synthetic_shot(spec);
  const double t = 0.6;  // s: climbing, ~20 m out
  const auto follow = [&](const WorldAsset& world) {
    ShotSceneInput input;
    input.assets = &test::assets();
    input.world = &world;
    ShotScene scene(input);
    scene.set_shot(shot, std::nullopt);
    return scene.camera(CameraKind::Follow, t, 640, 400);
  };
  const auto open = world_with_wall(std::nullopt);
  const Camera free = follow(*open);
  const Vec3 ball = sample_at(shot, t).position;
  REQUIRE(free.eye.x() < ball.x() - 2.0);  // the chase view stands behind the ball
  SECTION("a crown between them: the eye clear of it, looking at the same place") {
    const double wall = 0.5 * (free.eye.x() + ball.x());
    const auto canopy = world_with_wall(wall);
    const Camera c = follow(*canopy);
    CHECK(c.eye.x() > wall + 0.3);
    CHECK(c.eye.x() < ball.x());
    SurfaceContact hit;
    CHECK_FALSE(canopy->world->sweep(ball, c.eye, 0.1, &hit, nullptr));
    CHECK((c.target - free.target).norm() < 1e-9);
  }
  SECTION("a low crown near the camera: it rises over it, as far from the ball, behind the crown") {
    // Four fifths of the way back to the eye, and 1.6 m over the ball: above the chase view's
    // sight line there, below a line the eye at its distance can see over.
    const double wall = ball.x() - 0.8 * (ball.x() - free.eye.x());
    const double top = ball.y() + 1.6;
    const auto canopy = world_with_wall(wall, top);
    SurfaceContact hit;
    REQUIRE(canopy->world->sweep(ball, free.eye, 0.1, &hit, nullptr));  // the chase view is blocked
    const Camera c = follow(*canopy);
    CHECK(c.eye.y() > top);
    CHECK(c.eye.x() < wall);  // still on the far side of the crown, not in front of it
    CHECK((c.eye - ball).norm() == Approx((free.eye - ball).norm()).epsilon(1e-9));
    CHECK_FALSE(canopy->world->sweep(ball, c.eye, 0.1, &hit, nullptr));
    CHECK((c.target - free.target).norm() < 1e-9);
  }
  SECTION("the crown behind the camera: unchanged") {
    const auto canopy = world_with_wall(free.eye.x() - 3.0);
    const Camera c = follow(*canopy);
    CHECK((c.eye - free.eye).norm() < 1e-12);
  }
}

TEST_CASE("the side view looks down over a row of trees between it and the flight", "[render][camera]") {
  // A drive down +x; a row of crowns 15 m tall along the right of the line, 25 m off it,
  // between the flight and the side view (which stands to the right).
  const auto world = [](bool row) {
    std::vector<TreeWall> walls;
    if (row) walls.push_back(TreeWall{Vec3(-40, 0, 25), Vec3(290, 0, 25), 15.0});
    return tree_walls_asset(walls);
  };
  OffscreenContext context;
  SyntheticShotSpec spec;
  spec.lateral = 0.0;
  const ShotTrajectory shot = synthetic_shot(spec);
  const auto side = [&](const WorldAsset& w) {
    ShotSceneInput input;
    input.assets = &test::assets();
    input.world = &w;
    ShotScene scene(input);
    scene.set_shot(shot, std::nullopt);
    return scene.camera(CameraKind::Side, 1.0, 640, 400);
  };
  const auto down = [](const Camera& c) { return std::asin(std::clamp(-c.forward().y(), -1.0, 1.0)); };
  const auto open = world(false), trees = world(true);
  const Camera free = side(*open), over = side(*trees);
  CHECK(rad_to_deg(down(free)) == Approx(10.0).margin(0.5));  // the usual side view
  CHECK(rad_to_deg(down(over)) > 15.0);
  // From there most of the flight is in sight past the row.
  int hidden = 0;
  const auto& s = shot.samples;
  for (int i = 0; i < 20; ++i) {
    SurfaceContact hit;
    if (trees->world->sweep(over.eye, s[(s.size() - 1) * static_cast<std::size_t>(i) / 19].position, 0.05, &hit, nullptr) &&
        trees->world->material(hit.material).kind == SurfaceKind::Tree)
      ++hidden;
  }
  CHECK(hidden <= 2);
}

TEST_CASE("at address the golfer winds his club back up its arc as the meter climbs, and back down", "[render][golfer]") {
  OffscreenContext context;
  ShotSceneInput input;
  input.assets = &test::assets();
  input.world = &test_world("test_range.obj");
  input.impactor_mesh = "driver_head";
  ShotScene scene(input);
  const double r = input.ball_radius;
  const Vec3 ball(0.0, scene.ground_height(0.0, 0.0).value_or(0.0) + r, 0.0);
  scene.set_shot(ball_at_rest(ball), std::nullopt);
  const ImpactorPlacement address = club_at_address(ball, Vec3::UnitX(), r);
  scene.set_address(address);
  const Camera cam = scene.camera(CameraKind::Behind, 0.0, 640, 360);
  // The club head is the mesh drawn just before the ball (the last one).
  const auto head_at = [&](double fraction) {
    scene.set_backswing(fraction);
    const Scene s = scene.build(cam, 0.0, 640, 360);
    REQUIRE(s.meshes.size() >= 2);
    const Eigen::Vector3f p = s.meshes[s.meshes.size() - 2].model.block<3, 1>(0, 3);
    return Vec3(p.cast<double>());
  };
  const Vec3 at_ball = head_at(0.0), half = head_at(0.5), top = head_at(1.0);
  CHECK((at_ball - address.position).norm() < 1e-6);  // no backswing: the club at address
  // Half way round the arc the head has gone back (away from the target, -x) and up; at the
  // top, past vertical, it is over the golfer's shoulders pointing at the target (+x), as a
  // full swing's club lies at the top, well over a metre above the ball.
  INFO("ball " << ball.transpose() << " half " << half.transpose() << " top " << top.transpose());
  CHECK(half.x() < at_ball.x() - 0.3);
  CHECK(half.y() > at_ball.y() + 1.0);
  CHECK(top.x() > half.x() + 1.0);
  CHECK(top.y() > ball.y() + 1.2);
  // Coming down, the marker's fall takes it back the same way: at 0 it is at the ball again.
  CHECK((head_at(0.5) - half).norm() < 1e-9);
  CHECK((head_at(0.0) - at_ball).norm() < 1e-9);
}
