// Air density against standard tables and the wind profile's defining properties.
#include <catch2/catch.hpp>

#include <cmath>

#include "physics/atmosphere.hpp"
#include "physics/error.hpp"

using namespace sweetspot;

namespace {
Environment dry(double t_kelvin, double pressure) {
  Environment e;
  e.temperature = t_kelvin;
  e.pressure = pressure;
  e.humidity = 0.0;
  return e;
}
}  // namespace

TEST_CASE("dry air density matches standard tables", "[atmosphere]") {
  // ISA sea level: 15 °C, 101325 Pa -> 1.2250 kg/m³; 20 °C -> 1.2041; 0 °C -> 1.2922.
  CHECK(air_density(dry(288.15, 101325.0)) == Approx(1.2250).epsilon(2e-4));
  CHECK(air_density(dry(293.15, 101325.0)) == Approx(1.2041).epsilon(2e-4));
  CHECK(air_density(dry(273.15, 101325.0)) == Approx(1.2922).epsilon(2e-4));
}

TEST_CASE("standard atmosphere pressure and density with altitude", "[atmosphere]") {
  // ISA table: 1000 m 89874.6 Pa / 1.1117 kg/m³ (281.65 K); 2000 m 79495.2 Pa / 1.0066 (275.15 K).
  CHECK(standard_pressure(0.0) == Approx(101325.0).epsilon(1e-9));
  CHECK(standard_pressure(1000.0) == Approx(89874.6).epsilon(1e-4));
  CHECK(standard_pressure(2000.0) == Approx(79495.2).epsilon(1e-4));
  Environment e = dry(281.65, 0.0);
  e.altitude = 1000.0;
  CHECK(air_density(e) == Approx(1.1117).epsilon(5e-4));
  e.temperature = 275.15;
  e.altitude = 2000.0;
  CHECK(air_density(e) == Approx(1.0066).epsilon(5e-4));
  // An explicit station pressure overrides the altitude.
  e.pressure = 101325.0;
  e.temperature = 288.15;
  CHECK(air_density(e) == Approx(1.2250).epsilon(2e-4));
}

TEST_CASE("humid air is lighter than dry air", "[atmosphere]") {
  // Buck: e_s(30 °C) = 4246 Pa; saturated air at 30 °C, 101325 Pa is 1.1459 kg/m³ (dry 1.1644).
  CHECK(saturation_vapour_pressure(303.15) == Approx(4246.0).epsilon(2e-3));
  Environment e = dry(303.15, 101325.0);
  const double rho_dry = air_density(e);
  e.humidity = 1.0;
  CHECK(rho_dry == Approx(1.1644).epsilon(5e-4));
  CHECK(air_density(e) == Approx(1.1459).epsilon(5e-4));
}

TEST_CASE("default environment is 21 C, sea level, 50 % RH", "[atmosphere]") {
  const Environment e;
  CHECK(air_density(e) == Approx(1.1944).epsilon(1e-3));
  CHECK(air_viscosity(293.15) == Approx(1.81e-5).epsilon(5e-3));
}

TEST_CASE("wind profile: reference height, direction, growth with height", "[atmosphere][wind]") {
  Environment e;
  e.wind_speed = 5.0;
  e.wind_direction = 0.0;
  for (WindProfile p : {WindProfile::Logarithmic, WindProfile::PowerLaw, WindProfile::Uniform}) {
    e.wind_profile = p;
    const Vec3 w = wind_at(e, e.wind_reference_height);
    CHECK(w.x() == Approx(5.0).epsilon(1e-12));
    CHECK(w.y() == 0.0);
  }
  e.wind_profile = WindProfile::Logarithmic;
  CHECK(wind_at(e, 2.0).x() < wind_at(e, 10.0).x());
  CHECK(wind_at(e, 30.0).x() > 5.0);
  CHECK(wind_at(e, e.wind_roughness_length).norm() == 0.0);
  // ln(2/0.03)/ln(10/0.03) = 0.7225
  CHECK(wind_at(e, 2.0).x() == Approx(5.0 * std::log(2.0 / 0.03) / std::log(10.0 / 0.03)));
  e.wind_profile = WindProfile::PowerLaw;
  CHECK(wind_at(e, 2.0).x() == Approx(5.0 * std::pow(0.2, 1.0 / 7.0)));
  e.wind_direction = kPi / 2.0;  // toward +z (right)
  CHECK(wind_at(e, 10.0).z() == Approx(5.0));
  CHECK(std::abs(wind_at(e, 10.0).x()) < 1e-12);
}

