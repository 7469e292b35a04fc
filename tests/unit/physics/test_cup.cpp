// The hole (physics/cup.hpp): Holmes's capture speeds, lip-outs, the flagstick, and a putt
// that drops on a flat Stimpmeter green.
#include <catch2/catch.hpp>

#include <cmath>

#include "physics/cup.hpp"
#include "physics/flight.hpp"
#include "physics/ground.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

constexpr double kBallR = 0.021335;  // golf ball radius

SurfaceMaterial stimp_green(double feet) {
  SurfaceMaterial g = default_fairway();
  g.name = "green";
  g.kind = SurfaceKind::Green;
  g.stimp = ft_to_m(feet);
  return g;
}

// A ball rolling (already gripping) along +x toward a hole `distance` m away, `offset` m to the
// side, arriving at about `arrive` m/s on a flat 10 ft green. Returns the shot's end.
EndReason putt(double arrive, double offset, bool flagstick, double distance = 2.0) {
  static const FlatGround green(stimp_green(10.0));
  ShotModel model = test::golf_model(&green);
  Cup cup;
  cup.centre = Vec3(distance, 0.0, offset);
  cup.flagstick = flagstick;
  model.cup = cup;
  // Constant deceleration a (air included in the reading): v0² = v² + 2 a d.
  const double a = rolling_resistance_from_stimp(ft_to_m(10.0)) * kGravity;
  const double v0 = std::sqrt(arrive * arrive + 2.0 * a * distance);
  LaunchState l;
  l.position = Vec3(0.0, kBallR, 0.0);
  l.velocity = Vec3(v0, 0.0, 0.0);
  l.spin = Vec3(0.0, 0.0, -v0 / kBallR);  // rolling
  ShotState s = start_state(l);
  while (!s.ended) step(model, s);
  return s.end;
}

}  // namespace

TEST_CASE("Holmes's capture speeds: 1.31 m/s through the centre, falling to 0 at the rim", "[cup]") {
  // Holmes, Am. J. Phys. 59 (1991): a centred ball drops if slower than 1.31 m/s (4.3 ft/s)
  // on a 4.25 in hole.
  const Cup cup;
  CHECK(cup_capture_speed(cup, kBallR, 0.0) == Approx(1.31).epsilon(0.01));
  double last = 10.0;
  for (double b = 0.0; b < cup.radius; b += 0.005) {
    const double v = cup_capture_speed(cup, kBallR, b);
    CHECK(v <= last);
    last = v;
  }
  CHECK(cup_capture_speed(cup, kBallR, cup.radius) == 0.0);
  CHECK(cup_capture_speed(cup, kBallR, 0.06) == 0.0);  // outside the hole
}

TEST_CASE("a rolling putt drops below the capture speed and rides over above it", "[cup]") {
  CHECK(putt(1.20, 0.0, false) == EndReason::InCup);
  CHECK(putt(1.45, 0.0, false) != EndReason::InCup);
  CHECK(putt(0.30, 0.0, false) == EndReason::InCup);
  // 30 mm off line: the chord is shorter, the capture speed lower.
  CHECK(putt(0.60, 0.030, false) == EndReason::InCup);
  CHECK(putt(1.20, 0.030, false) != EndReason::InCup);
  // Past the rim: never.
  CHECK(putt(0.50, 0.060, false) != EndReason::InCup);
}

TEST_CASE("the hole judges the speed a putt arrives with, whatever its length", "[cup]") {
  // A roll step is up to 0.5 m long; judged with the speed at the step's start, up to
  // 0.15 m/s faster than at the rim on a 10 ft green, whether a putt drops would depend on
  // where its steps fall. Holmes's centred capture speed is 1.31 m/s (4 mm of
  // the ball's path and ~1 % of its speed before the rim's circle are not resolved). Putts up
  // to 3.4 m: `putt` sets the start speed for a constant deceleration, and the air's share,
  // which grows with speed, slows a longer (faster) putt more than that.
  for (const double distance : {0.4, 0.9, 1.7, 2.6, 3.35}) {
    INFO("putt of " << distance << " m");
    CHECK(putt(1.25, 0.0, false, distance) == EndReason::InCup);
    CHECK(putt(1.37, 0.0, false, distance) != EndReason::InCup);
  }
}

TEST_CASE("the flagstick stops a firm centred putt; a glancing one is turned aside", "[cup]") {
  // Pelz (1990): with the stick in, more putts were holed (it absorbs speed); Mase (2019):
  // the stick hurts putts that strike it off-centre.
  CHECK(putt(1.8, 0.0, false) != EndReason::InCup);
  CHECK(putt(1.8, 0.0, true) == EndReason::InCup);
  CHECK(putt(1.0, 0.020, false) == EndReason::InCup);
  CHECK(putt(1.0, 0.020, true) != EndReason::InCup);
}

