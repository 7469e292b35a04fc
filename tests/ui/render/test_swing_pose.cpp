// The replay's swing (game/render/swing_pose.hpp): the downswing ends exactly at the impact pose,
// arrives with the delivered velocity (path, attack angle, speed), is still at the top, and
// turns rigidly (the face keeps its relation to the path); after impact it follows through to rest.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "game/render/swing_pose.hpp"

using namespace sweetspot;

namespace {

// A tour driver's delivery: 50.5 m/s (113 mph), 1.3 deg down, path 2 deg in-to-out.
ImpactorPlacement driver_impact() {
  ImpactorPlacement p;
  p.position = Vec3(-0.0214, 0.0214, 0.0);
  p.orientation = Quat(Eigen::AngleAxisd(deg_to_rad(10.4), Vec3::UnitZ()));
  const double speed = 50.5, attack = deg_to_rad(-1.3), path = deg_to_rad(2.0);
  p.velocity = speed * Vec3(std::cos(attack) * std::cos(path), std::sin(attack), std::cos(attack) * std::sin(path));
  return p;
}

}  // namespace

TEST_CASE("the downswing arrives at the impact pose with the delivered velocity", "[render][unit]") {
  const ImpactorPlacement impact = driver_impact();
  const Vec3 contact = Vec3(0, 0.0214, 0) - 0.0214 * impact.velocity.normalized();
  const Vec3 shaft = impact.orientation * head_frame_shaft_axis();
  const ImpactorPlacement at0 = swing_pose(impact, contact, shaft, 0.0, kClubSwing);
  CHECK((at0.position - impact.position).norm() < 1e-12);
  // Velocity just before impact, by finite difference of a point rigidly attached (the
  // contact point): the delivered velocity within 1 % (the arc's curvature over 1e-4 s).
  const double dt = 1e-4;
  const ImpactorPlacement before = swing_pose(impact, contact, shaft, -dt, kClubSwing);
  const Vec3 contact_before = before.position + before.orientation * (impact.orientation.conjugate() * (contact - impact.position));
  const Vec3 v = (contact - contact_before) / dt;
  CHECK((v - impact.velocity).norm() < 0.01 * impact.velocity.norm());
  // At the top of the swing (and before it) the club is at rest, high above the ball.
  const ImpactorPlacement top = swing_pose(impact, contact, shaft, -kClubSwing.downswing, kClubSwing);
  const ImpactorPlacement earlier = swing_pose(impact, contact, shaft, -1.0, kClubSwing);
  CHECK((top.position - earlier.position).norm() < 1e-12);
  CHECK(top.position.y() > impact.position.y() + 1.0);
  // A rigid turn about the pivot: the head keeps its distance to it.
  const Vec3 vhat = impact.velocity.normalized();
  const Vec3 pivot = contact + kClubSwing.radius * (shaft - shaft.dot(vhat) * vhat).normalized();
  CHECK((top.position - pivot).norm() == Approx((impact.position - pivot).norm()).epsilon(1e-9));
  // No velocity (a launch-only shot): no swing.
  ImpactorPlacement still = impact;
  still.velocity = Vec3::Zero();
  CHECK((swing_pose(still, contact, shaft, -0.1, kClubSwing).position - still.position).norm() == 0.0);
}

TEST_CASE("after impact the club follows through on the same arc and comes to rest at the finish", "[render][unit]") {
  const ImpactorPlacement impact = driver_impact();
  const Vec3 contact = Vec3(0, 0.0214, 0) - 0.0214 * impact.velocity.normalized();
  const Vec3 shaft = impact.orientation * head_frame_shaft_axis();
  const Vec3 vhat = impact.velocity.normalized();
  const Vec3 pivot = contact + kClubSwing.radius * (shaft - shaft.dot(vhat) * vhat).normalized();
  // Just after impact it still moves at the delivered velocity (the same point, differenced).
  const double dt = 1e-4;
  const ImpactorPlacement after = swing_pose(impact, contact, shaft, dt, kClubSwing);
  const Vec3 contact_after = after.position + after.orientation * (impact.orientation.conjugate() * (contact - impact.position));
  CHECK(((contact_after - contact) / dt - impact.velocity).norm() < 0.01 * impact.velocity.norm());
  // It stops at the finish, 2F/omega after impact, turned F about the pivot, and stays there.
  const double omega = impact.velocity.norm() / kClubSwing.radius;
  const double tf = 2.0 * kClubSwing.finish / omega;
  const ImpactorPlacement finish = swing_pose(impact, contact, shaft, tf, kClubSwing);
  const ImpactorPlacement later = swing_pose(impact, contact, shaft, tf + 2.0, kClubSwing);
  CHECK((finish.position - later.position).norm() < 1e-12);
  CHECK((finish.position - pivot).norm() == Approx((impact.position - pivot).norm()).epsilon(1e-9));
  const Vec3 a = (impact.position - pivot).normalized(), b = (finish.position - pivot).normalized();
  CHECK(std::acos(std::clamp(a.dot(b), -1.0, 1.0)) == Approx(kClubSwing.finish).margin(1e-6));
  // A finish is high: the head ends up above the ball, toward the target side of the pivot.
  CHECK(finish.position.y() > impact.position.y() + 1.0);
  // Halfway through the follow-through it has gone more than half the way (it slows down).
  const ImpactorPlacement mid = swing_pose(impact, contact, shaft, 0.5 * tf, kClubSwing);
  const Vec3 m = (mid.position - pivot).normalized();
  CHECK(std::acos(std::clamp(a.dot(m), -1.0, 1.0)) > 0.7 * kClubSwing.finish);
}

TEST_CASE("a chip's follow-through is about as long as its backswing, a full swing's goes over the shoulder", "[render][unit]") {
  ImpactorPlacement chip = driver_impact();
  const Vec3 contact = Vec3(0, 0.0214, 0) - 0.0214 * chip.velocity.normalized();
  const Vec3 shaft = chip.orientation * head_frame_shaft_axis();
  const auto turned = [&](const ImpactorPlacement& impact, double t) {
    const Vec3 vhat = impact.velocity.normalized();
    const Vec3 pivot = contact + kClubSwing.radius * (shaft - shaft.dot(vhat) * vhat).normalized();
    const Vec3 a = (impact.position - pivot).normalized(), b = (swing_pose(impact, contact, shaft, t, kClubSwing).position - pivot).normalized();
    return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  };
  // A 14 % chip, ~6 m/s: wound back ~0.5 rad (the top of its downswing), through ~0.75 rad.
  chip.velocity = chip.velocity.normalized() * 6.0;
  const double back = turned(chip, -kClubSwing.downswing), through = turned(chip, 10.0);
  CHECK(back == Approx(6.0 / kClubSwing.radius * kClubSwing.downswing / 2.0).epsilon(1e-6));
  CHECK(through == Approx(kClubSwing.follow_per_backswing * back).epsilon(1e-6));
  CHECK(through < 1.0);
  // Every full swing, from a 54 mph wedge up, finishes at the full finish.
  ImpactorPlacement wedge = driver_impact();
  wedge.velocity = wedge.velocity.normalized() * 24.5;
  CHECK(turned(wedge, 10.0) == Approx(kClubSwing.finish).margin(1e-6));
  CHECK(turned(driver_impact(), 10.0) == Approx(kClubSwing.finish).margin(1e-6));
}
