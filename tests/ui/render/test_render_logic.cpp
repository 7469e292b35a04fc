// Rendering logic that needs no GL: camera framing, trail colouring, row flipping, labels.
#include <algorithm>
#include <filesystem>
#include <set>

#include <catch2/catch.hpp>

#include "game/render/camera.hpp"
#include "game/render/image.hpp"
#include "game/render/mesh_import.hpp"
#include "game/render/overlay_geometry.hpp"
#include "game/render/synthetic_shot.hpp"
#include "game/render/trail_geometry.hpp"
#include "physics/error.hpp"

using namespace sweetspot;

namespace {
// The pixel box the points project into; every point must be in front of the camera.
struct PixelBox {
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
};
template <class Points, class Position>
PixelBox projected_box(const Camera& c, const Points& points, Position position, int w, int h) {
  PixelBox b;
  for (const auto& p : points) {
    const auto q = c.project(position(p), w, h);
    REQUIRE(q);
    b.xmin = std::min(b.xmin, q->x());
    b.xmax = std::max(b.xmax, q->x());
    b.ymin = std::min(b.ymin, q->y());
    b.ymax = std::max(b.ymax, q->y());
  }
  return b;
}
}  // namespace

TEST_CASE("camera names parse and bad ones list the allowed names", "[render][unit]") {
  CHECK(parse_camera_kind("behind") == CameraKind::Behind);
  CHECK(parse_camera_kind("side") == CameraKind::Side);
  CHECK(parse_camera_kind("top") == CameraKind::Top);
  CHECK(parse_camera_kind("follow") == CameraKind::Follow);
  CHECK_THROWS_WITH(parse_camera_kind("drone"), Catch::Contains("behind, side, top, follow"));
  for (auto k : {CameraKind::Behind, CameraKind::Side, CameraKind::Top, CameraKind::Follow}) {
    CHECK(parse_camera_kind(to_string(k)) == k);
  }
}

TEST_CASE("projection: the target is the image centre, points behind the camera are not projected", "[render][unit]") {
  Camera c;
  c.eye = Vec3(-10, 2, 0);
  c.target = Vec3(40, 2, 0);
  const auto centre = c.project(c.target, 800, 600);
  REQUIRE(centre);
  CHECK(centre->x() == Approx(400).margin(1e-9));
  CHECK(centre->y() == Approx(300).margin(1e-9));
  CHECK_FALSE(c.project(Vec3(-20, 2, 0), 800, 600));
  // +z (right of the target line) is to the right in the image, +y up is up.
  CHECK(c.project(Vec3(40, 2, 5), 800, 600)->x() > 400);
  CHECK(c.project(Vec3(40, 7, 0), 800, 600)->y() < 300);
  // One pixel at distance d subtends 2 d tan(fov/2) / height.
  CHECK(c.metres_per_pixel(Vec3(90, 2, 0), 600) == Approx(2 * 100 * std::tan(c.fov_y / 2) / 600));
}

