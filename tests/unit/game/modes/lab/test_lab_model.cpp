// The Lab edits a typed ShotSpec through intents: an edit reaches the shot at once, a value
// out of its range is refused by its scenario key and leaves the last good shot, a constant
// e over a speed-dependent COR law is said, and Save writes the only text: a scenario that
// loads back to the same shot.
#include <catch2/catch.hpp>

#include <filesystem>
#include <unistd.h>

#include "game/content/scenario_toml.hpp"
#include "game/modes/lab/lab_model.hpp"
#include "game/rules/run_shot.hpp"
#include "physics/units.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;

namespace {
Intent edit(LabParam p, double v, double t = 0.0) {
  Intent in;
  in.kind = IntentKind::Edit;
  in.param = static_cast<int>(p);
  in.value = v;
  in.time = t;
  return in;
}
Intent choose(LabChoice c, std::string text) {
  Intent in;
  in.kind = IntentKind::Choose;
  in.param = static_cast<int>(c);
  in.text = std::move(text);
  return in;
}
}  // namespace

TEST_CASE("quantity text survives the round trip through the parser", "[lab]") {
  CHECK(quantity_text(105, "mph") == "105mph");
  CHECK(parse_quantity(quantity_text(104.123456789, "mph"), Dimension::Speed) ==
        Approx(mph_to_mps(104.123456789)).epsilon(1e-8));
  CHECK(quantity_list_text({12.5, -3}, "mm") == "[12.5mm, -3mm]");
  // A slider's float is saved as the decimal it shows, not as float noise.
  CHECK(quantity_text(float_as_decimal(0.808f), "") == "0.808");
  CHECK(quantity_text(float_as_decimal(113.3f), "mph") == "113.3mph");
  CHECK(quantity_text(0.1 + 0.2, "") == "0.30000000000000004");  // exact: a double keeps its digits
}

TEST_CASE("a Lab edit sets the ShotSpec field and runs the shot again", "[lab]") {
  LabModel lab(test::assets(), "golf/driver");
  const double v0 = lab.result().launch.ball_speed;
  const int serial = lab.shot_serial();
  lab.update({edit(LabParam::ClubSpeed, mph_to_mps(100.0))}, 0.0);
  CHECK(std::get<ClubStrike>(lab.spec().strike).swing.club_speed == mph_to_mps(100.0));
  CHECK(lab.result().launch.ball_speed < v0);
  CHECK(lab.shot_serial() == serial + 1);
  CHECK(lab.status().empty());
  // The same edit through the scenario text path gives the same shot, bit for bit.
  const ShotResult text = run_scenario(load_scenario(test::assets(), "golf/driver", {"swing.speed=100mph"}));
  CHECK(text.launch.ball_speed == lab.result().launch.ball_speed);
  CHECK(text.trajectory.summary.carry_m == lab.result().trajectory.summary.carry_m);
}

TEST_CASE("a Lab value out of its range is refused by its key; the last good shot stays", "[lab]") {
  LabModel lab(test::assets(), "golf/driver");
  const double v0 = lab.result().launch.ball_speed;
  lab.update({edit(LabParam::ClubSpeed, 500.0)}, 0.0);
  CHECK(lab.status().find("swing.speed") != std::string::npos);
  CHECK(lab.result().launch.ball_speed == v0);
  lab.update({edit(LabParam::Mu, 0.3)}, 0.0);  // a good edit clears the refusal
  CHECK(lab.status().empty());
}

TEST_CASE("a constant e over the ball's speed-dependent COR is said", "[lab]") {
  LabModel lab(test::assets(), "golf/driver");
  REQUIRE(lab.resolved().material.e.count > 1);  // the driver's COR falls with impact speed
  CHECK_FALSE(lab.e_replaces_law());
  lab.update({edit(LabParam::E, 0.75)}, 0.0);
  CHECK(lab.e_replaces_law());
  REQUIRE(lab.resolved().material.e.count == 1);
  CHECK(lab.resolved().material.e.cor[0] == 0.75);
  // Started with the constant already set (--set, or a scenario file), it is said too.
  CHECK(LabModel(test::assets(), "golf/driver", {"impact.e=0.75"}).e_replaces_law());
}

