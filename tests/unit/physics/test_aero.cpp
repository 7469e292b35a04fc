// Aero models are the published formulas, selectable by name.
#include <catch2/catch.hpp>

#include <cmath>

#include "physics/aero.hpp"
#include "physics/atmosphere.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

TEST_CASE("ferguson2022 coefficients are the published quadratics", "[aero]") {
  const AeroModel& m = test::assets().aero("ferguson2022");
  const AeroCoefficients c = m.coefficients(0.1, 0.0);
  CHECK(c.cd == Approx(0.1304 + 0.09287 - 0.008259).epsilon(1e-12));
  CHECK(c.cl == Approx(0.0504 + 0.12031 - 0.011490).epsilon(1e-12));
  // Held at the top of the fit range instead of turning over.
  CHECK(m.coefficients(0.9, 0.0).cl == Approx(m.coefficients(m.s_max, 0.0).cl));
}

TEST_CASE("smits_smith1994 and nathan coefficients", "[aero]") {
  const AeroCoefficients s = test::assets().aero("smits_smith1994").coefficients(0.15, 0.0);
  CHECK(s.cd == Approx(0.24 + 0.18 * 0.15));
  CHECK(s.cl == Approx(0.54 * std::pow(0.15, 0.4)));
  const AeroCoefficients n = test::assets().aero("nathan").coefficients(0.2, rpm_to_radps(2000.0));
  CHECK(n.cd == Approx(0.3008 + 0.0292 * 2.0));
  CHECK(n.cl == Approx(1.120 * 0.2 / (0.583 + 2.333 * 0.2)));
}

TEST_CASE("spin decay: golf ~4 %/s at driver speed, proportional to speed; nathan tau 30 s", "[aero]") {
  const AeroModel& g = test::assets().aero("ferguson2022");
  CHECK(g.spin_decay_rate(mph_to_mps(167.0)) == Approx(0.04).epsilon(1e-3));
  CHECK(g.spin_decay_rate(mph_to_mps(83.5)) == Approx(0.02).epsilon(1e-3));
  CHECK(test::assets().aero("nathan").spin_decay_rate(40.0) == Approx(1.0 / 30.0));
  // The rates are stated in the default environment's air, where both sources measured.
  CHECK(kSpinDecayReferenceDensity == Approx(air_density(Environment{})).epsilon(1e-14));
}

TEST_CASE("aero forces: drag opposes motion, backspin lifts, rifle spin does not", "[aero]") {
  const AeroModel& m = test::assets().aero("ferguson2022");
  const double rho = 1.2, r = 0.021335;
  const Vec3 v(70.0, 0.0, 0.0);
  const AeroEffect none = aero_effect(m, rho, r, v, Vec3::Zero());
  CHECK(none.force.x() == Approx(-0.5 * rho * kPi * r * r * 0.1304 * 70.0 * 70.0));
  CHECK(none.force.y() == 0.0);
  const AeroEffect back = aero_effect(m, rho, r, v, Vec3(0.0, 0.0, 300.0));  // backspin for +x
  CHECK(back.force.y() > 0.0);
  const AeroEffect rifle = aero_effect(m, rho, r, v, Vec3(300.0, 0.0, 0.0));
  CHECK(rifle.force.y() == 0.0);
  CHECK(rifle.force.z() == 0.0);
  // Side spin curving right (axis tilted, ω has a -y part for +x travel) pushes toward +z.
  const AeroEffect slice = aero_effect(m, rho, r, v, Vec3(0.0, -100.0, 300.0));
  CHECK(slice.force.z() > 0.0);
}

