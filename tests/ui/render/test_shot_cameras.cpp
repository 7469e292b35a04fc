// Every camera on real shots: a driver, a wedge and a home run, early in the
// flight, at the apex, at the landing and at the end. What must be in the frame is in it:
// the ball always; the trail drawn so far for the cameras that frame the shot; the landing
// point once Follow has turned to the landing area.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "game/content/scenario.hpp"
#include "game/render/camera.hpp"
#include "game/render/shot_scene.hpp"
#include "game/render/shot_view.hpp"
#include "support/test_assets.hpp"
#include "game/rules/run_shot.hpp"

using namespace sweetspot;

namespace {

bool in_frame(const Camera& c, const Vec3& p, int w, int h, double margin = 0.0) {
  const auto q = c.project(p, w, h);
  return q && q->x() >= margin && q->x() <= w - margin && q->y() >= margin && q->y() <= h - margin;
}

}  // namespace

TEST_CASE("every camera keeps the ball and the trail in the frame on a driver, a wedge and a home run", "[render][unit]") {
  const int w = 960, h = 540;
  for (const char* name : {"golf/driver", "golf/pw", "baseball/home-run"}) {
    const ShotResult r = run_scenario(load_scenario(test::assets(), name, {}));
    const ShotTrajectory& shot = r.trajectory;
    REQUIRE(shot.samples.size() > 10);
    const double land = shot.summary.hang_time_s, end = shot.samples.back().t;
    REQUIRE(land > 0);
    for (const double t : {0.15 * land, 0.5 * land, land, end}) {
      for (const CameraKind k : {CameraKind::Behind, CameraKind::Side, CameraKind::Top, CameraKind::Follow}) {
        INFO(name << " t=" << t << " s, camera " << to_string(k));
        const Camera c = frame_shot(k, shot, t, w, h);
        const Vec3 ball = sample_at(shot, t).position;
        CHECK(in_frame(c, ball, w, h, 2.0));
        if (k != CameraKind::Follow) {
          // The whole trail up to t (the framing covers the whole shot).
          std::size_t outside = 0;
          for (const auto& s : shot.samples)
            if (s.t <= t && !in_frame(c, s.position, w, h)) ++outside;
          CHECK(outside == 0);
        } else if (t >= land) {
          // Follow has turned to the landing area: the landing point and the ball.
          CHECK(in_frame(c, shot.summary.landing_position, w, h, 2.0));
        }
      }
    }
  }
}

TEST_CASE("follow turns smoothly from the chase to the landing view", "[render][unit]") {
  const ShotResult r = run_scenario(load_scenario(test::assets(), "golf/driver", {}));
  const ShotTrajectory& shot = r.trajectory;
  const double land = shot.summary.hang_time_s;
  const int w = 960, h = 540;
  // No jump between frames 1/60 s apart through the turn: the eye moves less than the ball
  // travels in a frame plus the turn's own share (the eye travels ~60 m over the second).
  Vec3 prev = frame_shot(CameraKind::Follow, shot, land - 1.2, w, h).eye;
  double worst = 0;
  for (double t = land - 1.2 + 1.0 / 60; t <= land + 0.2; t += 1.0 / 60) {
    const Vec3 eye = frame_shot(CameraKind::Follow, shot, t, w, h).eye;
    worst = std::max(worst, (eye - prev).norm());
    prev = eye;
  }
  CHECK(worst < 3.0);
  // Before the turn it chases: the eye a few metres behind the ball.
  const double t = land - 2.0;
  const Vec3 ball = sample_at(shot, t).position;
  CHECK((frame_shot(CameraKind::Follow, shot, t, w, h).eye - ball).norm() < 6.0);
}

TEST_CASE("follow's landing view looks the way the ball came down, when it rebounds behind", "[render][unit]") {
  // A ball that flies 50 m along +x, strikes a tree there and rebounds to rest 5 m behind
  // its launch: the landing view looks down the flight (+x), not back along launch -> rest.
  ShotTrajectory shot;
  const double land = 3.0;
  for (int i = 0; i <= 60; ++i) {
    const double t = land * i / 60.0, x = 50.0 * i / 60.0;
    TrajectorySample s;
    s.t = t;
    s.position = Vec3(x, 0.02 + 4.0 * 15.0 * (t / land) * (1.0 - t / land), 0.0);
    s.velocity = Vec3(50.0 / land, 20.0 * (1.0 - 2.0 * t / land), 0.0);
    shot.samples.push_back(s);
  }
  for (int i = 1; i <= 30; ++i) {
    TrajectorySample s;
    s.t = land + 0.1 * i;
    s.position = Vec3(50.0 - 55.0 * i / 30.0, 0.02, 3.0 * i / 30.0);
    s.velocity = Vec3(-18.0, 0.0, 1.0);
    s.phase = Phase::Roll;
    shot.samples.push_back(s);
  }
  shot.summary.hang_time_s = land;
  shot.summary.landing_position = Vec3(50.0, 0.02, 0.0);
  shot.summary.rest_position = shot.samples.back().position;
  const int w = 960, h = 540;
  const Camera c = frame_shot(CameraKind::Follow, shot, land, w, h);
  INFO("forward " << c.forward().transpose());
  CHECK(c.forward().x() > 0.8);
  CHECK(in_frame(c, shot.summary.landing_position, w, h, 2.0));
  // Half a second before the landing, mid-turn, the ball is still in the picture.
  const double t = land - 0.5;
  CHECK(in_frame(frame_shot(CameraKind::Follow, shot, t, w, h), sample_at(shot, t).position, w, h, 2.0));
}

