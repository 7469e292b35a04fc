// Ground contact (physics/ground.hpp): the bounce through the impact solver with the ground
// as an infinite mass, rolling resistance from a Stimpmeter reading (the USGA definition is
// the test), and the turf crater tilt.
#include <catch2/catch.hpp>

#include <cmath>

#include "physics/flight.hpp"
#include "physics/ground.hpp"
#include "physics/impact.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {

SurfaceMaterial rigid(double e, double mu) {
  SurfaceMaterial m = default_fairway();
  m.e = CorCurve::constant(e);
  m.mu = mu;
  m.crater_tilt = 0.0;
  m.layer_drag = 0.0;
  return m;
}

double ke(const BallProperties& b, const Vec3& v, const Vec3& w) {
  return 0.5 * b.mass * v.squaredNorm() + 0.5 * b.inertia * w.squaredNorm();
}

}  // namespace

TEST_CASE("a vertical drop rebounds at e times the impact speed, no spin made", "[ground][bounce]") {
  const BallProperties ball = golf_ball_properties();
  const BounceResult b = bounce_on_surface(rigid(0.6, 0.4), Vec3::UnitY(), Vec3(0, -5, 0), Vec3::Zero(), ball);
  CHECK(b.velocity.y() == Approx(3.0).epsilon(1e-12));
  CHECK(b.velocity.x() == Approx(0.0).margin(1e-12));
  CHECK(b.spin.norm() == Approx(0.0).margin(1e-9));
}

TEST_CASE("an oblique bounce that grips leaves the ball rolling (v = ωR) and loses energy", "[ground][bounce]") {
  // The worked friction case of DESIGN §3: a solid sphere at 10 m/s normal, 1 m/s tangential,
  // e = 0.5, µ = 0.4: it grips and leaves rolling at 5/7 of the tangential speed.
  const BallProperties ball = golf_ball_properties();
  const BounceResult b = bounce_on_surface(rigid(0.5, 0.4), Vec3::UnitY(), Vec3(1, -10, 0), Vec3::Zero(), ball);
  CHECK(b.impact.contact == ContactKind::Grip);
  CHECK(b.velocity.x() == Approx(5.0 / 7.0).epsilon(1e-9));
  CHECK(b.velocity.y() == Approx(5.0).epsilon(1e-9));
  // Rolling contact: the bottom of the ball is at rest, v + ω × (-R ŷ) has no x part.
  CHECK((b.velocity + b.spin.cross(-ball.radius * Vec3::UnitY())).x() == Approx(0.0).margin(1e-9));
  CHECK(ke(ball, b.velocity, b.spin) < ke(ball, Vec3(1, -10, 0), Vec3::Zero()));
}

TEST_CASE("the closed-form bounce is the impact solver's rigid Coulomb impulse with the ground as an infinite mass",
          "[ground][bounce][property]") {
  // bounce_on_surface solves the sphere-on-plane impulse by scalar formulas; the
  // general solver (physics/impact.cpp) is the reference: same contact kind, same velocity
  // and spin to rounding, over grip and slip, any spin, slope and restitution curve.
  const BallProperties ball = golf_ball_properties();
  std::uint64_t s = 11;
  auto u = [&s] {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  };
  int grips = 0, slips = 0;
  for (int i = 0; i < 20000; ++i) {
    SurfaceMaterial m = default_fairway();  // its speed-dependent e curve
    m.crater_tilt = 0.0;
    m.layer_drag = 0.0;  // the impulse alone: the layer's loss is checked on its own below
    m.mu = 1.5 * u();
    const Vec3 n = Vec3(0.6 * (u() - 0.5), 1.0, 0.6 * (u() - 0.5)).normalized();
    const Vec3 v(60.0 * (u() - 0.5), -30.0 * u() - 0.1, 60.0 * (u() - 0.5));
    const Vec3 w(800.0 * (u() - 0.5), 800.0 * (u() - 0.5), 800.0 * (u() - 0.5));
    if (v.dot(n) >= 0.0) continue;  // leaving the plane: no impact (bounce_on_surface returns it as is)
    ImpactInput in;
    in.impactor.inv_mass = 0.0;
    in.impactor.inv_inertia = Mat3::Zero();
    in.ball.inv_mass = 1.0 / ball.mass;
    in.ball.inv_inertia = Mat3::Identity() * (1.0 / ball.inertia);
    in.ball.r = -ball.radius * n;
    in.ball.velocity = v;
    in.ball.angular_velocity = w;
    in.normal = n;
    in.material.e = m.e;
    in.material.e_t = 0.0;
    in.material.mu = m.mu;
    in.material.friction = FrictionModel::Coulomb;
    in.material.model = ImpactModel::Rigid;
    const ImpactResult ref = solve_impact(in);
    const BounceResult b = bounce_on_surface(m, n, v, w, ball);
    INFO(i);
    REQUIRE(b.impact.contact == ref.contact);
    (ref.contact == ContactKind::Grip ? grips : slips) += 1;
    REQUIRE((b.velocity - ref.ball_after.velocity).norm() <= 1e-12 * (1.0 + v.norm()));
    REQUIRE((b.spin - ref.ball_after.angular_velocity).norm() <= 1e-12 * (1.0 + w.norm() + v.norm() / ball.radius));
    REQUIRE(b.impact.energy_loss == Approx(ref.energy_loss).epsilon(1e-9).margin(1e-12));
  }
  CHECK(grips > 1000);
  CHECK(slips > 1000);
}