TEST_CASE("a putt skids, then rolls at 5/7 of its speed", "[cup][skid]") {
  // A ball struck without spin slides until v = 5/7 v0 whatever µ (solid sphere, I = 2/5 mR²),
  // over 12 v0² / (49 µ g).
  const FlatGround green(stimp_green(10.0));
  ShotModel model = test::golf_model(&green);
  LaunchState l;
  l.position = Vec3(0.0, kBallR, 0.0);
  l.velocity = Vec3(2.0, 0.0, 0.0);
  ShotState s = start_state(l);
  ShotEvent ev;
  do {
    ev = step(model, s);
  } while (!s.ended && s.phase != Phase::Roll);
  REQUIRE(s.phase == Phase::Roll);
  while (!s.ended && s.skidding) step(model, s);  // the skid (in chunks that follow the ground)
  CHECK(s.velocity().norm() == Approx(5.0 / 7.0 * 2.0).epsilon(1e-3));
  const double mu = default_fairway().mu;
  CHECK(s.position().x() == Approx(12.0 * 4.0 / (49.0 * mu * kGravity)).epsilon(0.01));
}

namespace {

// The hole at the origin on a flat green (+y up); a ball rolling along +x, its centre passing
// `offset` m to the +z side of the hole's axis at `speed` m/s.
CupPass lip(double offset, double speed) {
  const Cup cup;
  return pass_over_cup(cup, kBallR, Vec3(-0.2, kBallR, offset), Vec3(0.2, kBallR, offset), Vec3(speed, 0.0, 0.0),
                       Vec3::UnitY());
}

double turn_deg(const CupPass& p) { return rad_to_deg(std::atan2(p.velocity.z(), p.velocity.x())); }

}  // namespace

TEST_CASE("a lip-out turns the ball round the hole, toward its middle, the more the slower it comes", "[cup]") {
  // Hogan & Antali (R. Soc. Open Sci. 2025): a lipping ball is turned around the rim, toward
  // the side of the hole it did not pass on. Past Holmes's capture speed it tips over the far
  // edge: its angular momentum about the edge is kept, so it turns the more the farther round
  // it meets the edge (off centre) and the slower it comes, and the blow never adds speed.
  for (const double offset : {0.015, 0.030, 0.045}) {
    const double capture = cup_capture_speed(Cup{}, kBallR, offset);
    double last_turn = -1.0;
    for (const double speed : {4.0, 2.5, 1.8, 1.4}) {
      if (speed <= capture) continue;
      INFO("offset " << offset << " m, " << speed << " m/s (capture " << capture << ")");
      const CupPass p = lip(offset, speed);
      REQUIRE(p.kind == CupPass::Kind::LipOut);
      CHECK(p.velocity.z() < 0.0);                         // toward the middle (-z), never away
      CHECK(p.velocity.x() > 0.0);                         // on over the hole
      CHECK(p.velocity.norm() <= speed * (1.0 + 1e-12));   // no speed from the rim
      const double turn = -turn_deg(p);
      CHECK(turn >= last_turn - 1e-9);                     // slower: turned more
      last_turn = turn;
      // The mirror image lips out the mirror way.
      const CupPass m = lip(-offset, speed);
      CHECK(m.velocity.z() == Approx(-p.velocity.z()).margin(1e-12));
      CHECK(m.velocity.x() == Approx(p.velocity.x()).margin(1e-12));
    }
  }
  // Through the middle it goes straight on, slowed by the blow on the far edge: just past the
  // capture speed it barely tips over; at 4 m/s it keeps most of its speed.
  const CupPass slow = lip(0.0, 1.4), fast = lip(0.0, 4.0);
  REQUIRE(slow.kind == CupPass::Kind::LipOut);
  REQUIRE(fast.kind == CupPass::Kind::LipOut);
  CHECK(slow.velocity.z() == Approx(0.0).margin(1e-12));
  CHECK(slow.velocity.norm() < 0.3);
  CHECK(fast.velocity.norm() > 0.8 * 4.0);
  CHECK(fast.velocity.norm() < 4.0);
}

TEST_CASE("a glancing putt rides the rim: it drops when slow, is flung out round the hole when faster", "[cup]") {
  // Coming in toward the axis slower than sqrt(g r) the ball rolls onto the edge and rides
  // it (Hogan & Antali's rim lip-out): gravity tips it in, its turn round the hole flings it
  // out. On the rim it rolls without slipping and keeps its energy: it leaves at its speed.
  const CupPass in = lip(0.048, 0.30);
  CHECK(in.kind == CupPass::Kind::Holed);
  const CupPass out = lip(0.048, 0.45);
  REQUIRE(out.kind == CupPass::Kind::LipOut);
  CHECK(out.velocity.norm() == Approx(0.45).epsilon(1e-3));
  CHECK(-turn_deg(out) > 30.0);  // turned well round, toward the middle
  CHECK(out.time_on_rim > 0.1);
  // It leaves from the rim, round from where it came on: farther along and nearer the middle.
  CHECK(out.leave_offset.z() < 0.0);
  // Faster, the same line is barely turned.
  const CupPass quick = lip(0.048, 1.1);
  REQUIRE(quick.kind == CupPass::Kind::LipOut);
  CHECK(-turn_deg(quick) < -turn_deg(out));
  CHECK(-turn_deg(quick) > 0.0);
}
