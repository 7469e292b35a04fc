// Delivery: swing (+ pitch) -> launch. Gear effect, bulge and roll, undercut, the bat's
// sweet spot: all from geometry and inertia fed to the impulse solver; these tests check
// the signs and sizes DESIGN §2/§3 promise, and momentum and energy on real deliveries.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "game/content/equipment_file.hpp"
#include "support/test_assets.hpp"
#include "physics/delivery.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {

const EquipmentCatalog& eq() { return test::assets().equipment(); }

Delivery golf(const char* club, GolfSwing s = {}) {
  const ClubSpec& c = eq().club(club);
  return deliver_golf(eq().ball("tour"), c, s, c.face);
}

Delivery bat_hit(const char* bat, BatSwing s = {}, Pitch p = {}) {
  const BatSpec& b = eq().bat(bat);
  return deliver_baseball(eq().ball("mlb"), b, s, p, b.material);
}

// Momentum and energy of the two bodies before and after a delivery's impact.
struct Balance {
  double dp_rel, dl_rel, energy_before, energy_after;
};
Balance balance(const Delivery& d) {
  const ImpactInput& in = d.impact_input;
  const ImpactResult& r = d.impact;
  const Vec3 contact = d.launch.position + in.ball.r;
  const Vec3 c1 = contact - in.impactor.r, c2 = d.launch.position;
  const double m1 = 1.0 / in.impactor.inv_mass, m2 = 1.0 / in.ball.inv_mass;
  const Mat3 i1 = in.impactor.inv_inertia.inverse(), i2 = in.ball.inv_inertia.inverse();
  auto p = [&](const ImpactBody& a, const ImpactBody& b) { return Vec3(m1 * a.velocity + m2 * b.velocity); };
  auto l = [&](const ImpactBody& a, const ImpactBody& b) {
    return Vec3(c1.cross(m1 * a.velocity) + i1 * a.angular_velocity + c2.cross(m2 * b.velocity) + i2 * b.angular_velocity);
  };
  auto ke = [&](const ImpactBody& a, const ImpactBody& b) {
    return 0.5 * m1 * a.velocity.squaredNorm() + 0.5 * a.angular_velocity.dot(i1 * a.angular_velocity) +
           0.5 * m2 * b.velocity.squaredNorm() + 0.5 * b.angular_velocity.dot(i2 * b.angular_velocity);
  };
  const Vec3 p0 = p(in.impactor, in.ball), p1 = p(r.impactor_after, r.ball_after);
  const Vec3 l0 = l(in.impactor, in.ball), l1 = l(r.impactor_after, r.ball_after);
  return {(p1 - p0).norm() / p0.norm(), (l1 - l0).norm() / (l0.norm() + c1.norm() * p0.norm()),
          ke(in.impactor, in.ball), ke(r.impactor_after, r.ball_after)};
}

}  // namespace

TEST_CASE("a square centre strike launches straight with backspin", "[delivery][golf]") {
  const Delivery d = golf("driver");
  const LaunchMetrics m = measure_launch(d.launch);
  CHECK(d.launch.position.y() == Approx(eq().ball("tour").radius));
  CHECK(std::abs(rad_to_deg(m.horizontal_angle)) < 0.5);
  CHECK(std::abs(rad_to_deg(m.spin.axis_rad)) < 3.0);  // only the CG's 1 mm toe offset and products of inertia tilt it
  CHECK(m.spin.backspin > 0.0);
  CHECK(m.vertical_angle > 0.0);
  CHECK(m.vertical_angle < eq().club("driver").dynamic_loft);  // friction pulls the launch below the face normal
  CHECK(d.smash_factor > 1.40);
  CHECK(d.smash_factor < 1.50);
  CHECK(d.impactor_speed == Approx(50.5).epsilon(1e-12));
  CHECK(d.impact.contact == ContactKind::Grip);
}

TEST_CASE("a frictionless centre strike leaves the ball without spin", "[delivery][golf]") {
  // Through the CG line of a symmetric face the frictionless impulse is along the normal
  // and passes through the ball's centre: no torque on the ball, whatever the loft.
  for (FrictionModel model : {FrictionModel::None, FrictionModel::Coulomb}) {
    const ClubSpec& c = eq().club("7-iron");
    ImpactMaterial m = c.face;
    m.friction = model;
    m.mu = 0.0;
    const Delivery d = deliver_golf(eq().ball("tour"), c, GolfSwing{}, m);
    CHECK(d.launch.spin.norm() < 1e-9);
    CHECK(d.launch.velocity.norm() > 30.0);
  }
}

