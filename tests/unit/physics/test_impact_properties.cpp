// Property tests of the impulse solver (DESIGN §3 invariants) on 10⁵ seeded random impacts,
// and its input validation.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "physics/error.hpp"
#include "physics/impact.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {

struct CaseRng {
  std::mt19937_64 gen;
  explicit CaseRng(std::uint64_t seed) : gen(seed) {}
  double uniform(double a, double b) { return a + (b - a) * std::generate_canonical<double, 53>(gen); }
  // One draw a statement: a constructor's arguments are evaluated in an unspecified order.
  Vec3 vec(double scale) {
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = uniform(-scale, scale);
    return v;
  }
  Eigen::Vector4d vec4() {
    Eigen::Vector4d v;
    for (int i = 0; i < 4; ++i) v[i] = uniform(-1, 1);
    return v;
  }
  Vec3 unit() {
    for (;;) {
      const Vec3 v = vec(1.0);
      const double n = v.norm();
      if (n > 0.1 && n <= 1.0) return v / n;
    }
  }
  Quat rotation() {
    Eigen::Vector4d q = vec4();
    while (q.norm() < 0.1) q = vec4();
    q.normalize();
    return Quat(q(0), q(1), q(2), q(3));
  }
  // A physical inertia tensor: principal moments of a random mass distribution (they obey
  // the triangle inequality) in randomly rotated principal axes.
  Mat3 inertia(double mass, double size) {
    const double a = uniform(0.05, 1.0), b = uniform(0.05, 1.0), c = uniform(0.05, 1.0);
    const double s = mass * size * size;
    const Vec3 principal(s * (b + c), s * (a + c), s * (a + b));
    const Mat3 r = rotation().toRotationMatrix();
    return r * principal.asDiagonal() * r.transpose();
  }
};

// One random two-body impact with its world-frame geometry kept for momentum checks.
struct Case {
  ImpactInput in;
  double m1 = 0, m2 = 0;
  Mat3 i1, i2;       // inertia tensors (not inverses), world
  Vec3 c1, c2;       // CG positions, world
};

Case random_case(CaseRng& rng, FrictionModel model) {
  for (;;) {
    Case c;
    c.m1 = std::exp(rng.uniform(std::log(0.02), std::log(5.0)));
    c.m2 = std::exp(rng.uniform(std::log(0.02), std::log(5.0)));
    c.i1 = rng.inertia(c.m1, rng.uniform(0.01, 0.3));
    c.i2 = rng.inertia(c.m2, rng.uniform(0.01, 0.3));
    const Vec3 contact = rng.vec(2.0);
    c.in.normal = rng.unit();
    // CGs: each body on its own side of the contact plane, anywhere within its size.
    c.c1 = contact - rng.uniform(0.005, 0.2) * c.in.normal + rng.vec(0.1);
    c.c2 = contact + rng.uniform(0.005, 0.2) * c.in.normal + rng.vec(0.1);
    c.in.impactor.inv_mass = 1.0 / c.m1;
    c.in.ball.inv_mass = 1.0 / c.m2;
    c.in.impactor.inv_inertia = c.i1.inverse();
    c.in.ball.inv_inertia = c.i2.inverse();
    c.in.impactor.r = contact - c.c1;
    c.in.ball.r = contact - c.c2;
    c.in.impactor.velocity = rng.vec(60.0);
    c.in.ball.velocity = rng.vec(60.0);
    c.in.impactor.angular_velocity = rng.vec(100.0);
    c.in.ball.angular_velocity = rng.vec(400.0);
    c.in.material.e = CorCurve::constant(rng.uniform(0.0, 1.0));
    c.in.material.e_t = rng.uniform(0.0, 1.0);
    c.in.material.mu = rng.uniform(0.0, 1.2);
    c.in.material.friction = model;
    if (contact_velocity(c.in.impactor, c.in.ball).dot(c.in.normal) < -0.1) return c;
  }
}