TEST_CASE("default cameras frame the whole shot inside the image", "[render][unit]") {
  const ShotTrajectory shot = synthetic_shot();
  const int w = 1280, h = 720;
  for (auto k : {CameraKind::Behind, CameraKind::Side, CameraKind::Top}) {
    INFO(to_string(k));
    const Camera c = frame_shot(k, shot, shot.samples.back().t, w, h);
    const auto [xmin, xmax, ymin, ymax] = projected_box(c, shot.samples, [](const TrajectorySample& s) { return s.position; }, w, h);
    // Inside with a margin, and not lost in a corner: the shot spans a good part of the image.
    CHECK(xmin > 0.03 * w);
    CHECK(xmax < 0.97 * w);
    CHECK(ymin > 0.03 * h);
    CHECK(ymax < 0.97 * h);
    CHECK(std::max((xmax - xmin) / w, (ymax - ymin) / h) > 0.5);
  }
  // Side: downrange runs left to right.
  const Camera side = frame_shot(CameraKind::Side, shot, 0.0, w, h);
  CHECK(side.project(Vec3(200, 0, 0), w, h)->x() > side.project(Vec3(0, 0, 0), w, h)->x() + 300);
  // Top: the shot's long axis along the image's long axis. A drive (long, narrow) in a
  // landscape image runs left to right, the right of the target line down the image (a map
  // turned so the tee is on the left); in a portrait image it runs up, right is right.
  const Camera top = frame_shot(CameraKind::Top, shot, 0.0, w, h);
  CHECK(top.project(Vec3(200, 0, 0), w, h)->x() > top.project(Vec3(0, 0, 0), w, h)->x() + 600);
  CHECK(top.project(Vec3(100, 0, 20), w, h)->y() > top.project(Vec3(100, 0, -20), w, h)->y());
  const Camera tall = frame_shot(CameraKind::Top, shot, 0.0, h, w);
  CHECK(tall.project(Vec3(200, 0, 0), h, w)->y() < tall.project(Vec3(0, 0, 0), h, w)->y() - 600);
  CHECK(tall.project(Vec3(100, 0, 20), h, w)->x() > tall.project(Vec3(100, 0, -20), h, w)->x());
  // The drive fills the landscape image along its length (not a thin strip up the middle,
  // 60 % of the frame empty).
  {
    double lo = 1e9, hi = -1e9;
    for (const auto& s : shot.samples) {
      const double x = top.project(s.position, w, h)->x();
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    CHECK(hi - lo > 0.8 * w);
  }
  // Behind: the launch point is low in the image, the apex above it.
  const Camera behind = frame_shot(CameraKind::Behind, shot, 0.0, w, h);
  CHECK(behind.project(shot.samples.front().position, w, h)->y() > 0.6 * h);
  // Follow: the ball at time t is near the image centre.
  const double t = 3.0;
  const Camera follow = frame_shot(CameraKind::Follow, shot, t, w, h);
  const auto ball = follow.project(sample_at(shot, t).position, w, h);
  REQUIRE(ball);
  CHECK(std::abs(ball->x() - w / 2.0) < 0.1 * w);
  CHECK(std::abs(ball->y() - h / 2.0) < 0.25 * h);
}

// A view that draws a panel over the top of its image (the batting cage's HUD and its call)
// frames the shot below it: Behind keeps every point inside the window, still filling it;
// the whole image as the window is the default framing exactly.
TEST_CASE("the behind camera frames the shot inside a window of the image", "[render][unit]") {
  const ShotTrajectory shot = synthetic_shot();
  const int w = 1280, h = 800;
  const ShotFraming f = shot_framing(shot, shot.samples.back().t);
  const Camera whole = frame_shot(CameraKind::Behind, f, w, h);
  const Camera same = frame_shot(CameraKind::Behind, f, w, h, FrameWindow{});
  CHECK(same.eye == whole.eye);
  CHECK(same.target == whole.target);
  CHECK(same.fov_y == whole.fov_y);
  for (const FrameWindow win : {FrameWindow{0.0, 0.38, 1.0, 1.0}, FrameWindow{0.36, 0.0, 1.0, 1.0},
                                FrameWindow{0.0, 0.0, 1.0, 0.6}, FrameWindow{0.1, 0.2, 0.7, 0.9}}) {
    INFO("window " << win.left << " " << win.top << " " << win.right << " " << win.bottom);
    const Camera c = frame_shot(CameraKind::Behind, f, w, h, win);
    const auto [xmin, xmax, ymin, ymax] = projected_box(c, f.points, [](const Vec3& p) { return p; }, w, h);
    CHECK(xmin >= win.left * w);
    CHECK(xmax <= win.right * w);
    CHECK(ymin >= win.top * h);
    CHECK(ymax <= win.bottom * h);
    // Not lost in a corner of it: the shot spans a good part of the window one way.
    CHECK(std::max((xmax - xmin) / ((win.right - win.left) * w), (ymax - ymin) / ((win.bottom - win.top) * h)) > 0.5);
  }
}

TEST_CASE("sample_at interpolates between samples and clamps to the shot", "[render][unit]") {
  ShotTrajectory s;
  s.samples.resize(2);
  s.samples[0].t = 0;
  s.samples[0].position = Vec3(0, 0, 0);
  s.samples[1].t = 2;
  s.samples[1].position = Vec3(10, 4, -2);
  std::size_t index = 99;
  CHECK((sample_at(s, 0.5, &index).position - Vec3(2.5, 1, -0.5)).norm() < 1e-12);
  CHECK(index == 0);
  CHECK((sample_at(s, 5.0, &index).position - Vec3(10, 4, -2)).norm() < 1e-12);
  CHECK(index == 1);
  CHECK(sample_at(s, -1.0).position.norm() < 1e-12);
}

TEST_CASE("the trail has one quad per segment coloured by the phase that made it", "[render][unit]") {
  ShotTrajectory s;
  const Phase phases[] = {Phase::Flight, Phase::Flight, Phase::Flight, Phase::Bounce, Phase::Bounce, Phase::Roll,
                          Phase::Rest};
  for (int i = 0; i < 7; ++i) {
    TrajectorySample x;
    x.t = i;
    x.position = Vec3(10.0 * i, i < 3 ? 5.0 * i * (3 - i) : 0.0, 0);
    x.phase = phases[i];
    s.samples.push_back(x);
  }
  Camera c;
  c.eye = Vec3(30, 5, 80);
  c.target = Vec3(30, 5, 0);
  MeshData out;
  append_trail(out, s, 100.0, c, {5.0, 720});
  // Segments 0-1, 1-2: flight; 2-3, 3-4: bounce; 4-5: roll; 5-6 ends at rest: no quad.
  REQUIRE(out.vertices.size() == 5 * 4);
  REQUIRE(out.indices.size() == 5 * 6);
  const Phase expect[] = {Phase::Flight, Phase::Flight, Phase::Bounce, Phase::Bounce, Phase::Roll};
  for (int q = 0; q < 5; ++q) {
    for (int k = 0; k < 4; ++k) CHECK(out.vertices[std::size_t(4 * q + k)].color == phase_color(expect[q]));
  }
  // The ribbon quad is about 5 + 1 px wide on screen wherever it is (5 px solid plus half a
  // pixel of soft edge each side; exact on the image axis, off axis the widening is
  // perpendicular to the line of sight, not to the image plane). Vertices carry the
  // across-ribbon coordinate for the edge fade.
  const auto a = c.project(out.vertices[0].position.cast<double>(), 1280, 720);
  const auto b = c.project(out.vertices[1].position.cast<double>(), 1280, 720);
  CHECK((*a - *b).norm() == Approx(6.0).epsilon(0.05));
  CHECK(out.vertices[0].pattern == -1.0f);
  CHECK(out.vertices[1].pattern == 1.0f);
  // The three phase colours are distinct from each other.
  CHECK((phase_color(Phase::Flight) - phase_color(Phase::Bounce)).norm() > 0.3);
  CHECK((phase_color(Phase::Bounce) - phase_color(Phase::Roll)).norm() > 0.3);
  // Up to t = 1.5 s: the first segment and half of the second.
  MeshData part;
  append_trail(part, s, 1.5, c, {5.0, 720});
  REQUIRE(part.vertices.size() == 2 * 4);
  CHECK(part.vertices[6].position.x() == Approx(15.0).margin(0.2));
}

TEST_CASE("flip_rows reverses the row order and keeps each row intact", "[render][unit]") {
  std::vector<std::uint8_t> px = {1, 2, 3, 4, 5, 6, 7, 8, 9};  // 3 x 3, one channel
  flip_rows(px, 3, 3, 1);
  CHECK(px == std::vector<std::uint8_t>{7, 8, 9, 4, 5, 6, 1, 2, 3});
  std::vector<std::uint8_t> two = {1, 1, 2, 2, 3, 3, 4, 4};  // 1 x 4, two channels
  flip_rows(two, 1, 4, 2);
  CHECK(two == std::vector<std::uint8_t>{4, 4, 3, 3, 2, 2, 1, 1});
}

TEST_CASE("PNGs are written atomically and read back identical", "[render][unit]") {
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_png_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::vector<std::uint8_t> rgba(5 * 3 * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 7);
  write_png_atomic(dir / "a.png", 5, 3, rgba);
  int w = 0, h = 0;
  CHECK(read_png_rgba(dir / "a.png", &w, &h) == rgba);
  CHECK(w == 5);
  CHECK(h == 3);
  // Only the final file remains: no temporary left behind.
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);
  CHECK_THROWS_WITH(write_png_atomic(dir / "missing" / "b.png", 5, 3, rgba), Catch::Contains("missing"));
  CHECK_THROWS_AS(write_png_atomic(dir / "c.png", 4, 3, rgba), InputError);
  std::filesystem::remove_all(dir);
}

