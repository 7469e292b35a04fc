#include <catch2/catch.hpp>

#include "game/render/camera.hpp"
#include "game/modes/replay.hpp"
#include "game/ui/trajectory_plot.hpp"

using namespace sweetspot;

namespace {
ShotTrajectory three_samples() {
  ShotTrajectory s;
  s.samples.push_back({0.0, Vec3(0, 0, 0), Vec3(10, 10, 0), Vec3::Zero(), Phase::Flight});
  s.samples.push_back({2.0, Vec3(20, 0, 2), Vec3(10, -10, 0), Vec3::Zero(), Phase::Bounce});
  s.samples.push_back({4.0, Vec3(30, 0, 2), Vec3::Zero(), Vec3::Zero(), Phase::Rest});
  return s;
}
}  // namespace

TEST_CASE("replay plays at its speed and pauses at the end", "[ui][replay]") {
  ReplayState r;
  r.speed = 2.0;
  r.advance(0.5, 4.0);
  CHECK(r.time == Approx(1.0));
  CHECK(r.playing);
  r.advance(10.0, 4.0);
  CHECK(r.time == 4.0);
  CHECK_FALSE(r.playing);
  r.restart();
  CHECK(r.time == 0.0);
  CHECK(r.playing);
  r.playing = false;
  r.advance(1.0, 4.0);
  CHECK(r.time == 0.0);  // paused: time stands still
  r.scrub(3.5, 4.0);
  CHECK(r.time == 3.5);
}

TEST_CASE("replay samples interpolate between bracketing samples", "[ui][replay]") {
  const ShotTrajectory s = three_samples();
  const TrajectorySample mid = sample_at(s, 1.0);
  CHECK(mid.position.x() == Approx(10.0));
  CHECK(mid.position.z() == Approx(1.0));
  CHECK(mid.velocity.y() == Approx(0.0).margin(1e-12));
  CHECK(sample_at(s, -1.0).position.x() == 0.0);
  CHECK(sample_at(s, 99.0).position.x() == 30.0);
  CHECK(duration(s) == 4.0);
  CHECK(duration(ShotTrajectory{}) == 0.0);
}

TEST_CASE("plot map keeps the trajectory inside its box with equal axes", "[ui][plot]") {
  const ShotTrajectory s = three_samples();
  for (PlotView view : {PlotView::Side, PlotView::Top}) {
    const PlotMap m = fit_plot(s, view, 100.0, 300.0, 400.0, 100.0);
    for (const auto& p : s.samples) {
      const double px = m.to_px_x(p.position.x()), py = m.to_px_y(plot_y(p.position, view));
      CHECK(px >= 100.0);
      CHECK(px <= 500.0);
      CHECK(py >= 200.0);
      CHECK(py <= 300.0);
    }
  }
  // Top view: a ball right of the target line is drawn below the line (larger pixel y).
  const PlotMap top = fit_plot(s, PlotView::Top, 0.0, 100.0, 400.0, 100.0);
  CHECK(top.to_px_y(plot_y(Vec3(20, 0, 2), PlotView::Top)) > top.to_px_y(0.0));
}

TEST_CASE("a replay with a pre-roll starts before launch and scrubs down to it", "[ui][replay]") {
  ReplayState r;
  r.pre_roll = 0.25;
  r.restart();
  CHECK(r.time == -0.25);
  r.advance(0.1, 4.0);
  CHECK(r.time == Approx(-0.15));
  r.scrub(-1.0, 4.0);
  CHECK(r.time == -0.25);  // held at the start of the pre-roll
  r.scrub(2.0, 4.0);
  CHECK(r.time == 2.0);
}