Vec3 linear_momentum(const Case& c, const ImpactBody& b1, const ImpactBody& b2) {
  return c.m1 * b1.velocity + c.m2 * b2.velocity;
}

Vec3 angular_momentum(const Case& c, const ImpactBody& b1, const ImpactBody& b2, const Vec3& o) {
  return (c.c1 - o).cross(c.m1 * b1.velocity) + c.i1 * b1.angular_velocity +
         (c.c2 - o).cross(c.m2 * b2.velocity) + c.i2 * b2.angular_velocity;
}

double energy(const Case& c, const ImpactBody& b1, const ImpactBody& b2) {
  return 0.5 * c.m1 * b1.velocity.squaredNorm() + 0.5 * b1.angular_velocity.dot(c.i1 * b1.angular_velocity) +
         0.5 * c.m2 * b2.velocity.squaredNorm() + 0.5 * b2.angular_velocity.dot(c.i2 * b2.angular_velocity);
}

ImpactInput rotated(const ImpactInput& in, const Mat3& r) {
  ImpactInput out = in;
  for (ImpactBody* b : {&out.impactor, &out.ball}) {
    b->inv_inertia = r * b->inv_inertia * r.transpose();
    b->r = r * b->r;
    b->velocity = r * b->velocity;
    b->angular_velocity = r * b->angular_velocity;
  }
  out.normal = (r * in.normal).normalized();
  return out;
}

bool all_finite(const ImpactResult& r) {
  return r.impulse.allFinite() && std::isfinite(r.energy_loss) && r.ball_after.velocity.allFinite() &&
         r.ball_after.angular_velocity.allFinite() && r.impactor_after.velocity.allFinite() &&
         r.impactor_after.angular_velocity.allFinite();
}

}  // namespace