TEST_CASE("lift reads the whole spin and acts with its share across the flow", "[aero]") {
  // A pitch whose spin is partly gyro (along the flight): the lift coefficient is read at the
  // whole spin's S = R|ω|/|v| and scaled by sin(ω, v), the share across the flow.
  const AeroModel& m = test::assets().aero("nathan");
  const double rho = 1.2, r = 0.0369, area = kPi * r * r;
  const Vec3 v(-38.0, 0.0, 0.0);              // toward the plate
  const Vec3 transverse(0.0, 0.0, -90.0);     // backspin for -x travel: lifts
  const Vec3 gyro(-200.0, 0.0, 0.0);          // along the flight
  const Vec3 w = transverse + gyro;
  const AeroEffect e = aero_effect(m, rho, r, v, w);
  const double s = r * w.norm() / v.norm();
  const double share = transverse.norm() / w.norm();
  CHECK(e.force.y() == Approx(0.5 * rho * area * m.coefficients(s, w.norm()).cl * v.squaredNorm() * share).epsilon(1e-12));
  CHECK(e.force.z() == Approx(0.0).margin(1e-12));
  // Spin all across the flow: the same law as reading the transverse spin alone.
  const AeroEffect across = aero_effect(m, rho, r, v, transverse);
  const double s_across = r * transverse.norm() / v.norm();
  CHECK(across.force.y() ==
        Approx(0.5 * rho * area * m.coefficients(s_across, transverse.norm()).cl * v.squaredNorm()).epsilon(1e-12));
  // Where Cl(S) bends over, the gyro share lowers what the same transverse spin lifts.
  CHECK(e.force.y() < across.force.y());
  CHECK(e.force.y() > 0.0);
}

TEST_CASE("unknown aero model lists the allowed names; the shipped models validate", "[aero][input]") {
  try {
    test::assets().aero("magic");
    FAIL("no throw");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("magic") != std::string::npos);
    CHECK(what.find("ferguson2022") != std::string::npos);
    CHECK(what.find("nathan") != std::string::npos);
  }
  CHECK(test::assets().aero_models().size() == 4);
  for (const AeroModel& m : test::assets().aero_models()) CHECK(validate_aero_model(m).empty());
  AeroModel bad = test::assets().aero("ferguson2022");
  bad.d0 = -1.0;  // drag pushing forward at low spin
  CHECK(validate_aero_model(bad).find("Cd") != std::string::npos);
  // Hostile aero files: a 1e300 drag sends the state to infinity, a 1e-300 s spin decay
  // makes the steps vanish. Coefficients and decay are bounded by what a ball can be.
  bad = test::assets().aero("ferguson2022");
  bad.d0 = 1e300;
  CHECK(validate_aero_model(bad).find("at most 2") != std::string::npos);
  bad = test::assets().aero("ferguson2022");
  bad.decay_tau = 1e-300;
  CHECK(validate_aero_model(bad).find("decay_tau") != std::string::npos);
  bad = test::assets().aero("ferguson2022");
  bad.crisis_rise = 50.0;
  CHECK(validate_aero_model(bad).find("rise") != std::string::npos);
  // The rise of Cd past the crisis: never falling (that is the crisis's shape), never steep.
  for (const double slope : {-0.01, 0.5, std::nan("")}) {
    bad = test::assets().aero("tour_fit");
    bad.drag_re_slope = slope;
    CHECK_FALSE(validate_aero_model(bad).empty());
    if (slope == 0.5) CHECK(validate_aero_model(bad).find("drag_re_slope must be in [0, 0.3]") != std::string::npos);
  }
  // Cd is checked at every Reynolds number a ball meets: a negative d0 passes at Re 2e5
  // behind the rise past the crisis (Cd 0.022 at S = 0) but pushes a wedge forward at 1.2e5.
  bad = test::assets().aero("tour_fit");
  bad.d0 = -0.05;
  CHECK(bad.coefficients(0.0, 0.0, 2e5).cd > 0.0);
  CHECK(validate_aero_model(bad).find("Cd must be > 0") != std::string::npos);
  bad = test::assets().aero("tour_fit");
  bad.crisis_rise = 0.0;  // a slope measured from no crisis
  CHECK(validate_aero_model(bad).find("give drag_crisis") != std::string::npos);
  bad = test::assets().aero("tour_fit");
  bad.crisis_width = 1e-3;  // a step the integrator cannot resolve
  CHECK(validate_aero_model(bad).find("width must be at least 100") != std::string::npos);
  bad = test::assets().aero("nathan");
  bad.d_krpm = -0.1;  // drag falling with spin: negative at 20 000 rpm
  CHECK(validate_aero_model(bad).find("Cd must be > 0") != std::string::npos);
  CHECK(test::assets().sport("golf").default_aero == "tour_fit");
  CHECK(test::assets().sport("baseball").default_aero == "nathan");
}
