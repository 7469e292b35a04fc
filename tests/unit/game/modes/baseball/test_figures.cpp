// The people on the field (figures.hpp): the pitcher's hand is at the pitch's release point
// when he lets it go, the batter's bat is level at the bat's height at contact, a fielder
// stands until his reaction, runs no faster than his sprint and stops at his goal.
#include <catch2/catch.hpp>

#include "game/modes/baseball/figures.hpp"

using namespace sweetspot;

TEST_CASE("the pitcher releases where the pitch starts; the batter meets it level", "[baseball][figures]") {
  const Vec3 release(16.46, 1.78, -0.55);
  for (const bool lefty : {false, true}) {
    const Vec3 r = lefty ? Vec3(release.x(), release.y(), -release.z()) : release;
    const Figure p = pitcher_figure(r, 0.0, lefty);
    CHECK((p.joint[lefty ? kLeftHand : kRightHand] - r).norm() < 1e-9);
    // Set before the wind-up: both hands together at his chest, on the rubber.
    const Figure set = pitcher_figure(r, -kWindupTime, lefty);
    CHECK((set.joint[kLeftHand] - set.joint[kRightHand]).norm() < 0.1);
    CHECK(set.joint[kPelvis].x() == Approx(18.44));
  }
  const Figure b = batter_figure(1.0, 0.7, false);
  REQUIRE(b.has_bat);
  CHECK(b.joint[kBatKnob].y() == Approx(0.7));
  CHECK(b.joint[kBatTip].y() == Approx(0.7));
  CHECK(b.joint[kBatTip].z() > b.joint[kBatKnob].z() + 0.8);  // square to the pitch, across the plate
  CHECK(b.joint[kBatKnob].z() < 0.0);                         // a right-hander on the third-base side
  CHECK(batter_figure(1.0, 0.7, true).joint[kBatKnob].z() > 0.0);
  // Through his stride (to phase 0.6, the pitch arriving) the bat stays loaded, up over his
  // back shoulder: a taken pitch shows no swing. The swing is the last 0.4, to level.
  const auto bat = [](double phase) {
    const Figure f = batter_figure(phase, 0.7, false);
    return Vec3(f.joint[kBatTip] - f.joint[kBatKnob]).normalized();
  };
  CHECK((bat(0.6) - bat(0.0)).norm() < 1e-9);
  CHECK(bat(0.6).y() > 0.8);
  CHECK(bat(0.8).y() < bat(0.6).y() - 0.1);
  CHECK(std::abs(bat(1.0).y()) < 1e-9);
}

TEST_CASE("a fielder waits for his reaction, runs at most his sprint and stops at his goal", "[baseball][figures]") {
  FielderAbility a;
  a.reaction = 0.3;
  a.accel = 4.0;
  a.sprint = 8.5;
  const Vec3 start(90.0, 0.0, 0.0), goal(110.0, 0.0, 15.0);
  CHECK((fielder_position(start, goal, a, 0.25) - start).norm() == 0.0);
  Vec3 last = start;
  for (double t = 0.35; t < 6.0; t += 0.05) {
    const Vec3 p = fielder_position(start, goal, a, t);
    CHECK((p - last).norm() <= a.sprint * 0.05 + 1e-9);
    last = p;
  }
  CHECK((last - goal).norm() < 1e-9);  // 25 m in well under 6 s
  // Standing, he faces home; running, along his run.
  const Figure f = fielder_figure(start, goal, a, 2.0, false);
  CHECK(f.joint[kHead].y() > 1.5);
  CHECK_FALSE(f.has_bat);
  // Fielding: his glove hand goes to the ball within his arm's reach, above his head for a
  // high one; for a grounder he bends and the glove goes down toward it.
  const Vec3 high = goal + Vec3(0.1, 1.9, 0.1);
  const Figure c = fielder_figure(start, goal, a, 6.0, false, high);
  CHECK(c.joint[kLeftHand].y() > c.joint[kHead].y());
  CHECK((c.joint[kLeftHand] - c.joint[kLeftShoulder]).norm() <= 0.62 + 1e-9);
  CHECK((c.joint[kLeftHand] - high).norm() < 0.15);
  const Vec3 low = goal + Vec3(0.4, 0.05, -0.3);
  const Figure g = fielder_figure(start, goal, a, 6.0, false, low);
  CHECK(g.joint[kPelvis].y() < f.joint[kPelvis].y() - 0.3);
  CHECK(g.joint[kLeftHand].y() < 0.6);
}