TEST_CASE("every world surface material has a distinct palette colour", "[render][unit]") {
  const char* names[] = {"tee", "fairway", "rough", "sand", "green", "water", "dirt", "grass", "warning_track",
                         "wall", "flag"};
  std::set<std::tuple<float, float, float>> seen;
  for (const char* n : names) {
    INFO(n);
    const auto p = palette_color(n);
    REQUIRE(p);
    seen.insert({p->color.x(), p->color.y(), p->color.z()});
  }
  CHECK(seen.size() == std::size(names));
  CHECK_FALSE(palette_color("no_such_material"));
  // Each surface has its procedural look: fairway and green mown (stripes), rough long
  // grass, then sand, water, dirt; walls and equipment plain.
  CHECK(palette_color("fairway")->pattern == surface_look::kMown);
  CHECK(palette_color("green")->pattern == surface_look::kMown);
  CHECK(palette_color("rough")->pattern == surface_look::kLongGrass);
  CHECK(palette_color("sand")->pattern == surface_look::kSand);
  CHECK(palette_color("water")->pattern == surface_look::kWater);
  CHECK(palette_color("dirt")->pattern == surface_look::kDirt);
  CHECK(palette_color("wall")->pattern == surface_look::kPlain);
}

TEST_CASE("label text: every marker character has a glyph, width grows per character", "[render][unit]") {
  for (char c : std::string("0123456789 ydft.")) CHECK(font_has_glyph(c));
  CHECK_FALSE(font_has_glyph('Q'));
  MeshData m;
  const double wd = append_text(m, "100", Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 7.0, Eigen::Vector3f::Ones());
  CHECK(wd == Approx(17.0));  // 3 glyphs of 5 cells + 2 gaps, cell = 1 m
  // "1" has 10 lit cells, "0" has 19: 48 quads.
  CHECK(m.vertices.size() == 48 * 4);
}