TEST_CASE("behind, side and top look along the shot's target line, not the world's +x", "[render][unit]") {
  // The tour drive turned to fly along +z, as on a hole played that way: its aim is the
  // hole's line, and each framing camera must stand where it does on a range, turned with it.
  const ShotResult r = run_scenario(load_scenario(test::assets(), "golf/driver", {}));
  const Quat turn(Eigen::AngleAxisd(-kPi / 2.0, Vec3::UnitY()));  // +x -> +z
  ShotTrajectory shot = r.trajectory;
  for (auto& s : shot.samples) {
    s.position = turn * s.position;
    s.velocity = turn * s.velocity;
  }
  shot.summary.landing_position = turn * shot.summary.landing_position;
  shot.summary.rest_position = turn * shot.summary.rest_position;
  const Vec3 line = aim_line(kPi / 2.0);
  REQUIRE(line.isApprox(Vec3::UnitZ(), 1e-12));
  const int w = 960, h = 540;
  const double t = shot.summary.hang_time_s;
  ShotFraming f = shot_framing(shot, t);
  f.target_line = line;
  const ShotFraming range = shot_framing(r.trajectory, t);  // the same shot down +x
  for (const CameraKind k : {CameraKind::Behind, CameraKind::Side, CameraKind::Top}) {
    INFO("camera " << to_string(k));
    const Camera c = frame_shot(k, f, w, h), ref = frame_shot(k, range, w, h);
    // The turned camera is the range camera turned: eye, view and image right alike.
    CHECK((c.eye - turn * ref.eye).norm() < 1e-6 * (1.0 + ref.eye.norm()));
    CHECK((c.forward() - turn * ref.forward()).norm() < 1e-9);
    CHECK((c.right() - turn * ref.right()).norm() < 1e-9);
    for (const auto& s : shot.samples) CHECK(in_frame(c, s.position, w, h));
  }
  // Behind stands behind the tee looking down the line; the side view sees downrange to the
  // image's right.
  const Camera behind = frame_shot(CameraKind::Behind, f, w, h);
  CHECK(behind.forward().dot(line) > 0.8);
  CHECK((f.launch - behind.eye).dot(line) > 10.0);
  const Camera side = frame_shot(CameraKind::Side, f, w, h);
  CHECK(side.right().dot(line) > 0.95);
}

TEST_CASE("a putt's view holds the ball above the swing meter, the cup and the flag in the frame", "[render][unit]") {
  // The meter takes the bottom ~110 px of the window (golf_hud.cpp: its bar at h - 80, its
  // label above it). A 40 ft putt's ball used to sit at y = 716 of 800, under it.
  const Vec3 ball(3.0, 0.021, -2.0), aim = Vec3(1.0, 0.0, 1.0).normalized();
  for (const auto& [w, h] : {std::pair{1280, 800}, std::pair{1280, 720}, std::pair{960, 540}}) {
    for (const double to_pin : {0.5, 1.0, 3.0, 6.0, 9.0, 12.2, 18.0, 30.0}) {
      INFO(w << "x" << h << ", putt of " << to_pin << " m");
      const Camera c = putt_address_camera(ball, aim, to_pin);
      const auto at = c.project(ball, w, h);
      REQUIRE(at);
      CHECK(at->y() < h - 110.0);
      CHECK(at->y() > 0.5 * h);  // still the lower half: the line runs up the image from it
      // The cup; the flag's top too from 10 ft (a shorter putt's view looks down at the cup,
      // the flag above it), out to 100 ft (past 40 ft the lens widens for it: a 61 ft chip's
      // cloth was cut off at the top).
      const Vec3 cup = ball + to_pin * aim;
      CHECK(in_frame(c, Vec3(cup.x(), 0.0, cup.z()), w, h, 2.0));
      if (to_pin >= 3.0) CHECK(in_frame(c, Vec3(cup.x(), kFlagstickHeight, cup.z()), w, h, 2.0));
      CHECK(c.fov_y <= deg_to_rad(60.0) + 1e-12);
    }
  }
}

