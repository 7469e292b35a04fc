// Impact regression cases: the textbook's worked examples (DESIGN §3) read from
// tests/regression and solved, checked here against the closed forms independently of the
// files' own expectations.
#include <catch2/catch.hpp>

#include <cmath>

#include "game/tuning/impact_case.hpp"
#include "physics/error.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {

ImpactMeasurements solve_file(const std::string& name) {
  const auto path = std::filesystem::path(SWEETSPOT_SOURCE_DIR) / "tests/regression" / name;
  const CheckedDoc doc(read_toml_doc(path), impact_case_schema());
  const ImpactInput in = impact_input_from(doc);
  return measure_impact(in, solve_impact(in));
}

}  // namespace

TEST_CASE("billiards case reproduces the closed form", "[impact-case]") {
  const auto m = solve_file("bourg_billiards_exact.toml");
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  const double jn = 6.0 * c * 1.9 / 2.0;  // per unit mass, along n
  CHECK(m.values.at("ball_velocity")[0] == Approx(jn * c).epsilon(1e-12));
  CHECK(m.values.at("ball_velocity")[1] == Approx(-jn * s).epsilon(1e-12));
  CHECK(m.values.at("impactor_velocity")[0] == Approx(6.0 - jn * c).epsilon(1e-12));
  CHECK(m.values.at("impactor_velocity")[1] == Approx(jn * s).epsilon(1e-12));
  CHECK(m.values.at("ball_direction")[0] == Approx(-kPi / 6).epsilon(1e-12));
  CHECK(m.contact == "none");
}

TEST_CASE("friction plane cases: coulomb grips, textbook creates energy", "[impact-case]") {
  const auto grip = solve_file("friction_plane_coulomb.toml");
  CHECK(grip.contact == "grip");
  CHECK(grip.values.at("ball_tangential_velocity")[0] == Approx(5.0 / 7.0).epsilon(1e-12));
  CHECK(grip.values.at("contact_tangential_velocity")[0] == Approx(0.0).margin(1e-12));
  CHECK(grip.values.at("energy_ratio")[0] < 1.0);
  const auto textbook = solve_file("friction_plane_textbook.toml");
  CHECK(textbook.contact == "slip");
  CHECK(textbook.values.at("contact_tangential_velocity")[0] == Approx(-20.0).epsilon(1e-12));
  CHECK(textbook.values.at("energy_ratio")[0] == Approx(70.0 / 50.5).epsilon(1e-12));
}

TEST_CASE("impact cases reject a fixed impactor with a mass and a zero normal", "[impact-case][bad-input]") {
  const std::string base = "case = \"impact\"\nnormal = [0.0, 0.0, 0.0]\n[impactor]\nfixed = true\n"
                           "[ball]\nmass = \"45g\"\ninertia = \"1e-5kg*m^2\"\nvelocity = [\"0m/s\", \"-1m/s\", \"0m/s\"]\n"
                           "[impact]\ne = 0.5\n";
  const CheckedDoc zero(parse_toml_doc(base, "z.toml"), impact_case_schema());
  CHECK_THROWS_WITH(impact_input_from(zero), Contains("z.toml:2") && Contains("normal"));
  const std::string massive = base + "[impactor]\n";  // duplicate table -> malformed TOML
  CHECK_THROWS_WITH(parse_toml_doc(massive, "m.toml"), Contains("m.toml:") && Contains("malformed TOML"));
  const std::string with_mass = "case = \"impact\"\nnormal = [0.0, 1.0, 0.0]\n[impactor]\nfixed = true\nmass = \"1kg\"\n"
                                "[ball]\nmass = \"45g\"\ninertia = \"1e-5kg*m^2\"\nvelocity = [\"0m/s\", \"-1m/s\", \"0m/s\"]\n"
                                "[impact]\ne = 0.5\n";
  const CheckedDoc fixed_mass(parse_toml_doc(with_mass, "f.toml"), impact_case_schema());
  CHECK_THROWS_WITH(impact_input_from(fixed_mass), Contains("f.toml:4") && Contains("fixed"));
}