TEST_CASE("label text: g, p and y hang below the baseline, the other letters stand on it", "[render][unit]") {
  // Cell = 1 m (height 7): the baseline is y = 0; "yd" read as "3d" while the font had no descent.
  auto lowest = [](const std::string& text) {
    MeshData m;
    append_text(m, text, Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 7.0, Eigen::Vector3f::Ones());
    float y = 1e9f;
    for (const Vertex& v : m.vertices) y = std::min(y, v.position.y());
    return y;
  };
  for (const char* c : {"g", "p", "y"}) {
    INFO(c);
    CHECK(lowest(c) == Approx(-text_descent(7.0)));
  }
  for (const char* c : {"0", "a", "d", "f", "t", "m", "."}) {
    INFO(c);
    CHECK(lowest(c) == Approx(0.0));
  }
}

TEST_CASE("the tracer's halo lies under the core and fades from the ball back to the launch", "[render][unit]") {
  ShotTrajectory s;
  for (int i = 0; i < 5; ++i) {
    TrajectorySample x;
    x.t = i;
    x.position = Vec3(10.0 * i, 4.0 * i * (4 - i), 0);
    x.phase = Phase::Flight;
    s.samples.push_back(x);
  }
  Camera c;
  c.eye = Vec3(20, 5, 80);
  c.target = Vec3(20, 5, 0);
  TrailStyle style{5.0, 720};
  style.glow_px = 18.0;
  MeshData out;
  append_trail(out, s, 100.0, c, style);
  // Four halo quads first (drawn under), then the four core quads.
  REQUIRE(out.vertices.size() == 2 * 4 * 4);
  for (int q = 0; q < 4; ++q) {
    CHECK(out.vertices[std::size_t(4 * q)].normal.x() == 2.0f);      // halo
    CHECK(out.vertices[std::size_t(16 + 4 * q)].normal.x() == 1.0f); // feathered core
  }
  // Opacity grows toward the ball: 40 % of the full opacity at the launch, all of it at the ball.
  CHECK(out.vertices[0].normal.y() == Approx(0.4 * style.glow_opacity));
  CHECK(out.vertices[14].normal.y() == Approx(style.glow_opacity));
  for (int q = 0; q + 1 < 4; ++q)
    CHECK(out.vertices[std::size_t(4 * (q + 1))].normal.y() > out.vertices[std::size_t(4 * q)].normal.y());
  // The halo is glow_px wide on screen, the core width_px + 1.
  const auto a = c.project(out.vertices[0].position.cast<double>(), 1280, 720);
  const auto b = c.project(out.vertices[1].position.cast<double>(), 1280, 720);
  CHECK((*a - *b).norm() == Approx(18.0).epsilon(0.05));
}

TEST_CASE("a camera change glides: blend_cameras runs from one camera to the other without a flip", "[render][unit]") {
  const ShotTrajectory shot = synthetic_shot();
  const int w = 1280, h = 720;
  for (CameraKind from : {CameraKind::Behind, CameraKind::Side, CameraKind::Top, CameraKind::Follow}) {
    for (CameraKind to : {CameraKind::Behind, CameraKind::Side, CameraKind::Top, CameraKind::Follow}) {
      INFO(to_string(from) << " -> " << to_string(to));
      const Camera a = frame_shot(from, shot, 3.0, w, h), b = frame_shot(to, shot, 3.0, w, h);
      CHECK((blend_cameras(a, b, 0.0).eye - a.eye).norm() < 1e-9);
      CHECK((blend_cameras(a, b, 1.0).eye - b.eye).norm() < 1e-9);
      CHECK((blend_cameras(a, b, 1.0).target - b.target).norm() < 1e-9);
      Vec3 prev = a.eye;
      for (int i = 1; i <= 20; ++i) {
        const Camera c = blend_cameras(a, b, i / 20.0);
        // A usable camera all the way: a unit up not along the view, the eye moving steadily.
        CHECK(std::abs(c.up.norm() - 1.0) < 1e-9);
        CHECK(std::abs(c.forward().dot(c.up)) < 0.999);
        CHECK((c.eye - prev).norm() <= (b.eye - a.eye).norm() / 20.0 + 1e-9);
        prev = c.eye;
      }
    }
  }
}
