// Sports as data: the shipped profiles, and a bad profile named by file, line and key.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "game/content/aero_file.hpp"
#include "game/content/sport_file.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

TEST_CASE("the shipped sports: golf swings a club off the ground, baseball a bat at 0.9 m", "[sport]") {
  const SportCatalog& c = test::assets().sports();
  CHECK(c.names() == "golf, baseball");
  const SportProfile& g = c.get("golf");
  CHECK(g.impactor == ImpactorKind::Club);
  CHECK_FALSE(g.contact_height.has_value());
  CHECK(g.distance_unit == "yd");
  const SportProfile& b = c.get("baseball");
  CHECK(b.impactor == ImpactorKind::Bat);
  CHECK(*b.contact_height == Approx(0.9));
  CHECK(b.distance_unit == "ft");
  CHECK_THROWS_WITH(c.get("cricket"), Contains("unknown sport 'cricket'") && Contains("golf, baseball"));
}

TEST_CASE("a bad sports or aero file is named with its line and key", "[sport][input]") {
  const fs::path dir = fs::temp_directory_path() / "sweetspot_sport_file_test";
  fs::create_directories(dir);
  std::ofstream(dir / "sports.toml") << "[[sport]]\nname = \"darts\"\nball = \"tour\"\nimpactor = \"arrow\"\n";
  CHECK_THROWS_WITH(load_sports(dir / "sports.toml"), Contains("sports.toml:4") && Contains("impactor") && Contains("club, bat"));
  std::ofstream(dir / "aero.toml") << "[[model]]\nname = \"x\"\nsport = \"golf\"\nsource = \"s\"\ndrag = [-1, 0, 0]\n"
                                      "lift_law = \"quadratic\"\nlift = [0, 1, 0]\n";
  CHECK_THROWS_WITH(load_aero_models(dir / "aero.toml", test::assets().sports()), Contains("aero.toml:1") && Contains("Cd must be > 0"));
  std::ofstream(dir / "aero.toml") << "[[model]]\nname = \"x\"\nsport = \"golf\"\nsource = \"s\"\ndrag = [0.2, 0, 0]\n"
                                      "lift_law = \"quadratic\"\nlift = [0, 1, 0]\ndrag_re_slope = -0.2\n";
  CHECK_THROWS_WITH(load_aero_models(dir / "aero.toml", test::assets().sports()), Contains("aero.toml:1") && Contains("drag_re_slope") && Contains("[0, 0.3]"));
  // A model for a sport the build does not know would never be chosen, and said nothing.
  std::ofstream(dir / "aero.toml") << "[[model]]\nname = \"x\"\nsport = \"tennis\"\nsource = \"s\"\ndrag = [0.2, 0, 0]\n"
                                      "lift_law = \"quadratic\"\nlift = [0, 1, 0]\n";
  CHECK_THROWS_WITH(load_aero_models(dir / "aero.toml", test::assets().sports()),
                    Contains("aero.toml:3") && Contains("sport") && Contains("'tennis'") && Contains("golf, baseball"));
  fs::remove_all(dir);
}