TEST_CASE("Save writes the edited shot as a scenario that loads back to the same launch", "[lab]") {
  const auto dir = std::filesystem::temp_directory_path() / ("sweetspot-lab-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "saved.toml").string();
  LabModel lab(test::assets(), "golf/7-iron");
  lab.update({edit(LabParam::ClubSpeed, mph_to_mps(85.0)), edit(LabParam::E, 0.808), edit(LabParam::Temperature, fahrenheit_to_kelvin(90.0)),
              edit(LabParam::ImpactToe, 0.01), edit(LabParam::ImpactUp, 0.002), choose(LabChoice::Friction, "textbook")},
             0.0);
  REQUIRE(lab.status().empty());
  Intent save;
  save.kind = IntentKind::Save;
  save.text = path;
  lab.update({save}, 0.0);
  CHECK(lab.status() == "saved " + path);
  const std::string text = lab.scenario_text();
  CHECK(text.find("e = 0.808\n") != std::string::npos);
  CHECK(text.find("speed = \"85mph\"") != std::string::npos);
  CHECK(text.find("temperature = \"32.2222222222C\"") != std::string::npos);  // 90 °F in the key's unit
  const Scenario loaded = load_scenario(test::assets(), path, {});
  CHECK(loaded.spec.environment.temperature == Approx(fahrenheit_to_kelvin(90.0)).epsilon(1e-12));
  const ShotResult back = run_scenario(loaded);
  CHECK(back.launch.ball_speed == Approx(lab.result().launch.ball_speed).epsilon(1e-12));
  CHECK(back.launch.spin.total == Approx(lab.result().launch.spin.total).epsilon(1e-12));
  CHECK(back.impact.friction == FrictionModel::Textbook);
  std::filesystem::remove_all(dir);
}

TEST_CASE("a loft given where the face meets the ball stays so through edits and Save", "[lab]") {
  // Started with TrackMan's dynamic loft and a speed; the strike then moves to the face
  // centre. The face keeps its loft (the contact moves over it), the edit replaces the
  // started speed, and the saved file still gives the loft at the strike.
  LabModel lab(test::assets(), "golf/driver", {"swing.strike_loft=15.1deg", "swing.speed = 94mph"});  // spaced as a shell may pass it
  REQUIRE(lab.status().empty());
  const double face = lab.value(LabParam::DynamicLoft);
  CHECK(rad_to_deg(face) == Approx(15.1 - 2.159).margin(0.005));
  lab.update({edit(LabParam::ImpactUp, 0.0), edit(LabParam::ClubSpeed, mph_to_mps(95.0))}, 0.0);
  REQUIRE(lab.status().empty());
  CHECK(lab.value(LabParam::DynamicLoft) == Approx(face).epsilon(1e-12));
  const std::string text = lab.scenario_text();
  INFO(text);
  CHECK(text.find("strike_loft") != std::string::npos);
  CHECK(text.find("dynamic_loft") == std::string::npos);
  CHECK(text.find("speed = \"95mph\"") != std::string::npos);
  const auto dir = std::filesystem::temp_directory_path() / ("sweetspot-lab-loft-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "loft.toml").string();
  Intent save;
  save.kind = IntentKind::Save;
  save.text = path;
  lab.update({save}, 0.0);
  CHECK(lab.status() == "saved " + path);
  const ShotResult back = run_scenario(load_scenario(test::assets(), path, {}));
  CHECK(back.launch.spin.total == Approx(lab.result().launch.spin.total).epsilon(1e-9));
  CHECK(back.launch.vertical_angle == Approx(lab.result().launch.vertical_angle).epsilon(1e-9));
  std::filesystem::remove_all(dir);
}

TEST_CASE("a face angle given where the face meets the ball stays so through edits and Save", "[lab]") {
  // A toe strike square where it meets the ball: the face centre is shut by the bulge's
  // turn. Moving the strike moves the contact over that face (the face does not turn), and
  // the saved file gives the face angle at its new strike.
  LabModel lab(test::assets(), "golf/driver", {"swing.strike_face_angle=0deg", "swing.impact_offset=[12.7mm,11.5mm]"});
  REQUIRE(lab.status().empty());
  const double face = lab.value(LabParam::FaceAngle);
  CHECK(rad_to_deg(face) == Approx(-2.44).margin(0.02));
  CHECK(lab.result().club.strike_face_angle == Approx(0.0).margin(1e-12));
  lab.update({edit(LabParam::ImpactToe, 0.0)}, 0.0);
  REQUIRE(lab.status().empty());
  CHECK(lab.value(LabParam::FaceAngle) == Approx(face).epsilon(1e-12));
  CHECK(lab.result().club.strike_face_angle == Approx(face).margin(1e-12));  // the centre's own angle now
  const std::string text = lab.scenario_text();
  INFO(text);
  CHECK(text.find("strike_face_angle") != std::string::npos);
  const ShotResult back = run_scenario(load_scenario(test::assets(), "golf/driver", {[&] {
    const auto at = text.find("strike_face_angle = \"");
    REQUIRE(at != std::string::npos);
    const auto from = at + std::string("strike_face_angle = \"").size();
    return "swing.strike_face_angle=" + text.substr(from, text.find('"', from) - from);
  }(), "swing.impact_offset=[0mm,11.5mm]"}));
  CHECK(back.launch.spin.axis_rad == Approx(lab.result().launch.spin.axis_rad).margin(1e-9));
}

TEST_CASE("choosing another scenario or sport drops the edits", "[lab]") {
  LabModel lab(test::assets(), "golf/driver");
  lab.update({edit(LabParam::ClubSpeed, mph_to_mps(93.7))}, 0.0);
  CHECK(lab.scenario_text().find("93.7mph") != std::string::npos);
  lab.update({choose(LabChoice::Sport, "baseball")}, 0.0);
  CHECK(lab.spec().sport == "baseball");
  CHECK(lab.scenario_text().find("93.7mph") == std::string::npos);
  lab.update({edit(LabParam::BatSpeed, mph_to_mps(75.0))}, 0.0);
  CHECK(std::get<BatStrike>(lab.spec().strike).swing.bat_speed == mph_to_mps(75.0));
  // A club key on a bat shot changes nothing.
  const double v = lab.result().launch.ball_speed;
  lab.update({edit(LabParam::ClubSpeed, 40.0)}, 0.0);
  CHECK(lab.result().launch.ball_speed == v);
}
