// Equipment files: the shipped data matches its documented sources, and bad files are
// rejected naming file, line, entry, key and range.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "game/content/equipment_file.hpp"
#include "physics/error.hpp"
#include "physics/units.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;

namespace {
namespace fs = std::filesystem;
const fs::path kEquipment = fs::path(SWEETSPOT_SOURCE_DIR) / "assets" / "equipment";

// A scratch copy of the equipment directory with one file's text edited, in the assets
// layout (the meshes beside it are the shipped ones).
struct ScratchDir {
  fs::path root, dir;
  ScratchDir() {
    root = fs::temp_directory_path() / ("sweetspot_eq_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    dir = root / "equipment";
    fs::create_directories(dir);
    fs::create_directory_symlink(kEquipment.parent_path() / "meshes", root / "meshes");
    for (const char* f : {"balls.toml", "clubs.toml", "bats.toml"}) fs::copy_file(kEquipment / f, dir / f);
  }
  ~ScratchDir() { fs::remove_all(root); }
  void replace(const char* file, const std::string& from, const std::string& to) {
    std::ifstream in(dir / file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    std::ofstream(dir / file) << text;
  }
};
}  // namespace

TEST_CASE("the shipped equipment loads and matches DESIGN's measured references", "[equipment]") {
  const EquipmentCatalog cat = load_equipment(kEquipment);
  const BallSpec& tour = cat.ball("tour");
  CHECK(tour.mass == Approx(0.04593).epsilon(1e-12));
  CHECK(2 * tour.radius == Approx(0.04267).epsilon(1e-12));
  CHECK(tour.inertia == Approx(83.63e-7).epsilon(1e-9));
  const BallSpec& mlb = cat.ball("mlb");
  CHECK(mlb.mass == Approx(0.145));
  CHECK(mlb.radius == Approx(0.0369));
  CHECK(mlb.inertia == Approx(0.4 * 0.145 * 0.0369 * 0.0369).epsilon(1e-12));

  const char* bag[] = {"driver", "3-wood", "5-wood", "hybrid", "3-iron", "4-iron", "5-iron",
                       "6-iron", "7-iron", "8-iron", "9-iron", "pw", "sw", "lw"};
  REQUIRE(cat.clubs.size() == 15);  // 14 above plus the putter: a bag of 14 is chosen from them
  double last_loft = 0;
  for (const char* n : bag) {
    const ClubSpec& c = cat.club(n);
    INFO(n);
    CHECK(c.loft > 0.0);
    if (std::string(n) != "3-iron") CHECK(c.loft >= last_loft);  // 3-iron and hybrid share 21°
    last_loft = c.loft;
    CHECK(c.cg.x() < 0.0);  // behind the face
    CHECK_NOTHROW(validate_club(c));
  }
  const ClubSpec& d = cat.club("driver");
  CHECK(rad_to_deg(d.loft) == Approx(9.8));
  CHECK(d.head_mass == Approx(0.204));
  CHECK(d.cg.x() == Approx(-0.0423));
  CHECK(d.inertia(0, 0) == Approx(2843e-7));
  CHECK(d.inertia(1, 1) == Approx(5679e-7));
  CHECK(d.inertia(2, 2) == Approx(4085e-7));
  CHECK(d.inertia(0, 1) == Approx(-733e-7));
  CHECK(d.inertia(1, 0) == Approx(-733e-7));
  CHECK(d.inertia(0, 2) == Approx(530.2e-7));
  CHECK(d.bulge_radius == Approx(0.305));
  CHECK(d.face.e.at(48.8) == Approx(0.83).epsilon(1e-12));
  CHECK(d.face.e.at(30.0) > d.face.e.at(55.0));  // ball COR falls with impact speed
  CHECK(d.inertia(1, 1) < 5900e-7);               // USGA MOI limit
  CHECK(cat.club("7-iron").bulge_radius > 5.0);   // flat iron face

  const BatSpec& maple = cat.bat("maple");
  CHECK(maple.length == Approx(0.84));
  CHECK(maple.mass == Approx(0.989));
  CHECK(maple.inertia_cg == Approx(0.046));
  CHECK(maple.length - maple.cg_from_knob == Approx(0.265));
  CHECK(maple.sweet_spot_from_tip == Approx(0.1524));
  CHECK(maple.radius_at(0.7) == Approx(0.033));
  CHECK(maple.radius_at(0.2) < 0.015);  // handle
  CHECK(maple.radius_at(0.9) == 0.0);   // beyond the tip
  // A turned barrel has no corners: at every profile point inside the bat the slope (which
  // tilts the contact's normal) is the same on either side, the radius passes through the
  // point, and between points it never leaves the two points' range (no bulge, no dip).
  for (const char* name : {"maple", "bbcor"}) {
    const BatSpec& bat = cat.bat(name);
    const auto slope = [&](double x) { return (bat.radius_at(x + 1e-6) - bat.radius_at(x - 1e-6)) / 2e-6; };
    for (std::size_t i = 1; i + 1 < bat.barrel_profile.size(); ++i) {
      const auto [x, r] = bat.barrel_profile[i];
      INFO(name << " point " << i << " at " << x << " m");
      CHECK(bat.radius_at(x) == Approx(r).epsilon(1e-12));
      CHECK(std::abs(slope(x - 1e-5) - slope(x + 1e-5)) < 0.01);  // a linear profile's corners: 0.06-0.5
      const auto [x1, r1] = bat.barrel_profile[i + 1];
      for (double f = 0.1; f < 1.0; f += 0.1) {
        const double at = bat.radius_at(x + f * (x1 - x));
        CHECK(at >= std::min(r, r1) - 1e-12);
        CHECK(at <= std::max(r, r1) + 1e-12);
      }
    }
  }
  CHECK(maple.cor_factor_at(0.15) == Approx(1.0));
  CHECK(maple.cor_factor_at(0.0) < maple.cor_factor_at(0.15));
  CHECK(maple.cor_factor_at(0.45) < maple.cor_factor_at(0.15));
  const BatSpec& bbcor = cat.bat("bbcor");
  CHECK(bbcor.material.e.at(60.8) <= 0.50);  // the BBCOR certification limit
  CHECK(bbcor.material.e.at(60.8) <= maple.material.e.at(60.8));
}

TEST_CASE("the putter is data: 3 deg loft, no tee, its own mesh", "[equipment]") {
  const EquipmentCatalog cat = load_equipment(kEquipment);
  const ClubSpec& p = cat.club("putter");
  const ClubInfo& info = cat.club_info_of("putter");
  CHECK(rad_to_deg(p.loft) == Approx(3.0));
  CHECK(info.kind == "putter");
  CHECK(info.tee_height == 0.0);
  CHECK(info.mesh == "putter_head");
  CHECK(fs::is_regular_file(kEquipment.parent_path() / "meshes" / "putter_head.obj"));
  CHECK(cat.club_info_of("driver").tee_height > 0.02);
  CHECK(cat.club_info_of("driver").mesh == "driver_head");
}

TEST_CASE("unknown equipment names list the allowed ones", "[equipment]") {
  const EquipmentCatalog cat = load_equipment(kEquipment);
  CHECK_THROWS_WITH(cat.club("spoon"), Contains("unknown club 'spoon'") && Contains("driver") && Contains("putter"));
  CHECK_THROWS_WITH(cat.ball("range"), Contains("allowed: tour, mlb"));
  CHECK_THROWS_WITH(cat.bat("aluminium"), Contains("maple, bbcor"));
}

TEST_CASE("bad equipment files name file, line, entry, key and range", "[equipment][validation]") {
  {
    // A mesh is a name of assets/meshes, never a path out of the assets.
    ScratchDir s;
    s.replace("clubs.toml", "mesh = \"driver_head\"", "mesh = \"../../../../etc/passwd\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("mesh") && Contains("not a mesh name"));
  }
  {
    // A mesh that is not there: the club would be drawn as nothing.
    ScratchDir s;
    s.replace("clubs.toml", "mesh = \"driver_head\"", "mesh = \"nope\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("mesh") && Contains("no mesh 'nope'"));
  }
  {
    ScratchDir s;
    s.replace("balls.toml", "stiffness = 2.36e7", "stiffness = 1e-3");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("stiffness") && Contains("too soft"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "e = [0.65, 0.92]", "e = [0.92, 0.65]");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("face.measured.e") &&
                                                 Contains("low <= high"));
  }
  {
    ScratchDir s;
    s.replace("bats.toml", "mu = [0.35, 0.65]", "mu = [0.35, 3.0]");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("bats.toml:") && Contains("material.measured.mu"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "pair = \"a golf ball on a club face\"", "");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("pair"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "head_mass = \"204g\"", "head_mass = \"5000g\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("club 'driver'") &&
                                                 Contains("head_mass") && Contains("[0.05, 1] kg"));
  }
  {
    // A check across keys (the cg must sit behind the face) names the key's own line and
    // the club once.
    ScratchDir s;
    s.replace("clubs.toml", "cg = [\"-42.3mm\"", "cg = [\"5mm\"");
    try {
      load_equipment(s.dir);
      FAIL("a cg in front of the face was accepted");
    } catch (const InputError& e) {
      const std::string m = e.what();
      CHECK_THAT(m, Contains("clubs.toml:109: club 'driver': cg must be"));
      CHECK(m.find("club 'driver'") == m.rfind("club 'driver'"));
    }
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "loft = \"9.8deg\"", "loft = \"9.8mph\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("loft") && Contains("angle"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "loft = \"9.8deg\"", "loft = 0.17");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("missing unit"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "\"2843g*cm^2\"", "\"-2843g*cm^2\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("positive definite"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "e_t = 0.25", "e_t = 1.35");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("e_t") && Contains("[0, 1]"));
  }
  {
    ScratchDir s;
    s.replace("balls.toml", "mass = \"145g\"", "mass = \"-145g\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("balls.toml:") && Contains("ball 'mlb'") && Contains("mass"));
  }
  {
    ScratchDir s;
    s.replace("bats.toml", "cor = [[\"25m/s\", 0.55]", "cor = [[\"25m/s\", 1.55]");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("bats.toml:") && Contains("bat 'maple'") && Contains("[0, 1]"));
  }
  {
    ScratchDir s;
    s.replace("bats.toml", "[\"0.60m\", \"33mm\"], [\"0.83m\"", "[\"0.90m\", \"33mm\"], [\"0.83m\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("strictly increasing"));
  }
  {
    ScratchDir s;
    s.replace("bats.toml", "length = \"0.84m\"", "");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("bats.toml:") && Contains("length") && Contains("missing"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "\n[face]\n", "\n[face\n");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("clubs.toml:") && Contains("malformed TOML"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "friction = \"coulomb\"", "friction = \"sticky\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("none, textbook, coulomb"));
  }
  {
    ScratchDir s;
    s.replace("clubs.toml", "kind = \"putter\"", "kind = \"broom\"");
    CHECK_THROWS_WITH(load_equipment(s.dir), Contains("club 'putter'") && Contains("wood, hybrid, iron, wedge, putter"));
  }
  CHECK_THROWS_WITH(load_equipment("/nonexistent/dir"), Contains("balls.toml"));
}