TEST_CASE("10^5 random impacts keep momentum, never gain energy, and are frame independent",
          "[impact][property]") {
  for (FrictionModel model : {FrictionModel::None, FrictionModel::Coulomb}) {
    CaseRng rng(model == FrictionModel::None ? 20261123u : 777u);
    int failures_p = 0, failures_l = 0, failures_e = 0, failures_rot = 0, failures_grip = 0;
    int nonfinite = 0, grips = 0, slips = 0, limited = 0;
    double worst_p = 0, worst_l = 0, worst_rot = 0;
    constexpr int kCases = 50000;  // per model: 10⁵ in all
    for (int i = 0; i < kCases; ++i) {
      const Case c = random_case(rng, model);
      REQUIRE(validate_impact(c.in).empty());
      const ImpactResult r = solve_impact(c.in);
      if (!all_finite(r)) {
        ++nonfinite;
        continue;
      }
      if (r.contact == ContactKind::Grip) ++grips;
      if (r.contact == ContactKind::Slip) ++slips;
      if (r.energy_limited) ++limited;

      // Linear momentum, relative to the momentum scale of the impact.
      const Vec3 p0 = linear_momentum(c, c.in.impactor, c.in.ball);
      const Vec3 p1 = linear_momentum(c, r.impactor_after, r.ball_after);
      const double p_scale = c.m1 * c.in.impactor.velocity.norm() + c.m2 * c.in.ball.velocity.norm() + r.impulse.norm();
      const double dp = (p1 - p0).norm() / p_scale;
      worst_p = std::max(worst_p, dp);
      if (dp > 1e-12) ++failures_p;

      // Angular momentum about an arbitrary fixed point.
      const Vec3 o = rng.vec(3.0);
      const Vec3 l0 = angular_momentum(c, c.in.impactor, c.in.ball, o);
      const Vec3 l1 = angular_momentum(c, r.impactor_after, r.ball_after, o);
      const double l_scale = (c.c1 - o).norm() * c.m1 * c.in.impactor.velocity.norm() +
                             (c.c2 - o).norm() * c.m2 * c.in.ball.velocity.norm() +
                             (c.i1 * c.in.impactor.angular_velocity).norm() +
                             (c.i2 * c.in.ball.angular_velocity).norm() + 5.0 * r.impulse.norm();
      const double dl = (l1 - l0).norm() / l_scale;
      worst_l = std::max(worst_l, dl);
      if (dl > 1e-9) ++failures_l;

      // Kinetic energy never increases (round-off allowance relative to the energy).
      const double e0 = energy(c, c.in.impactor, c.in.ball), e1 = energy(c, r.impactor_after, r.ball_after);
      if (e1 > e0 * (1.0 + 1e-10)) ++failures_e;
      if (std::abs((e0 - e1) - r.energy_loss) > 1e-8 * e0) ++failures_e;

      // Grip leaves the tangential contact velocity at −e_t·u_t and separates at −e·un.
      if (r.contact == ContactKind::Grip && !r.energy_limited) {
        const Vec3 u0 = contact_velocity(c.in.impactor, c.in.ball);
        const Vec3 u1 = contact_velocity(r.impactor_after, r.ball_after);
        const Vec3 n = c.in.normal;
        const Vec3 want = -r.e_t_used * (u0 - u0.dot(n) * n) - r.e_used * u0.dot(n) * n;
        if ((u1 - want).norm() > 1e-9 * u0.norm()) ++failures_grip;
      }

      // Same physics in a randomly rotated frame.
      const Mat3 rot = rng.rotation().toRotationMatrix();
      const ImpactResult rr = solve_impact(rotated(c.in, rot));
      const double drot = (rr.impulse - rot * r.impulse).norm() / (r.impulse.norm() + 1e-300);
      worst_rot = std::max(worst_rot, drot);
      if (drot > 1e-9) ++failures_rot;
    }
    INFO("model " << to_string(model) << ": grip " << grips << ", slip " << slips << ", energy-limited "
                  << limited << "; worst |dP|/P " << worst_p << ", |dL|/L " << worst_l << ", rotation "
                  << worst_rot);
    CHECK(nonfinite == 0);
    CHECK(failures_p == 0);
    CHECK(failures_l == 0);
    CHECK(failures_e == 0);
    CHECK(failures_grip == 0);
    CHECK(failures_rot == 0);
    if (model == FrictionModel::Coulomb) {
      // Both branches are exercised, and the energy limiter is a rare safety net.
      CHECK(grips > kCases / 10);
      CHECK(slips > kCases / 10);
      CHECK(limited < kCases / 20);
    } else {
      CHECK(limited == 0);
    }
  }
}

TEST_CASE("coulomb grip on a sphere leaves the tangential velocity at -e_t·u_t", "[impact][friction]") {
  // Ball onto an immovable plane: K is isotropic in the tangent plane, so nothing limits.
  for (double et : {0.0, 0.2, 0.5, 1.0}) {
    ImpactInput in;
    const double m = 0.0459, R = 0.0213;
    in.ball.inv_mass = 1.0 / m;
    in.ball.inv_inertia = solid_sphere_inertia(m, R).inverse();
    in.ball.r = Vec3(0, -R, 0);
    in.ball.velocity = Vec3(3, -10, 1);
    in.normal = Vec3(0, 1, 0);
    in.material.e = CorCurve::constant(0.6);
    in.material.e_t = et;
    in.material.mu = 0.8;
    const auto r = solve_impact_checked(in);
    REQUIRE(r.contact == ContactKind::Grip);
    CHECK_FALSE(r.energy_limited);
    const Vec3 u1 = contact_velocity(r.impactor_after, r.ball_after);
    CHECK(u1.x() == Approx(-et * 3.0).margin(1e-12));
    CHECK(u1.z() == Approx(-et * 1.0).margin(1e-12));
    CHECK(u1.y() == Approx(6.0).epsilon(1e-12));
    CHECK(r.energy_loss >= 0.0);
  }
}

