// The one TOML reader: what it refuses before reading, and the one rule for values.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "game/content/quantity_text.hpp"
#include "game/content/toml_file.hpp"
#include "physics/error.hpp"
#include "physics/math.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

TEST_CASE("data files: FIFOs, devices, directories and oversized files are refused unread", "[toml][hostile]") {
  const fs::path dir = fs::temp_directory_path() / "sweetspot_toml_file_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  REQUIRE(::mkfifo((dir / "pipe.toml").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(TomlFile::read(dir / "pipe.toml", "scenario"), Contains("pipe.toml") && Contains("not a regular file"));
  CHECK_THROWS_WITH(TomlFile::read("/dev/zero", "scenario"), Contains("/dev/zero") && Contains("not a regular file"));
  CHECK_THROWS_WITH(TomlFile::read(dir, "scenario"), Contains("is a directory"));
  CHECK_THROWS_WITH(TomlFile::read(dir / "absent.toml", "scenario"), Contains("absent.toml") && Contains("not found"));
  {
    std::ofstream f(dir / "big.toml");
    f << "x = 1\n";
  }
  fs::resize_file(dir / "big.toml", kMaxDataFileBytes + 1);
  CHECK_THROWS_WITH(TomlFile::read(dir / "big.toml", "scenario"), Contains("over the limit"));
  fs::remove_all(dir);
}

TEST_CASE("values: units required for dimensional quantities, bare for numbers, ranges checked", "[toml]") {
  const TomlFile f = TomlFile::parse("speed = 50\nangle = \"3deg\"\ne = 0.8\nfrac = 0.5\nname = \"\"\nlist = [\"1mm\"]\n",
                                     "t.toml");
  const auto& t = f.root();
  CHECK_THROWS_WITH(f.quantity(*t.get("speed"), "speed", Dimension::Speed), Contains("t.toml:1") && Contains("missing unit"));
  CHECK(f.quantity(*t.get("angle"), "angle", Dimension::Angle) == Approx(deg_to_rad(3.0)));
  CHECK(f.quantity(*t.get("e"), "e", Dimension::Dimensionless) == 0.8);
  // Fractions carry "%" like every other dimension: `humidity = 1` is not 100 %.
  CHECK_THROWS_WITH(f.quantity(*t.get("frac"), "frac", Dimension::Fraction), Contains("missing unit"));
  constexpr Range unit{0.0, 0.5};
  CHECK_THROWS_WITH(f.quantity(*t.get("e"), "e", Dimension::Dimensionless, &unit), Contains("e = 0.8") && Contains("[0, 0.5]"));
  CHECK_THROWS_WITH(f.text(*t.get("name"), "name"), Contains("empty"));
  CHECK_THROWS_WITH(f.quantities(*t.get("list"), "list", Dimension::Length, 2), Contains("expected an array of 2"));
  CHECK_THROWS_WITH(f.only_keys(t, "", {"speed"}), Contains("unknown key") && Contains("allowed: speed"));
  CHECK_THROWS_WITH(TomlFile::parse("a = [", "bad.toml"), Contains("bad.toml:1") && Contains("malformed TOML"));
}

TEST_CASE("quantity text: the one rule shared by files and flags", "[toml][units]") {
  CHECK(read_quantity("113mph", Dimension::Speed) == Approx(mph_to_mps(113)));
  CHECK_THROWS_WITH(read_quantity("113", Dimension::Speed), Contains("missing unit in '113'") && Contains("mph"));
  CHECK_THROWS_WITH(read_quantity("", Dimension::Length), Contains("empty"));
  CHECK(read_quantity("0.4", Dimension::Dimensionless) == 0.4);
  CHECK(read_quantity_list("[10mm, -2mm]", Dimension::Length) == std::vector<double>{0.010, -0.002});
  CHECK_THROWS_WITH(read_quantity_list("[10mm, 2]", Dimension::Length), Contains("missing unit"));
  CHECK(has_unit("5%"));
  CHECK_FALSE(has_unit(" 5 "));
}