TEST_CASE("bounces never create energy, whatever the spin, angle or surface", "[ground][bounce][property]") {
  const BallProperties ball = golf_ball_properties();
  std::uint64_t s = 7;
  auto u = [&s] {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < 20000; ++i) {
    SurfaceMaterial m = rigid(u(), 2.0 * u());
    m.crater_tilt = 0.6 * u();
    m.layer_drag = SurfaceMaterial::kLayerDrag.max * u() * u();
    const Vec3 n = Vec3(0.3 * (u() - 0.5), 1.0, 0.3 * (u() - 0.5)).normalized();
    const Vec3 v(60.0 * (u() - 0.5), -30.0 * u() - 0.1, 60.0 * (u() - 0.5));
    const Vec3 w(800.0 * (u() - 0.5), 800.0 * (u() - 0.5), 800.0 * (u() - 0.5));
    const double firmness = kFirmness.min + (kFirmness.max - kFirmness.min) * u();
    const BounceResult b = bounce_on_surface(m, n, v, w, ball, firmness);
    INFO(i);
    REQUIRE(ke(ball, b.velocity, b.spin) <= ke(ball, v, w) * (1 + 1e-12));
    // The energy the result reports lost is what was lost, the layer's share included.
    REQUIRE(b.impact.energy_loss ==
            Approx(ke(ball, v, w) - ke(ball, b.velocity, b.spin)).margin(1e-9 * (1.0 + ke(ball, v, w))));
  }
}

TEST_CASE("the turf's layer takes layer_drag · v_t² from a landing that presses through it",
          "[ground][bounce][layer]") {
  SurfaceMaterial m = rigid(0.3, 0.4);
  m.layer_drag = 0.01;  // s/m
  // Pressed through (v_n ≥ kTurfLayerSpeed): all of it; 20 m/s along loses 4 m/s.
  CHECK(layer_speed_loss(m, 20.0, 10.0) == Approx(4.0).epsilon(1e-12));
  CHECK(layer_speed_loss(m, 20.0, kTurfLayerSpeed) == Approx(4.0).epsilon(1e-12));
  // Quadratic in the speed along: the layer's mass is set moving at the ball's speed
  // (Poncelet's inertial term), so a landing at twice the speed loses four times as much.
  CHECK(layer_speed_loss(m, 10.0, 10.0) == Approx(1.0).epsilon(1e-12));
  // A lighter touch presses in as far as its normal energy: (v_n / kTurfLayerSpeed)².
  CHECK(layer_speed_loss(m, 20.0, 0.5 * kTurfLayerSpeed) == Approx(1.0).epsilon(1e-12));
  CHECK(layer_speed_loss(m, 20.0, 0.0) == 0.0);
  // A firmer turf is pressed less deep, as its crater: 1/√firmness.
  CHECK(layer_speed_loss(m, 20.0, 10.0, 4.0) == Approx(2.0).epsilon(1e-12));
  // Never more than half the speed along (the layer slows the ball, it does not stop it).
  CHECK(layer_speed_loss(m, 80.0, 10.0) == Approx(40.0).epsilon(1e-12));
  m.layer_drag = 0.0;
  CHECK(layer_speed_loss(m, 20.0, 10.0) == 0.0);

  // In a bounce the loss comes off the speed along the surface before the contact's friction
  // acts: a spinless ball at 21 m/s along and 10 m/s down, e 0.3, grips (µ 0.4 covers 2/7 of
  // the slip) and leaves rolling at 5/7 of the 21 − 4.41 m/s the layer leaves it.
  const BallProperties ball = golf_ball_properties();
  m.layer_drag = 0.01;
  const BounceResult b = bounce_on_surface(m, Vec3::UnitY(), Vec3(21, -10, 0), Vec3::Zero(), ball);
  CHECK(b.impact.contact == ContactKind::Grip);
  CHECK(b.velocity.x() == Approx(5.0 / 7.0 * (21.0 - 0.01 * 21.0 * 21.0)).epsilon(1e-9));
  CHECK(b.velocity.y() == Approx(3.0).epsilon(1e-9));
}

