// UI logic without a window: panel edits become scenario overrides, go through the same
// validation as the command line, and a saved scenario reproduces the shot.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "game/content/scenario.hpp"
#include "game/ui/ui_state.hpp"
#include "support/test_assets.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"
#include "game/rules/run_shot.hpp"

using namespace sweetspot;

TEST_CASE("quantity text survives the round trip through the parser", "[ui]") {
  CHECK(quantity_text(105, "mph") == "105mph");
  CHECK(parse_quantity(quantity_text(104.123456789, "mph"), Dimension::Speed) ==
        Approx(mph_to_mps(104.123456789)).epsilon(1e-8));
  CHECK(quantity_list_text({12.5, -3}, "mm") == "[12.5mm, -3mm]");
  // Issue 21: a slider's float is saved as the decimal it shows, not as float noise.
  CHECK(quantity_text(float_as_decimal(0.808f), "") == "0.808");
  CHECK(quantity_text(float_as_decimal(113.3f), "mph") == "113.3mph");
  CHECK(quantity_text(0.1 + 0.2, "") == "0.30000000000000004");  // exact: a double keeps its digits
}

TEST_CASE("a saved scenario writes bare numbers bare and quantities quoted", "[ui]") {
  UiState st;
  st.scenario = "golf/7-iron";
  st.set("impact.e", quantity_text(float_as_decimal(0.808f), ""));
  st.set("impact.mu", "0.31");
  st.set("environment.temperature", "90F");
  const std::string text = scenario_toml(load_ui_scenario(test::assets(), st));
  CHECK(text.find("e = 0.808\n") != std::string::npos);
  CHECK(text.find("mu = 0.31\n") != std::string::npos);
  CHECK(text.find("temperature = \"90F\"\n") != std::string::npos);
  CHECK(text.find("0.808000") == std::string::npos);
}

TEST_CASE("panel edits change the loaded scenario", "[ui]") {
  UiState st;
  st.scenario = "golf/driver";
  st.set("swing.speed", quantity_text(100, "mph"));
  st.set("impact.mu", quantity_text(0.2, ""));
  st.set("impact.friction", "textbook");
  st.set("swing.impact_offset", quantity_list_text({15, 5}, "mm"));
  const Scenario s = load_ui_scenario(test::assets(), st);
  const GolfSwing& g = std::get<ClubStrike>(s.spec.strike).swing;
  CHECK(g.club_speed == Approx(mph_to_mps(100)));
  CHECK(s.resolved.material.mu == Approx(0.2));
  CHECK(s.resolved.material.friction == FrictionModel::Textbook);
  CHECK(g.impact_toe == Approx(0.015));
  CHECK(g.impact_up == Approx(0.005));
  CHECK(st.override_list().size() == 4);

  // The change reaches the shot: slower club, slower ball.
  UiState base;
  const double v0 = run_scenario(load_ui_scenario(test::assets(), base), {true, false}).launch.ball_speed;
  const double v1 = run_scenario(s, {true, false}).launch.ball_speed;
  CHECK(v1 < v0);
}

TEST_CASE("the e_t slider changes a rigid-model driver shot", "[ui]") {
  UiState st;
  st.set("impact.model", "rigid");  // the compliant contact makes its own tangential rebound
  st.set("impact.e_t", "0");
  const ShotResult a = run_scenario(load_ui_scenario(test::assets(), st), {true, false});
  st.set("impact.e_t", "0.3");
  const ShotResult b = run_scenario(load_ui_scenario(test::assets(), st), {true, false});
  CHECK(b.launch.spin.total > a.launch.spin.total * 1.05);  // more tangential rebound, more spin
}

TEST_CASE("switching scenario drops the previous edits", "[ui]") {
  UiState st;
  st.set("swing.speed", "90mph");
  st.choose_scenario("baseball/line-drive");
  CHECK(st.overrides.empty());
  CHECK(load_ui_scenario(test::assets(), st).spec.sport == "baseball");
}

TEST_CASE("a bad edit is rejected like the command line would", "[ui]") {
  UiState st;
  st.set("impact.e", "1.5");
  CHECK_THROWS_AS(load_ui_scenario(test::assets(), st), InputError);
  st.overrides.clear();
  st.set("swing.speed", "fast");
  CHECK_THROWS_AS(load_ui_scenario(test::assets(), st), InputError);
}

TEST_CASE("a saved scenario reproduces the tuned shot", "[ui]") {
  for (const char* name : {"golf/7-iron", "baseball/home-run"}) {
    UiState st;
    st.scenario = name;
    st.set("impact.mu", "0.31");
    st.set("environment.temperature", "90F");
    if (std::string(name).rfind("golf", 0) == 0) st.set("swing.impact_offset", "[8mm, -4mm]");
    const Scenario s = load_ui_scenario(test::assets(), st);
    const ShotResult a = run_scenario(s);

    const auto path = std::filesystem::temp_directory_path() / "sweetspot_ui_saved.toml";
    {
      std::ofstream f(path);
      f << scenario_toml(s);
    }
    const Scenario back = load_scenario(test::assets(), path.string(), {});
    const ShotResult b = run_scenario(back);
    std::filesystem::remove(path);
    CHECK(b.launch.ball_speed == a.launch.ball_speed);
    CHECK(b.launch.spin.total == a.launch.spin.total);
    CHECK(b.trajectory.summary.carry_m == a.trajectory.summary.carry_m);
  }
}