TEST_CASE("slip takes friction at its limit and is continuous at the grip boundary", "[impact][friction]") {
  ImpactInput in;
  const double m = 1.0, R = 0.1;
  in.ball.inv_mass = 1.0 / m;
  in.ball.inv_inertia = solid_sphere_inertia(m, R).inverse();
  in.ball.r = Vec3(0, -R, 0);
  in.ball.velocity = Vec3(8, -10, 0);
  in.normal = Vec3(0, 1, 0);
  in.material.e = CorCurve::constant(0.5);
  in.material.mu = 0.1;
  const auto slip = solve_impact_checked(in);
  REQUIRE(slip.contact == ContactKind::Slip);
  CHECK(slip.tangential_impulse == Approx(0.1 * slip.normal_impulse).epsilon(1e-12));
  CHECK(slip.ball_after.velocity.y() == Approx(5.0).epsilon(1e-12));
  CHECK(slip.impulse.x() < 0.0);  // opposes the sliding
  // Grip needs p_t/p_n = (8/3.5)/15 = 0.15238...; just above and below give the same impulse.
  const double mu_c = (8.0 / 3.5) / 15.0;
  in.material.mu = mu_c * (1 + 1e-9);
  const auto a = solve_impact_checked(in);
  in.material.mu = mu_c * (1 - 1e-9);
  const auto b = solve_impact_checked(in);
  CHECK(a.contact == ContactKind::Grip);
  CHECK(b.contact == ContactKind::Slip);
  CHECK((a.impulse - b.impulse).norm() < 1e-7);
}

TEST_CASE("speed-dependent restitution is read at the normal approach speed", "[impact]") {
  CorCurve c;
  c.count = 3;
  c.speed = {10.0, 40.0, 60.0};
  c.cor = {0.9, 0.8, 0.7};
  CHECK(c.at(0.0) == 0.9);
  CHECK(c.at(25.0) == Approx(0.85).epsilon(1e-14));
  CHECK(c.at(50.0) == Approx(0.75).epsilon(1e-14));
  CHECK(c.at(100.0) == 0.7);
  ImpactInput in;
  in.impactor.inv_mass = 1.0 / 5.0;
  in.impactor.velocity = Vec3(25, 0, 0);
  in.ball.inv_mass = 1.0 / 0.1;
  in.material.e = c;
  in.material.friction = FrictionModel::None;
  const auto r = solve_impact_checked(in);
  CHECK(r.e_used == Approx(0.85).epsilon(1e-14));
  CHECK(r.ball_after.velocity.x() - r.impactor_after.velocity.x() == Approx(0.85 * 25.0).epsilon(1e-12));
}

// ---- validation: every bad input gives a clear message, never a NaN -----------------
namespace {
ImpactInput valid_input() {
  ImpactInput in;
  in.impactor.inv_mass = 1.0 / 0.2;
  in.impactor.inv_inertia = Mat3(Vec3(3e-4, 5e-4, 4e-4).asDiagonal()).inverse();
  in.impactor.r = Vec3(0.04, 0.0, 0.0);
  in.impactor.velocity = Vec3(50, 0, 0);
  in.ball.inv_mass = 1.0 / 0.0459;
  in.ball.inv_inertia = solid_sphere_inertia(0.0459, 0.0213).inverse();
  in.ball.r = Vec3(-0.0213, 0, 0);
  return in;
}
}  // namespace