TEST_CASE("the layer's share grows continuously from a touch to a landing", "[ground][layer][property]") {
  // No step at any normal speed: a hop that barely leaves the ground and the roll it turns
  // into lose alike (the hop-or-roll sweep in test_world.cpp checks the rest it gives).
  double previous = 0.0;
  for (int i = 1; i <= 400; ++i) {
    const double vn = 0.01 * i;  // 0.01 .. 4 m/s
    const double share = turf_layer_share(vn);
    CHECK(share >= previous);
    CHECK(share - previous <= 2.0 * 0.01 / kTurfLayerSpeed + 1e-12);
    previous = share;
  }
  CHECK(turf_layer_share(4.0) == 1.0);
  CHECK(turf_layer_share(0.25) == Approx(0.015625));  // a roll's threshold touch: 1.6 %
}

TEST_CASE("the crater tilt: Penner's at his reference, linear in speed, none for a vertical drop",
          "[ground][crater]") {
  SurfaceMaterial green = default_fairway();
  green.crater_tilt = deg_to_rad(15.4);  // Penner 2002's green at 18.6 m/s, 44.4°
  green.layer_drag = 0.0;                // a green's bounce is Penner's crater alone
  const BallProperties ball = golf_ball_properties();
  const auto tilt = [&](double speed, double incidence_deg, double firmness = 1.0) {
    return rad_to_deg(crater_tilt_at(green, speed, deg_to_rad(incidence_deg), firmness));
  };
  CHECK(tilt(18.6, 44.4) == Approx(15.4).epsilon(1e-4));  // the reference impact
  CHECK(tilt(9.3, 44.4) == Approx(7.7).epsilon(1e-4));    // linear in speed
  // Penner's form is linear in incidence for shallow landings: sin 2θ ≈ 2θ.
  CHECK(tilt(18.6, 5.0) / tilt(18.6, 2.5) == Approx(2.0).epsilon(0.01));
  CHECK(tilt(18.6, 90.0) == Approx(0.0).margin(1e-9));    // a crater dug straight down is symmetric
  CHECK(tilt(60.0, 45.0) <= 2.0 * 15.4 + 1e-9);           // at most twice the reference
  CHECK(tilt(18.6, 44.4, 4.0) == Approx(7.7).epsilon(1e-4));  // 4x stiffer turf: half as deep
  // The bounce uses it, and never sends the ball into the ground.
  const double a = deg_to_rad(44.4);
  const BounceResult b = bounce_on_surface(green, Vec3::UnitY(), 18.6 * Vec3(std::cos(a), -std::sin(a), 0), Vec3::Zero(), ball);
  CHECK(rad_to_deg(std::acos(b.normal.dot(Vec3::UnitY()))) == Approx(15.4).epsilon(1e-4));
  CHECK(b.velocity.y() > 0.0);
}

TEST_CASE("a spinless ball never bounces backwards off flat ground; backspin can bring it back",
          "[ground][crater][property]") {
  // The crater's far wall can stop a ball, not throw it back (thrown back, a spinless 70°
  // landing at 26 m/s would come to rest 10 m behind where it landed).
  const BallProperties ball = golf_ball_properties();
  for (const SurfaceMaterial& m : test::assets().materials()) {
    if (m.kind == SurfaceKind::Water || m.kind == SurfaceKind::Decoration) continue;
    for (double speed : {2.0, 10.0, 26.0, 45.0}) {
      for (double deg = 5.0; deg < 90.0; deg += 5.0) {
        const double a = deg_to_rad(deg);
        const Vec3 v = speed * Vec3(std::cos(a), -std::sin(a), 0);
        INFO(m.name << " " << speed << " m/s at " << deg << " deg");
        CHECK(bounce_on_surface(m, Vec3::UnitY(), v, Vec3::Zero(), ball).velocity.x() >= -1e-9);
        CHECK(bounce_on_surface(m, Vec3::UnitY(), v, Vec3::Zero(), ball, 0.25).velocity.x() >= -1e-9);
      }
    }
  }
  // A wedge's backspin (9000 rpm, +z spins a ball moving +x backward) lands at 50° and
  // comes back on the green: Haake's receptive greens kept balls spinning back above ~3300 rpm.
  const SurfaceMaterial* green_ptr = nullptr;
  for (const SurfaceMaterial& m : test::assets().materials())
    if (m.kind == SurfaceKind::Green) green_ptr = &m;
  REQUIRE(green_ptr != nullptr);
  const SurfaceMaterial& green = *green_ptr;
  const double a = deg_to_rad(50.0);
  const BounceResult back = bounce_on_surface(green, Vec3::UnitY(), 20.0 * Vec3(std::cos(a), -std::sin(a), 0),
                                              Vec3(0, 0, rpm_to_radps(9000)), ball);
  CHECK(back.velocity.x() < 0.0);
}