TEST_CASE("gear effect: toe hooks, heel slices, high spins less", "[delivery][golf][gear]") {
  GolfSwing s;
  const LaunchMetrics centre = measure_launch(golf("driver", s).launch);
  s.impact_toe = 0.015;
  const LaunchMetrics toe = measure_launch(golf("driver", s).launch);
  s.impact_toe = -0.015;
  const LaunchMetrics heel = measure_launch(golf("driver", s).launch);
  s.impact_toe = 0.0;
  s.impact_up = 0.010;
  const LaunchMetrics high = measure_launch(golf("driver", s).launch);
  s.impact_up = -0.010;
  const LaunchMetrics low = measure_launch(golf("driver", s).launch);

  CHECK(rad_to_deg(toe.spin.axis_rad) < -5.0);   // hook spin
  CHECK(rad_to_deg(heel.spin.axis_rad) > 5.0);   // slice spin
  CHECK(toe.horizontal_angle > 0.0);             // bulge starts a toe hit right ...
  CHECK(heel.horizontal_angle < 0.0);            // ... and a heel hit left, to curve back
  CHECK(high.spin.backspin < centre.spin.backspin - rpm_to_radps(200));
  CHECK(low.spin.backspin > centre.spin.backspin + rpm_to_radps(200));
  CHECK(high.vertical_angle > centre.vertical_angle);  // roll tilts the normal up
  CHECK(toe.ball_speed < centre.ball_speed);            // off-centre hits lose ball speed
  CHECK(heel.ball_speed < centre.ball_speed);
}

TEST_CASE("gear effect comes from the CG depth, not from a hand-added term", "[delivery][golf][gear]") {
  // Same toe hit on a flat face: the spin axis tilt is all gear effect. Move the CG to the
  // face and the head no longer twists: the hook spin vanishes.
  ClubSpec flat = eq().club("driver");
  flat.bulge_radius = flat.roll_radius = 1000.0;
  GolfSwing s;
  s.impact_toe = 0.015;
  const double deep = measure_launch(deliver_golf(eq().ball("tour"), flat, s, flat.face).launch).spin.sidespin_right;
  ClubSpec shallow = flat;
  shallow.cg = Vec3(-0.0005, 0.0, 0.0);
  shallow.inertia = Mat3(Vec3(2843e-7, 5679e-7, 4085e-7).asDiagonal());
  s.impact_toe = 0.0;
  const double centre_shallow =
      measure_launch(deliver_golf(eq().ball("tour"), shallow, s, shallow.face).launch).spin.sidespin_right;
  s.impact_toe = 0.015;
  const double toe_shallow =
      measure_launch(deliver_golf(eq().ball("tour"), shallow, s, shallow.face).launch).spin.sidespin_right;
  CHECK(deep < -rpm_to_radps(300));  // hook from CG depth alone
  CHECK(std::abs(toe_shallow - centre_shallow) < 0.2 * std::abs(deep));
}

TEST_CASE("face and path set start direction and curve in TrackMan's sense", "[delivery][golf]") {
  GolfSwing s;
  s.face_angle = deg_to_rad(3);  // open to a straight path: starts right, slices
  const LaunchMetrics open = measure_launch(golf("7-iron", s).launch);
  CHECK(open.horizontal_angle > deg_to_rad(2.0));
  CHECK(open.spin.axis_rad > deg_to_rad(3.0));
  s.face_angle = 0;
  s.club_path = deg_to_rad(4);  // in-to-out with a square face: starts right, draws
  const LaunchMetrics out = measure_launch(golf("7-iron", s).launch);
  CHECK(out.horizontal_angle > 0.0);
  CHECK(out.spin.axis_rad < -deg_to_rad(3.0));
  s.club_path = 0;
  // Closure rate: the head turns about the shaft axis (rising toward the golfer at the
  // lie), + closing, i.e. about +y for a right-hander; the face angle AT impact is given,
  // so closure only changes what happens during the contact.
  s.closure_rate = 35.0;
  const Delivery closing = golf("driver", s);
  CHECK(closing.impactor_at_impact.angular_velocity.y() == Approx(35.0 * std::sin(eq().club("driver").lie)));
  CHECK(closing.impactor_at_impact.angular_velocity.z() < 0.0);  // shaft leans toward the golfer (-z)
  CHECK(closing.launch.spin != golf("driver").launch.spin);
  s.closure_rate = 0;
  s.attack_angle = deg_to_rad(5);  // hitting up lowers spin loft: less spin
  CHECK(measure_launch(golf("driver", s).launch).spin.backspin < measure_launch(golf("driver").launch).spin.backspin);
}