TEST_CASE("a chip's view from beside the ball shows the flag clear of the golfer; the full shot's hid it", "[render][unit]") {
  // A 20 ft chip aimed 11.4 deg right of the pin for the slope (play --mode golf --seed 8,
  // hole 2, stroke 4). The golfer stands ~0.75 m left of the ball's line, his head ~1.6 m up;
  // the golf view takes the putt's camera for such a chip (golf_view.cpp, address_camera_at).
  const Vec3 ball(0.0, 0.021, 0.0);
  const double off = deg_to_rad(11.4);
  const Vec3 aim(std::cos(off), 0.0, std::sin(off));  // the aim: right of +x, the pin's line
  const Vec3 right(-aim.z(), 0.0, aim.x());
  const Vec3 pin = ball + 6.1 * Vec3::UnitX();
  const Vec3 head = ball - 0.75 * right + Vec3(0.0, 1.6, 0.0), chest = ball - 0.75 * right + Vec3(0.0, 1.2, 0.0);
  const int w = 1280, h = 800;
  // Apart on the screen: the flag's pole from its cup to its top against his head and chest.
  const auto clear = [&](const Camera& c) {
    double nearest = 1e9;
    for (const Vec3& body : {head, chest})
      for (const double y : {0.0, 0.5 * kFlagstickHeight, kFlagstickHeight}) {
        const auto a = c.project(body, w, h), b = c.project(Vec3(pin.x(), y, pin.z()), w, h);
        REQUIRE(a);
        REQUIRE(b);
        nearest = std::min(nearest, (*a - *b).norm());
      }
    return nearest;
  };
  const Camera chip = putt_address_camera(ball, aim, 6.1);
  CHECK(in_frame(chip, pin, w, h, 2.0));
  CHECK(in_frame(chip, Vec3(pin.x(), kFlagstickHeight, pin.z()), w, h, 2.0));
  CHECK(clear(chip) > 80.0);
  CHECK(clear(full_shot_address_camera(ball, aim)) < 40.0);
}

TEST_CASE("a putt's view sees the green left of the line over the golfer's head", "[render][unit]") {
  // The golfer addresses a putt from the left of its line: his legs and hips a box 0.55-0.95 m
  // left of it up to 0.95 m, his trunk and head, bent over toward the ball, 0.45-0.9 m left
  // from there to 1.7 m, each 0.15 m either side of the ball's station (ESTIMATES of the
  // figure game/render/golfer_figure draws). Of the green left of the line 0.8-2.4 m out to
  // the side and 2-9 m ahead (where the slope arrows lie), the share his boxes cover on the
  // screen: from 1.9 m up the sight line over his head met the green ~25 m out and he
  // covered 42 % of it.
  const Vec3 ball(0.0, 0.021, 0.0), aim = Vec3::UnitX();
  const Vec3 left(aim.z(), 0.0, -aim.x());
  const int w = 1280, h = 800;
  struct Box {
    double side0, side1, up0, up1;
  };
  const Box boxes[] = {{0.55, 0.95, 0.0, 0.95}, {0.45, 0.9, 0.95, 1.7}};
  const auto hidden_share = [&](const Camera& c) {
    std::vector<Eigen::Vector4d> outlines;  // each box's outline on the screen: x0, y0, x1, y1
    for (const Box& b : boxes) {
      Eigen::Vector4d o(1e9, 1e9, -1e9, -1e9);
      for (const double side : {b.side0, b.side1})
        for (const double along : {-0.15, 0.15})
          for (const double up : {b.up0, b.up1}) {
            const auto p = c.project(ball + side * left + along * aim + Vec3(0.0, up, 0.0), w, h);
            REQUIRE(p);
            o = Eigen::Vector4d(std::min(o[0], p->x()), std::min(o[1], p->y()), std::max(o[2], p->x()), std::max(o[3], p->y()));
          }
      outlines.push_back(o);
    }
    int hidden = 0, seen = 0;
    for (double side = 0.8; side <= 2.41; side += 0.4)
      for (double ahead = 2.0; ahead <= 9.01; ahead += 1.0) {
        const auto p = c.project(ball + ahead * aim + side * left, w, h);
        if (!p || p->x() < 0 || p->x() > w || p->y() < 0 || p->y() > h) continue;
        ++seen;
        if (std::any_of(outlines.begin(), outlines.end(), [&](const Eigen::Vector4d& o) {
              return p->x() > o[0] && p->x() < o[2] && p->y() > o[1] && p->y() < o[3];
            }))
          ++hidden;
      }
    REQUIRE(seen > 20);
    return static_cast<double>(hidden) / seen;
  };
  const double share = hidden_share(putt_address_camera(ball, aim, 7.3));
  INFO("hidden share " << share);
  CHECK(share < 0.25);
}