TEST_CASE("the wind in the grass is the surface's log law, whatever the flight's profile", "[atmosphere][wind]") {
  Environment e;
  e.wind_speed = 20.0;
  for (WindProfile p : {WindProfile::Logarithmic, WindProfile::PowerLaw, WindProfile::Uniform}) {
    e.wind_profile = p;
    // A golf ball's centre (21 mm) sits below the fairway's roughness length (30 mm): still air.
    CHECK(ground_wind_at(e, 0.021335).norm() == 0.0);
    // A hop 1 m up: ln(1/0.03)/ln(10/0.03) = 0.6036 of the 10 m wind.
    CHECK(ground_wind_at(e, 1.0).x() == Approx(20.0 * std::log(1.0 / 0.03) / std::log(10.0 / 0.03)).epsilon(1e-12));
  }
  e.wind_profile = WindProfile::Uniform;
  CHECK(wind_at(e, 0.021335).x() == 20.0);  // the flight's convention: one speed at every height
}

TEST_CASE("environment validation names the field and range", "[atmosphere][input]") {
  Environment e;
  CHECK(validate_environment(e).empty());
  e.humidity = 1.5;
  CHECK(validate_environment(e).find("humidity") != std::string::npos);
  CHECK_THROWS_AS(check_environment(e), InputError);
  e = Environment{};
  e.temperature = std::nan("");
  CHECK(validate_environment(e).find("temperature") != std::string::npos);
  e = Environment{};
  e.altitude = 9000.0;
  CHECK(validate_environment(e).find("environment.altitude = 9000 m is out of range (allowed [-500, 6000] m)") !=
        std::string::npos);
  // The log profile needs its roughness well below the reference height (it blows up as
  // z0 nears h_ref): refused with the bound, not turned into NaN wind.
  e = Environment{};
  e.wind_speed = 10.0;
  e.wind_roughness_length = 0.99;
  e.wind_reference_height = 1.0;
  CHECK(validate_environment(e).find("wind_reference_height / 10") != std::string::npos);
  // Past hurricane force (Beaufort 12, 32.7 m/s) no game is played and a landed ball hops on
  // at the wind's pace: refused with the range.
  e = Environment{};
  e.wind_speed = 33.0;
  CHECK(validate_environment(e).find("environment.wind_speed = 33 m/s is out of range (allowed [0, 32.7] m/s)") !=
        std::string::npos);
  // Beaufort's scale is the wind at 10 m: 32 m/s measured at 2 m is ~42 m/s there (log law).
  e.wind_speed = 32.0;
  e.wind_reference_height = 2.0;
  CHECK(validate_environment(e).find("at 10 m: past hurricane force") != std::string::npos);
  e.wind_reference_height = 10.0;
  CHECK(validate_environment(e).empty());
  // A uniform wind measured at 2 m is that at 10 m too, but the turf's log law through it is not.
  e.wind_profile = WindProfile::Uniform;
  e.wind_reference_height = 2.0;
  CHECK(validate_environment(e).find("past hurricane force") != std::string::npos);
  // The land's roughness: at least Davenport–Wieringa's "smooth" land (calm water's 0.1 mm is
  // not ground a ball lies on).
  e = Environment{};
  e.wind_roughness_length = 1e-4;
  CHECK(validate_environment(e).find("wind_roughness_length") != std::string::npos);
  // Wind above the surface layer is held at its 100 m value (finite at any height).
  e = Environment{};
  e.wind_speed = 10.0;
  CHECK(wind_at(e, 1e6) == wind_at(e, 100.0));
}