TEST_CASE("golf deliveries conserve momentum and never gain energy, every club", "[delivery][golf]") {
  for (const ClubSpec& c : eq().clubs) {
    for (double toe : {-0.02, 0.0, 0.02}) {
      for (double up : {-0.01, 0.0, 0.01}) {
        GolfSwing s;
        s.club_speed = 45.0;
        s.attack_angle = deg_to_rad(-3);
        s.impact_toe = toe;
        s.impact_up = up;
        s.closure_rate = 20.0;
        const Delivery d = deliver_golf(eq().ball("tour"), c, s, c.face);
        INFO(c.name << " toe " << toe << " up " << up);
        const Balance b = balance(d);
        CHECK(b.dp_rel < 1e-12);
        CHECK(b.dl_rel < 1e-12);
        CHECK(b.energy_after <= b.energy_before);
        CHECK(d.impact.energy_loss >= 0.0);
        CHECK_FALSE(d.impact.energy_limited);  // the safety net never fires on real clubs
        CHECK(d.launch.velocity.allFinite());
        CHECK(d.launch.spin.allFinite());
      }
    }
  }
}

TEST_CASE("the club pose is reported in the head (mesh) frame", "[delivery][golf]") {
  GolfSwing s;
  s.face_angle = deg_to_rad(2);
  const Delivery d = golf("driver", s);
  const ImpactorPose& p = d.impactor_at_impact;
  const Vec3 face_normal = p.orientation * Vec3::UnitX();
  CHECK(rad_to_deg(std::asin(face_normal.y())) == Approx(rad_to_deg(eq().club("driver").dynamic_loft)).margin(1e-9));
  CHECK(rad_to_deg(std::atan2(face_normal.z(), face_normal.x())) == Approx(2.0).margin(1e-9));
  // Centre strike: the face centre touches the ball one radius from its centre.
  CHECK((p.position + eq().ball("tour").radius * face_normal - d.launch.position).norm() < 1e-12);
  CHECK(p.velocity.norm() == Approx(s.club_speed));
}

TEST_CASE("bad swings are rejected naming the field and range", "[delivery][validation]") {
  GolfSwing s;
  s.club_speed = -5;
  CHECK_THROWS_WITH(golf("driver", s), Contains("swing.speed = -5 m/s is out of range (allowed (0, 90] m/s)"));
  s = GolfSwing{};
  s.impact_toe = 0.2;
  CHECK_THROWS_WITH(golf("driver", s), Contains("swing.impact_offset[0] (toe)") && Contains("[-0.05, 0.05] m"));
  s = GolfSwing{};
  s.dynamic_loft = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(golf("driver", s), Contains("swing.dynamic_loft"));
  s = GolfSwing{};
  s.attack_angle = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(golf("driver", s), Contains("swing.attack_angle"));
  ImpactMaterial m = eq().club("driver").face;
  m.mu = -1;
  CHECK_THROWS_WITH(deliver_golf(eq().ball("tour"), eq().club("driver"), GolfSwing{}, m), Contains("impact.mu"));
  BatSwing b;
  b.undercut = 0.2;
  CHECK_THROWS_WITH(bat_hit("maple", b), Contains("swing.undercut"));
  b = BatSwing{};
  b.impact_from_tip = 0.9;
  CHECK_THROWS_WITH(bat_hit("maple", b), Contains("swing.impact_from_tip"));
  Pitch p;
  p.speed = -1;
  CHECK_THROWS_WITH(bat_hit("maple", BatSwing{}, p), Contains("pitch.speed"));
}

// ---- baseball --------------------------------------------------------------------------

TEST_CASE("the pitch arrives along -x with backspin about -z", "[delivery][baseball]") {
  Pitch p;
  p.approach_angle = 0;
  const Delivery d = bat_hit("maple", BatSwing{}, p);
  CHECK(d.impact_input.ball.velocity.x() == Approx(-p.speed));
  CHECK(d.impact_input.ball.angular_velocity.z() == Approx(-p.spin));
  CHECK(d.launch.position.y() == Approx(kBaseballContactHeight));
}

TEST_CASE("undercut lifts the ball with backspin, overcut drives it down with topspin", "[delivery][baseball]") {
  BatSwing s;
  const LaunchMetrics square = measure_launch(bat_hit("maple", s).launch);
  s.undercut = 0.015;
  const LaunchMetrics under = measure_launch(bat_hit("maple", s).launch);
  s.undercut = -0.015;
  const LaunchMetrics over = measure_launch(bat_hit("maple", s).launch);
  CHECK(under.vertical_angle > square.vertical_angle + deg_to_rad(8));
  CHECK(under.spin.backspin > rpm_to_radps(1500));
  CHECK(over.vertical_angle < 0.0);
  CHECK(over.spin.backspin < -rpm_to_radps(1500));  // topspin
  s.undercut = 0;
  s.direction = deg_to_rad(20);
  CHECK(measure_launch(bat_hit("maple", s).launch).horizontal_angle > deg_to_rad(15));
}