TEST_CASE("a Stimpmeter ball released at 1.83 m/s rolls the reading on a flat green", "[ground][stimp]") {
  // USGA Stimpmeter: the ball leaves the ramp at 6 ft/s (1.83 m/s) rolling; the distance it
  // rolls on a flat green is the reading. 10.5 ft = 3.2 m.
  SurfaceMaterial green = default_fairway();
  green.name = "green";
  green.kind = SurfaceKind::Green;
  green.stimp = ft_to_m(10.5);
  CHECK(rolling_resistance_from_stimp(green.stimp) == Approx(1.83 * 1.83 / (2 * 9.80665 * 3.2004)).epsilon(1e-12));
  const FlatGround flat(green);
  test::FlightCase c;
  c.aero = &test::assets().aero("ferguson2022");
  c.launch.position = Vec3(0, c.ball.radius, 0);
  c.launch.velocity = Vec3(1.83, 0, 0);
  c.launch.spin = Vec3(0, 0, -1.83 / c.ball.radius);  // rolling forward
  const ShotTrajectory t = test::fly(c, &flat);
  CHECK(t.summary.end == EndReason::Rest);
  // The reading includes what the still air takes (rolling_resistance_from_stimp(stimp, k)):
  // the simulated roll, air and all, covers it.
  CHECK(t.summary.total_m == Approx(green.stimp).epsilon(0.005));
}

TEST_CASE("surface validation names the material, the field and its range", "[ground][input]") {
  SurfaceMaterial m = default_fairway();
  m.mu = 3.0;
  CHECK(validate_surface_material(m).find("material 'fairway': mu = 3 is out of range (allowed [0, 2])") !=
        std::string::npos);
  m = default_fairway();
  m.stimp = 10.0;
  CHECK(validate_surface_material(m).find("stimp") != std::string::npos);
  m = default_fairway();
  m.e.cor[1] = 1.5;
  CHECK(validate_surface_material(m).find("e = 1.5") != std::string::npos);
  CHECK(validate_surface_material(default_fairway()).empty());
}

TEST_CASE("a skidding ball on a side slope is pulled down it before it grips", "[ground][skid]") {
  // The slope acts on the ball in the skid as in the roll.
  const BallProperties ball = golf_ball_properties();
  auto side_drift = [&](double slope_deg) {
    struct Tilted final : Terrain {
      Vec3 n;
      SurfaceMaterial m = default_fairway();
      bool sweep(const Vec3& from, const Vec3& to, double radius, SurfaceContact* hit, const Vec3*) const override {
        const double d0 = n.dot(from) - radius, d1 = n.dot(to) - radius;
        if (d1 > 0.0 || d1 >= d0) return false;
        hit->fraction = d0 <= 0.0 ? 0.0 : d0 / (d0 - d1);
        const Vec3 c = from + hit->fraction * (to - from);
        hit->point = c - radius * n;
        hit->normal = n;
        hit->material = 0;
        return true;
      }
      bool support(const Vec3& centre, double radius, double reach, SurfaceContact* hit) const override {
        if (n.dot(centre) - radius > reach) return false;
        hit->point = centre - n.dot(centre) * n;
        hit->normal = n;
        hit->material = 0;
        return true;
      }
      bool may_touch(const Vec3&, const Vec3&, double) const override { return true; }
      bool may_touch_steep(const Vec3&, const Vec3&, double) const override { return false; }
      const SurfaceMaterial& material(int) const override { return m; }
      bool inside(const Vec3&) const override { return true; }
    } ground;
    const double a = deg_to_rad(slope_deg);
    ground.n = Vec3(0.0, std::cos(a), std::sin(a));  // y = -z tanθ: falls toward +z
    ShotModel model = test::golf_model(&ground);
    LaunchState l;
    l.position = ground.n * ball.radius;
    l.velocity = Vec3(3.0, 0.0, 0.0);
    ShotState s = start_state(l);
    while (!s.ended && s.phase != Phase::Roll) step(model, s);
    const double z0 = s.position().z();
    while (!s.ended && s.skidding) step(model, s);  // the skid (in chunks that follow the ground)
    return s.position().z() - z0;
  };
  CHECK(side_drift(0.0) == Approx(0.0).margin(1e-9));
  CHECK(side_drift(3.0) > 1e-3);  // pulled down the slope (+z) while it slides
}