TEST_CASE("bad impact inputs are rejected with a message naming the field", "[impact][validation]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  REQUIRE(validate_impact(valid_input()).empty());
  auto expect = [](const ImpactInput& in, const std::string& words) {
    const std::string msg = validate_impact(in);
    INFO(msg);
    CHECK_THAT(msg, Contains(words));
    CHECK_THROWS_AS(solve_impact_checked(in), InputError);
  };
  ImpactInput in = valid_input();
  in.ball.inv_mass = -1.0;
  expect(in, "ball: mass must be > 0");
  in = valid_input();
  in.impactor.inv_mass = std::numeric_limits<double>::infinity();  // mass 0
  expect(in, "impactor: mass must be > 0");
  in = valid_input();
  in.impactor.inv_inertia(0, 1) = 100.0;
  expect(in, "symmetric");
  in = valid_input();
  in.impactor.inv_inertia(2, 2) = -1.0;
  expect(in, "positive definite");
  in = valid_input();
  in.material.e = CorCurve::constant(1.2);
  expect(in, "impact.e = 1.2 is out of range (allowed [0, 1])");
  in = valid_input();
  in.material.e = CorCurve::constant(-0.1);
  expect(in, "impact.e");
  in = valid_input();
  in.material.e_t = 1.5;
  expect(in, "impact.e_t = 1.5 is out of range (allowed [0, 1])");
  in = valid_input();
  in.material.mu = -0.2;
  expect(in, "impact.mu = -0.2 is out of range (allowed [0, 2])");
  in = valid_input();
  in.normal = Vec3(1, 0.1, 0);
  expect(in, "unit vector");
  in = valid_input();
  in.impactor.velocity = Vec3(-5, 0, 0);
  expect(in, "separating");
  in = valid_input();
  in.impactor.velocity = Vec3::Zero();
  expect(in, "separating");  // touching at rest: nothing to solve
  in = valid_input();
  in.impactor.inv_mass = 0.0;
  in.impactor.inv_inertia.setZero();
  in.ball.inv_mass = 0.0;
  in.ball.inv_inertia.setZero();
  expect(in, "at least one body");
  // NaN anywhere
  in = valid_input();
  in.ball.velocity.x() = nan;
  expect(in, "finite");
  in = valid_input();
  in.normal.y() = nan;
  expect(in, "unit vector");
  in = valid_input();
  in.material.e = CorCurve::constant(nan);
  expect(in, "impact.e");
  in = valid_input();
  in.material.mu = nan;
  expect(in, "impact.mu");
  in = valid_input();
  in.material.e_t = nan;
  expect(in, "impact.e_t");
  in = valid_input();
  in.impactor.inv_mass = nan;
  expect(in, "mass");
  in = valid_input();
  in.material.e.count = 2;
  in.material.e.speed = {30.0, 20.0};
  in.material.e.cor = {0.8, 0.7};
  expect(in, "strictly increasing");
}

TEST_CASE("mass properties are validated where bodies are built", "[impact][validation]") {
  RigidBody b;
  b.mass = 0.2;
  b.inertia_body = Mat3(Vec3(3e-4, 5e-4, 4e-4).asDiagonal());
  CHECK(validate_mass_properties(b.mass, b.inertia_body, "club").empty());
  CHECK_THAT(validate_mass_properties(0.0, b.inertia_body, "club"), Contains("club.mass: must be > 0"));
  CHECK_THAT(validate_mass_properties(-1.0, b.inertia_body, "club"), Contains("club.mass"));
  Mat3 asym = b.inertia_body;
  asym(0, 2) = 1e-4;
  CHECK_THAT(validate_mass_properties(0.2, asym, "club"), Contains("club.inertia: the tensor must be symmetric"));
  Mat3 indefinite = b.inertia_body;
  indefinite(0, 1) = indefinite(1, 0) = 6e-4;
  CHECK_THAT(validate_mass_properties(0.2, indefinite, "club"), Contains("positive definite"));
  b.mass = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(make_impact_body(b, Vec3::Zero(), "bat"), Contains("bat.mass"));
  b.mass = 0.2;
  b.position = Vec3(-0.04, 0.01, 0);
  b.velocity = Vec3(50, 0, 0);
  const ImpactBody ib = make_impact_body(b, Vec3::Zero(), "club");
  CHECK(ib.inv_mass == Approx(5.0));
  CHECK((ib.r - Vec3(0.04, -0.01, 0)).norm() < 1e-15);
  CHECK((ib.inv_inertia * b.inertia_body - Mat3::Identity()).norm() < 1e-12);
}