TEST_CASE("exit speed peaks near the sweet spot and q is about 0.2 there", "[delivery][baseball]") {
  Pitch p;
  p.approach_angle = 0;
  p.spin = 0;
  BatSwing s;
  s.attack_angle = 0;
  auto exit_at = [&](const char* bat, double from_tip) {
    s.impact_from_tip = from_tip;
    return measure_launch(bat_hit(bat, s, p).launch).ball_speed;
  };
  for (const char* bat : {"maple", "bbcor"}) {
    INFO(bat);
    double best = 0, best_at = 0;
    for (double x = 0.0; x <= 0.45; x += 0.01) {
      if (exit_at(bat, x) > best) {
        best = exit_at(bat, x);
        best_at = x;
      }
    }
    CHECK(best_at >= 0.10);  // 4–8 in from the tip, around Statcast's 6 in
    CHECK(best_at <= 0.20);
    CHECK(exit_at(bat, 0.01) < best - mph_to_mps(8));   // falls toward the tip ...
    CHECK(exit_at(bat, 0.40) < best - mph_to_mps(20));  // ... and toward the hands
    s.impact_from_tip = eq().bat(bat).sweet_spot_from_tip;
    const Delivery d = bat_hit(bat, s, p);
    const double q = (measure_launch(d.launch).ball_speed - d.impactor_speed) / (p.speed + d.impactor_speed);
    CHECK(q > 0.15);
    CHECK(q < 0.25);
    CHECK(d.impactor_speed == Approx(s.bat_speed).epsilon(0.01));  // contact is on the surface, not the axis
  }
  s.impact_from_tip = 0.1524;
  // BBCOR bats perform at or below wood (certified to a wood-like COR, lighter).
  CHECK(exit_at("bbcor", 0.1524) <= exit_at("maple", 0.1524) + mph_to_mps(1.0));
  CHECK(exit_at("bbcor", 0.1524) > exit_at("maple", 0.1524) - mph_to_mps(12.0));
}

TEST_CASE("baseball deliveries conserve momentum and never gain energy", "[delivery][baseball]") {
  for (const char* bat : {"maple", "bbcor"}) {
    for (double from_tip : {0.02, 0.1524, 0.35}) {
      for (double undercut : {-0.03, 0.0, 0.03}) {
        BatSwing s;
        s.impact_from_tip = from_tip;
        s.undercut = undercut;
        const Delivery d = bat_hit(bat, s);
        INFO(bat << " " << from_tip << " " << undercut);
        const Balance b = balance(d);
        CHECK(b.dp_rel < 1e-12);
        CHECK(b.dl_rel < 1e-12);
        CHECK(b.energy_after <= b.energy_before);
        CHECK_FALSE(d.impact.energy_limited);
      }
    }
  }
}

TEST_CASE("the bat pose is reported in the bat (mesh) frame", "[delivery][baseball]") {
  const BatSpec& b = eq().bat("maple");
  BatSwing s;
  const Delivery d = bat_hit("maple", s);
  const ImpactorPose& p = d.impactor_at_impact;
  const Vec3 axis = p.orientation * Vec3::UnitX();
  CHECK(axis.z() > 0.95);  // knob toward the third-base side, tip toward first
  // The sweet spot moves at bat_speed; the knob end (near the pivot) barely moves.
  const Vec3 sweet = p.position + (b.length - b.sweet_spot_from_tip) * axis;
  const Vec3 v_sweet = p.velocity + p.angular_velocity.cross(sweet - p.position);
  CHECK(v_sweet.norm() == Approx(s.bat_speed).epsilon(1e-12));
  CHECK(p.velocity.norm() < 0.3 * s.bat_speed);
}

TEST_CASE("a glancing swing that cannot close on the ball is called a miss", "[delivery][baseball][soak]") {
  // Found by the soak (shot 53): the bat swung almost sideways (87°), struck near the hands
  // where it moves slowly, 36 mm under the ball's centre, with the pitch rising at it. The
  // contact point does not close, which used to surface as the solver's "bodies are
  // separating"; a player needs to hear that the strike misses.
  BatSwing s;
  s.bat_speed = 11.2134;
  s.attack_angle = -0.08988;
  s.direction = 1.51427;
  s.impact_from_tip = 0.56017;
  s.undercut = 0.03571;
  Pitch p;
  p.speed = 49.0;  // the soak had 50.27 m/s, since refused: pitches are at most 110 mph
  p.approach_angle = -0.23809;
  p.spin = 86.55;
  p.spin_axis = 0.0745;
  CHECK_THROWS_WITH(bat_hit("maple", s, p), Contains("the strike misses") && Contains("closing speed"));
  // Squared up, the same slow swing near the hands makes (weak) contact.
  s.direction = 0.0;
  s.undercut = 0.0;
  CHECK_NOTHROW(bat_hit("maple", s, p));
}
