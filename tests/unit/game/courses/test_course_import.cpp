// Course import (game/courses): OpenStreetMap golf data -> a course that rounds play. The
// fixtures are hand-made maps (tests/data/osm): nine_holes.osm (scripts/gen_osm_fixture.py:
// nine holes with their par, handicap and dist, a multipolygon green, water and a lateral
// burn, pins on three greens, the course's boundary) and edge_cases.osm (a hole without par,
// a green relation with a bunker cut out of it inside a fairway, a tee ring left open by
// 0.5 m, lateral water, no boundary).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <cpl_conv.h>
#include <gdal.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#endif
#include <osmium/io/pbf_output.hpp>
#include <osmium/io/reader.hpp>
#include <osmium/io/writer.hpp>
#include <osmium/io/xml_input.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#include <ogr_srs_api.h>

#include "game/content/course_file.hpp"
#include "game/content/gzip_file.hpp"
#include "game/courses/course_import.hpp"
#include "game/courses/elevation.hpp"
#include "game/courses/golf_map.hpp"
#include "game/courses/surface_plan.hpp"
#include "game/courses/terrain_heights.hpp"
#include "game/courses/tree_planting.hpp"
#include "game/modes/golf/bot.hpp"
#include "game/modes/golf/round.hpp"
#include "game/rules/run_shot.hpp"
#include "physics/ground.hpp"
#include "physics/error.hpp"
#include "support/test_assets.hpp"

using namespace sweetspot;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

const fs::path kData = fs::path(SWEETSPOT_SOURCE_DIR) / "tests" / "data" / "osm";

// A fresh, empty working folder for one test.
struct Scratch {
  fs::path dir;
  explicit Scratch(const std::string& name) : dir(fs::temp_directory_path() / ("sweetspot_import_" + name + "_" + std::to_string(getpid()))) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  // Nothing but what the test put there: no working directory left behind.
  bool no_leftovers() const {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().rfind(".course-import-", 0) == 0) return false;
    return true;
  }
};

ImportResult import(const fs::path& map, const fs::path& out) {
  ImportOptions o;
  o.map = map;
  o.out = out;
  return import_course(test::assets(), o);
}

std::vector<Vec3> obj_vertices(const fs::path& obj_gz) {
  std::istringstream in(read_gzip_file(obj_gz, "test mesh", std::uintmax_t{1} << 28));
  std::vector<Vec3> v;
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("v ", 0) == 0) {
      std::istringstream s(line.substr(2));
      double x, y, z;
      s >> x >> y >> z;
      v.emplace_back(x, y, z);
    }
  return v;
}

bool has_report(const ImportResult& r, const std::string& a, const std::string& b = "") {
  for (const std::string& s : r.report)
    if (s.find(a) != std::string::npos && s.find(b) != std::string::npos) return true;
  return false;
}

// The edge-case map with one piece of its text replaced, written to `dir/name`.
fs::path edge_variant(const fs::path& dir, const std::string& name, const std::string& from, const std::string& to) {
  std::ifstream in(kData / "edge_cases.osm");
  std::string text(std::istreambuf_iterator<char>(in), {});
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

}  // namespace

TEST_CASE("course import: the nine-hole map's holes, pars, lengths and stroke indexes", "[course][import]") {
  Scratch s("nine");
  const ImportResult r = import(kData / "nine_holes.osm", s.dir / "nine");
  CHECK(r.name == "Fixture Nine");
  REQUIRE(r.holes.size() == 9);
  // As mapped (scripts/gen_osm_fixture.py): par, handicap and the dist tag, m, tee to green
  // along the line (the cup moves 4 m past the centre on holes 1, 4 and 7, where a pin is mapped).
  const int par[] = {4, 3, 5, 4, 4, 3, 4, 5, 4}, index[] = {5, 9, 1, 6, 3, 8, 4, 2, 7};
  const GolfMap map = read_golf_map(kData / "nine_holes.osm");
  for (std::size_t i = 0; i < 9; ++i) {
    INFO("hole " << i + 1);
    CHECK(r.holes[i].number == static_cast<int>(i) + 1);
    CHECK(r.holes[i].par == par[i]);
    CHECK(r.holes[i].index == index[i]);
    const MapHole* mh = nullptr;
    for (const MapHole& h : map.holes)
      if (h.ref == std::to_string(i + 1)) mh = &h;
    REQUIRE(mh != nullptr);
    REQUIRE(mh->dist);
    const double pin_shift = (i == 0 || i == 3 || i == 6) ? 4.0 : 0.0;
    CHECK(r.holes[i].length == Approx(*mh->dist + pin_shift).margin(1.0));
  }
  // The course loads as any course does, tees and cups where the import put them.
  const Course c = load_course(test::assets(), (s.dir / "nine").string());
  REQUIRE(c.holes.size() == 9);
  CHECK(c.par() == 36);
  for (std::size_t i = 0; i < 9; ++i) {
    CHECK(c.holes[i].tee.x() == Approx(r.holes[i].tee.x).margin(1e-3));
    CHECK(c.holes[i].pin.z() == Approx(r.holes[i].pin.z).margin(1e-3));
  }
  CHECK(s.no_leftovers());
}

TEST_CASE("course import: every surface lies where the map draws it, and the mesh keeps the mapped edges", "[course][import]") {
  Scratch s("surfaces");
  const fs::path map_path = kData / "nine_holes.osm";
  std::vector<std::string> report;
  const GolfMap map = read_golf_map(map_path);
  const LocalFrame frame = LocalFrame::around(map);
  const SurfacePlan plan(map, frame, report);
  // The fixture's 1st hole runs east from its tee along the row at 0 m north; a point in each
  // surface, through the frame (x east, z south).
  const auto at = [&](double east, double north) {
    const LocalPoint o = frame.to_local({56.34, -2.80});
    return plan.material_at(o.x + east, o.z - north);
  };
  CHECK(at(0.0, 0.0) == "tee");
  CHECK(at(250.0, 0.0) == "fairway");
  CHECK(at(365.0, 0.0) == "green");
  CHECK(at(365.0 - 4.0, -18.0) == "sand");      // the greenside bunker
  CHECK(at(100.0, 40.0) == "rough");
  CHECK(at(-55.0, 0.0) == "out_of_bounds");     // west of the boundary (40 m west of the tee)
  CHECK(at(200.0, 7 * 90.0 + 29.0) == "water"); // the burn along the 8th
  // The 5th green (east, like every odd hole) is a relation with a pot bunker cut into it: sand in the hole, green around.
  CHECK(at(395.0 - 6.0, 4 * 90.0 + 5.0) == "sand");
  CHECK(at(395.0 + 6.0, 4 * 90.0) == "green");
  // Areas: nine 16 x 13 m elliptical greens (24-gons) less the pot bunker and the bunkers' bites.
  const double polygon = 0.5 * 24 * 16.0 * 13.0 * std::sin(2.0 * 3.14159265358979 / 24);  // one 24-gon's area
  CHECK(plan.area("green") < 9 * polygon);
  CHECK(plan.area("green") > 9 * polygon - 9 * 30.0 - 40.0);
  // Every node of every mapped green is a vertex of the written ground: its edges are the
  // map's, not a staircase of cells.
  import(map_path, s.dir / "c");
  const std::vector<Vec3> v = obj_vertices(s.dir / "c" / "world.obj.gz");
  int checked = 0;
  for (const MapArea& a : map.areas) {
    if (a.surface != MapSurface::Green) continue;
    for (const MapPolygon& p : a.polygons)
      for (const GeoPoint& g : p.outer) {
        const LocalPoint q = frame.to_local(g);
        double nearest = 1e9;
        for (const Vec3& w : v) nearest = std::min(nearest, std::hypot(w.x() - q.x, w.z() - q.z));
        INFO(a.element << " node at " << q.x << ", " << q.z);
        CHECK(nearest < 1e-3);
        ++checked;
      }
  }
  CHECK(checked >= 9 * 24);
}

TEST_CASE("course import: what the map leaves out is mended and said", "[course][import]") {
  Scratch s("edges");
  const ImportResult r = import(kData / "edge_cases.osm", s.dir / "e");
  REQUIRE(r.holes.size() == 2);
  CHECK(r.holes[0].par == 4);  // 330 m: no par tag, par from its length
  CHECK(has_report(r, "way 100", "no par mapped; par 4"));
  CHECK(r.holes[1].par == 3);
  CHECK(r.holes[0].length == Approx(330.0).margin(1.5));
  CHECK(has_report(r, "way 201", "ring closed"));
  CHECK(has_report(r, "no leisure=golf_course boundary"));
  std::vector<std::string> report;
  const GolfMap map = read_golf_map(kData / "edge_cases.osm");
  const LocalFrame frame = LocalFrame::around(map);
  const SurfacePlan plan(map, frame, report);
  const auto at = [&](double east, double north) {
    const LocalPoint o = frame.to_local({56.34, -2.80});
    return plan.material_at(o.x + east, o.z - north);
  };
  CHECK(at(330.0, 0.0) == "green");    // the relation's green, inside the fairway
  CHECK(at(324.0, 6.0) == "sand");     // its inner ring, a bunker
  CHECK(at(318.0, -10.0) == "green");
  CHECK(at(200.0, 0.0) == "fairway");
  CHECK(at(250.0, 85.0) == "water");   // the lateral hazard
  CHECK(at(330.0, 60.0) == "tee");     // the tee ring closed across its gap
  CHECK(at(330.0, 120.0) == "rough");  // within 40 m of a mapped area: the assumed course
  CHECK(at(330.0, 150.0) == "out_of_bounds");  // past it, in the 30 m ring of out of bounds
  CHECK(at(330.0, 300.0).empty());             // off the world
  // The cup: the green's centre, 4 m from the bunker's corner, is fair (>= 3 m in).
  const LocalPoint c = frame.to_local({56.34, -2.7946584});
  CHECK(r.holes[0].pin.x == Approx(c.x).margin(0.01));
}

TEST_CASE("course import: bad maps are refused naming the file or the element; nothing is written", "[course][import][input]") {
  Scratch s("bad");
  const auto variant = [&](const std::string& name, const std::string& from, const std::string& to) {
    return edge_variant(s.dir, name, from, to);
  };
  const fs::path out = s.dir / "out";
  {
    const fs::path p = s.dir / "notes.osm";
    std::ofstream(p) << "these are not the map you are looking for\n";
    CHECK_THROWS_WITH(import(p, out), Contains("notes.osm") && Contains("not OpenStreetMap"));
  }
  // No holes at all: only a green.
  {
    const fs::path p = s.dir / "no_holes.osm";
    std::ofstream(p) << "<?xml version='1.0'?>\n<osm version='0.6'>\n"
                        "<node id='1' lat='56.34' lon='-2.8'/><node id='2' lat='56.3401' lon='-2.8'/>"
                        "<node id='3' lat='56.3401' lon='-2.7998'/>\n"
                        "<way id='9'><nd ref='1'/><nd ref='2'/><nd ref='3'/><nd ref='1'/><tag k='golf' v='green'/></way>\n</osm>\n";
    CHECK_THROWS_WITH(import(p, out), Contains("no_holes.osm") && Contains("no golf=hole ways"));
  }
  // Hole 2's green is not there.
  CHECK_THROWS_WITH(import(variant("no_green.osm", "<tag k='golf' v='green'/>\n  </way>\n  <!-- a lateral", "</way>\n  <!-- a lateral"), out),
                    Contains("way 200") && Contains("no golf=green within 40 m"));
  // The tee ring left open by 30 m instead of 0.5.
  CHECK_THROWS_WITH(import(variant("open_ring.osm", "<node id='54' lat='56.34049907'", "<node id='54' lat='56.34076000'"), out),
                    Contains("way 201") && Contains("not closed"));
  // A tee in the water.
  CHECK_THROWS_WITH(import(variant("wet_tee.osm", "<node id='40' lat='56.34053954' lon='-2.79465840'/>",
                                   "<node id='40' lat='56.34076000' lon='-2.79600000'/>"),
                           out),
                    Contains("way 200") && Contains("lies on water"));
  CHECK_FALSE(fs::exists(out));
  CHECK(s.no_leftovers());
  // An output that exists is never overwritten.
  fs::create_directories(out);
  CHECK_THROWS_WITH(import(kData / "edge_cases.osm", out), Contains("already exists"));
  CHECK(fs::is_empty(out));
}

// The tour bot on the imported nine: every hole holed, a card around the map's par of 36
// (nine holes of 155-490 m on flat, open ground: a tour player's 33-37).
TEST_CASE("course import: a tour bot plays the imported nine to about its par", "[course][import][golf][bot]") {
  Scratch s("round");
  import(kData / "nine_holes.osm", s.dir / "nine");
  const Course c = load_course(test::assets(), (s.dir / "nine").string());
  GolfRound round(test::assets(), c, golfer_skill("tour"));
  GolfBot bot(test::assets(), golfer_skill("tour"), 3);
  while (!round.finished()) round.play(bot.plan(round));
  int strokes = 0;
  for (const HoleCard& h : round.card()) {
    INFO("hole " << h.number << ": " << h.strokes << " on a par " << h.par);
    CHECK(h.holed);
    CHECK(h.strokes <= h.par + 2);
    CHECK(h.strokes >= h.par - 2);
    strokes += h.strokes;
  }
  CHECK(strokes >= c.par() - 5);
  CHECK(strokes <= c.par() + 4);
}

// ---- elevation (--dem) ---------------------------------------------------------------------

namespace {

// A GeoTIFF in UTM zone 30N (EPSG:32630) under the nine-hole fixture, 1 m cells, made here:
// the ground rises 1 % to the east, and round the 3rd green an 8 % ramp climbs east of its
// centre (a green steep on its east half, gentle on its west). `shift_east` m moves the whole
// raster (a raster of another place).
struct Utm {
  OGRSpatialReferenceH wgs = nullptr, utm = nullptr;
  OGRCoordinateTransformationH to = nullptr;
  Utm() {
    wgs = OSRNewSpatialReference(nullptr);
    utm = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(wgs, 4326);
    OSRImportFromEPSG(utm, 32630);
    OSRSetAxisMappingStrategy(wgs, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(utm, OAMS_TRADITIONAL_GIS_ORDER);
    to = OCTNewCoordinateTransformation(wgs, utm);
  }
  ~Utm() {
    OCTDestroyCoordinateTransformation(to);
    OSRDestroySpatialReference(wgs);
    OSRDestroySpatialReference(utm);
  }
  // The fixture's (east, north) offsets from 56.34 N, 2.80 W (scripts/gen_osm_fixture.py's metres).
  std::pair<double, double> of(double east, double north) const {
    const double m_lat = 111132.954 - 559.822 * std::cos(2 * 56.34 * 3.14159265358979 / 180.0);
    const double m_lon = 111412.84 * std::cos(56.34 * 3.14159265358979 / 180.0);
    double x = -2.80 + east / m_lon, y = 56.34 + north / m_lat;
    OCTTransform(to, 1, &x, &y, nullptr);
    return {x, y};
  }
};

// The ground's height at UTM (e, n): `tee` the 1st tee's and `green3` the 3rd green's
// centre in UTM (Utm::of), worked out once by the caller.
double ground(const std::pair<double, double>& tee, const std::pair<double, double>& green3, double e, double n) {
  double h = 50.0 + 0.01 * (e - tee.first);
  if (std::abs(n - green3.second) < 40.0 && e > green3.first) h += 0.08 * (e - green3.first);
  return h;
}

fs::path make_raster(const fs::path& path, double shift_east, bool with_crs = true) {
  GDALAllRegister();
  const Utm u;
  const auto [w0, s0] = u.of(-120.0, -120.0);
  const auto [e1, n1] = u.of(650.0, 850.0);
  const int width = static_cast<int>(e1 - w0) + 1, height = static_cast<int>(n1 - s0) + 1;
  GDALDriverH drv = GDALGetDriverByName("GTiff");
  GDALDatasetH ds = GDALCreate(drv, path.string().c_str(), width, height, 1, GDT_Float32, nullptr);
  double gt[6] = {std::floor(w0) + shift_east, 1.0, 0.0, std::ceil(n1), 0.0, -1.0};
  GDALSetGeoTransform(ds, gt);
  if (with_crs) {
    char* wkt = nullptr;
    OSRExportToWkt(u.utm, &wkt);
    GDALSetProjection(ds, wkt);
    CPLFree(wkt);
  }
  std::vector<float> row(static_cast<std::size_t>(width));
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  const auto tee = u.of(0.0, 0.0), green3 = u.of(470.0, 180.0);
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c)
      row[static_cast<std::size_t>(c)] = static_cast<float>(ground(tee, green3, gt[0] - shift_east + c + 0.5, gt[3] - r - 0.5));
    REQUIRE(GDALRasterIO(band, GF_Write, 0, r, width, 1, row.data(), width, 1, GDT_Float32, 0, 0) == CE_None);
  }
  GDALClose(ds);
  return path;
}

}  // namespace

TEST_CASE("course import --dem: the ground follows the raster; greens smooth, cups level, bunkers sunk, water flat",
          "[course][import][dem]") {
  Scratch s("dem");
  const fs::path tif = make_raster(s.dir / "ground.tif", 0.0);
  ImportOptions o;
  o.map = kData / "nine_holes.osm";
  o.dem = tif;
  o.out = s.dir / "hilly";
  const ImportResult r = import_course(test::assets(), o);
  CHECK(has_report(r, "ground from ground.tif"));
  const Course c = load_course(test::assets(), o.out.string());
  const Utm u;
  // Tees stand on the raster's ground, heights from hole 1's tee (1 % a metre east).
  const auto tee_utm = u.of(0.0, 0.0), green3_utm = u.of(470.0, 180.0);
  const auto raw = [&](double e, double n) {
    const auto [x, y] = u.of(e, n);
    return ground(tee_utm, green3_utm, x, y);
  };
  CHECK(c.holes[0].tee.y() == Approx(0.0).margin(0.02));
  CHECK(c.holes[1].tee.y() == Approx(raw(520.0, 90.0) - raw(0.0, 0.0)).margin(0.05));  // 5.2 m up
  // Every cup on a putting surface of 3 % at most; the 3rd's moved off the ramp, west of the
  // green's centre (470 m east), out of the ramp's 8 %.
  for (const ImportedHole& h : r.holes) {
    INFO("hole " << h.number << " cup slope " << h.pin_slope);
    CHECK(h.pin_slope <= kMaxPinSlope + 1e-9);
  }
  const LocalPoint centre3 = LocalFrame::around(read_golf_map(o.map)).to_local({56.34 + 180.0 / 111064.2, -2.80 + 470.0 / 61688.0});
  const ElevationModel dem(tif);
  CHECK(green_slope(dem, LocalFrame::around(read_golf_map(o.map)), centre3) > kMaxPinSlope);  // its deepest point is too steep
  CHECK(r.holes[2].pin.x < centre3.x - 1.0);
  // The written ground: bunkers below the raster's ground, water one flat plane below its bank.
  const std::vector<Vec3> v = obj_vertices(o.out / "world.obj.gz");
  std::vector<std::string> report;
  const GolfMap map = read_golf_map(o.map);
  const LocalFrame frame = LocalFrame::around(map);
  const SurfacePlan plan(map, frame, report);
  const double tee1 = raw(0.0, 0.0);
  int sunk = 0, wet = 0;
  double level = 0.0;
  for (const Vec3& p : v) {
    const std::string m = plan.material_at(p.x(), p.z());
    if (m != "sand" && m != "water") continue;  // the raster's look-up only where it is checked
    const GeoPoint g = frame.to_geo({p.x(), p.z()});
    double x = g.lon, y = g.lat;
    OCTTransform(u.to, 1, &x, &y, nullptr);
    const double below = ground(tee_utm, green3_utm, x, y) - tee1 - p.y();
    if (m == "sand" && plan.depth_inside(p.x(), p.z()) > 1.0) {
      CHECK(below > 0.3);
      ++sunk;
    }
    if (m == "water" && plan.depth_inside(p.x(), p.z()) > 0.5 && plan.water_at(p.x(), p.z()) == 0) {
      if (wet++ == 0) level = p.y();
      CHECK(p.y() == Approx(level).margin(1e-9));
      CHECK(below > 0.25);
    }
  }
  CHECK(sunk > 20);
  CHECK(wet > 5);
  // The greens' grid is 0.5 m: a vertex for every quarter square metre of green.
  int on_green = 0;
  for (const Vec3& p : v) on_green += plan.material_at(p.x(), p.z()) == "green" ? 1 : 0;
  CHECK(on_green > 0.9 * plan.area("green") / 0.25);
}

TEST_CASE("course import --dem: a raster of another place, or none, is refused naming the file", "[course][import][dem][input]") {
  Scratch s("dem_bad");
  ImportOptions o;
  o.map = kData / "nine_holes.osm";
  o.out = s.dir / "c";
  o.dem = make_raster(s.dir / "elsewhere.tif", 100000.0);
  CHECK_THROWS_WITH(import_course(test::assets(), o), Contains("elsewhere.tif") && Contains("does not cover the course"));
  o.dem = make_raster(s.dir / "nowhere.tif", 0.0, false);
  CHECK_THROWS_WITH(import_course(test::assets(), o), Contains("nowhere.tif") && Contains("no coordinate reference system"));
  o.dem = s.dir / "notes.tif";
  std::ofstream(o.dem) << "not a raster\n";
  CHECK_THROWS_WITH(import_course(test::assets(), o), Contains("notes.tif") && Contains("not an elevation raster"));
  CHECK_FALSE(fs::exists(o.out));
  CHECK(s.no_leftovers());
}

// The same map as an Overpass API export (edge_cases.json: its elements, ways before nodes
// as `out body; >; out skel;` lists them) and as PBF (written here by libosmium from the
// XML) imports to the same course.
TEST_CASE("course import: Overpass JSON and PBF read as the XML does", "[course][import]") {
  Scratch s("formats");
  const ImportResult xml = import(kData / "edge_cases.osm", s.dir / "xml");
  const ImportResult json = import(kData / "edge_cases.json", s.dir / "json");
  {
    osmium::io::Reader in(osmium::io::File((kData / "edge_cases.osm").string()));
    osmium::io::Writer out(osmium::io::File((s.dir / "edge_cases.osm.pbf").string()));
    while (osmium::memory::Buffer b = in.read()) out(std::move(b));
    out.close();
    in.close();
  }
  const ImportResult pbf = import(s.dir / "edge_cases.osm.pbf", s.dir / "pbf");
  for (const ImportResult* r : {&json, &pbf}) {
    REQUIRE(r->holes.size() == xml.holes.size());
    for (std::size_t i = 0; i < xml.holes.size(); ++i) {
      CHECK(r->holes[i].par == xml.holes[i].par);
      CHECK(r->holes[i].pin.x == Approx(xml.holes[i].pin.x).margin(1e-6));
      CHECK(r->holes[i].tee.z == Approx(xml.holes[i].tee.z).margin(1e-6));
    }
    CHECK(r->triangles == xml.triangles);
    CHECK(r->areas.at("green") == Approx(xml.areas.at("green")).epsilon(1e-9));
  }
  const fs::path bad = s.dir / "bad.json";
  std::ofstream(bad) << "{\"version\": 0.6}";
  CHECK_THROWS_WITH(import(bad, s.dir / "bad"), Contains("bad.json") && Contains("no \"elements\" array"));
}

// A course's name comes from the map (or --name) and is written into TOML and OBJ comments:
// quotes and line breaks in it cannot break either file.
TEST_CASE("course import: a hostile course name is written safely", "[course][import][input]") {
  Scratch s("name");
  ImportOptions o;
  o.map = kData / "edge_cases.osm";
  o.out = s.dir / "c";
  o.name = "St Andrew's \"Old\" \\ Course name = \"hijacked\"";
  import_course(test::assets(), o);
  const Course c = load_course(test::assets(), o.out.string());
  CHECK(c.name == "St Andrew's \"Old\" \\ Course name = \"hijacked\"");
  // A line break or a terminal's escape in --name is refused, naming the flag: a card's
  // title is one line, and a name printed to a terminal cannot clear its screen.
  o.out = s.dir / "d";
  o.name = "Old\nname = \"hijacked\"";
  CHECK_THROWS_WITH(import_course(test::assets(), o), Contains("--name") && Contains("control character"));
  o.name = "a\x1b[2Jb";
  CHECK_THROWS_WITH(import_course(test::assets(), o), Contains("--name") && Contains("control character"));
  CHECK_FALSE(fs::exists(o.out));
}

// Hostile maps: nodes off the globe, a green with no area, a stray node kilometres away, a
// ref that is not a number, a grid too fine for the course: each refused naming what is
// wrong, never a crash or an hours-long mesh.
TEST_CASE("course import: hostile maps are refused, not run", "[course][import][input]") {
  Scratch s("hostile");
  const auto variant = [&](const std::string& name, const std::string& from, const std::string& to) {
    return edge_variant(s.dir, name, from, to);
  };
  const fs::path out = s.dir / "out";
  // Hole 1's green node off the globe, and a green's node off it (that one used to drop out
  // of the green's ring unsaid): refused, naming the node.
  CHECK_THROWS_WITH(import(variant("off_globe.osm", "<node id='2' lat='56.34000000'", "<node id='2' lat='96.34000000'"), out),
                    Contains("node 2") && Contains("off the globe"));
  CHECK_THROWS_WITH(import(variant("off_globe_green.osm", "<node id='54' lat='56.34049907'", "<node id='54' lat='95.0'"), out),
                    Contains("node 54") && Contains("latitude -90..90"));
  // Green 2 squashed flat (its nodes on one line): no green for hole 2 to end on.
  {
    std::ifstream in(kData / "edge_cases.osm");
    std::string t(std::istreambuf_iterator<char>(in), {});
    for (const char* id : {"62", "63"}) {
      const auto at = t.find(std::string("<node id='") + id + "' lat='56.34064743'");
      REQUIRE(at != std::string::npos);
      t.replace(at, std::string("<node id='62' lat='56.34064743'").size(), std::string("<node id='") + id + "' lat='56.34043165'");
    }
    std::ofstream(s.dir / "flat_green.osm") << t;
    CHECK_THROWS_WITH(import(s.dir / "flat_green.osm", out), Contains("way 200") && Contains("no golf=green"));
  }
  // A bunker node 40 km off.
  CHECK_THROWS_WITH(import(variant("stray.osm", "<node id='31' lat='56.34002697' lon='-2.79470696'/>",
                                   "<node id='31' lat='56.34002697' lon='-2.19470696'/>"),
                           out),
                    Contains("spans") && Contains("far-off feature"));
  CHECK_THROWS_WITH(import(variant("ref.osm", "<tag k='ref' v='2'/>", "<tag k='ref' v='2;3'/>"), out),
                    Contains("way 200") && Contains("ref=2;3"));
  ImportOptions fine;
  fine.map = kData / "nine_holes.osm";
  fine.out = out;
  fine.cell = 0.5;
  CHECK_THROWS_WITH(import_course(test::assets(), fine), Contains("--cell 0.50") && Contains("million cells"));
  CHECK_FALSE(fs::exists(out));
  CHECK(s.no_leftovers());
}

TEST_CASE("course import: a mapped tree stands in the rough, blocks a shot flown into its crown, and the ground under it is rough",
          "[course][import][tree]") {
  Scratch s("tree");
  // A 15 m tree 40 m out on hole 1's line, in the rough short of the fairway; and one on the
  // fairway, which is left out (a fairway is kept clear).
  const std::string before = "  <!-- fairway 120..330 m east";
  const fs::path treed = edge_variant(s.dir, "treed.osm", before,
                                      "  <node id='900' lat='56.34000000' lon='-2.79935253'><tag k='natural' v='tree'/>"
                                      "<tag k='height' v='15 m'/></node>\n"
                                      "  <node id='901' lat='56.34000000' lon='-2.79627000'><tag k='natural' v='tree'/></node>\n" + before);
  const ImportResult with = import(treed, s.dir / "with");
  const ImportResult without = import(kData / "edge_cases.osm", s.dir / "without");
  CHECK(with.trees == 1);
  CHECK(without.trees == 0);
  CHECK(has_report(with, "trees planted: 1 (1 mapped", "1 left out"));
  // The same pitch (80 mph, 16°, 4000 rpm: ~10 m up as it passes 40 m) down the line from hole
  // 1's tee: over open rough it carries far past the tree; into the crown it drops out near it.
  ShotSpec spec = test::launch_spec("golf", 80.0, 16.0, 4000.0);
  spec.world = (s.dir / "without" / "world.toml").string();
  const ShotResult open = run_shot(resolve(spec, test::assets()), "test");
  spec.world = (s.dir / "with" / "world.toml").string();
  const ShotResult blocked = run_shot(resolve(spec, test::assets()), "test");
  CHECK(open.trajectory.summary.carry_m > 70.0);
  // The world's origin is hole 1's tee; the tree stands 40 m east of it.
  const Vec3 tree = test::assets().world((s.dir / "with" / "world.toml").string())->description().origin + Vec3(40.0, 0.0, 0.0);
  const Vec3& rest = blocked.trajectory.summary.rest_position;
  INFO("rest " << rest.transpose() << ", tree " << tree.transpose() << ", open carry " << open.trajectory.summary.carry_m);
  CHECK(std::hypot(rest.x() - tree.x(), rest.z() - tree.z()) < 15.0);
  CHECK(blocked.trajectory.summary.total_m < 0.7 * open.trajectory.summary.carry_m);
  CHECK(blocked.end == ShotEnd::Rest);
  CHECK(rest.y() < 0.5);  // on the ground, not in the tree
  // The ground under the crown is the rough the tree stands in.
  const WorldAsset* world = test::assets().world((s.dir / "with" / "world.toml").string());
  REQUIRE(world != nullptr);
  SurfaceContact under;
  REQUIRE(ground_under(*world->world, tree.x(), tree.z() + 0.5, 100.0, 200.0, &under));
  CHECK(world->world->material(under.material).name == "rough");
  CHECK(under.point.y() == Approx(0.0).margin(1e-6));
}

TEST_CASE("course import: named tee boxes become tee sets and each green gets spread pin sets a round can choose",
          "[course][import]") {
  Scratch s("sets");
  const ImportResult r = import(kData / "nine_holes.osm", s.dir / "nine");
  // The 1st has a white box round its line's first node and a red one 40 m on (scripts/gen_osm_fixture.py).
  REQUIRE(r.holes[0].tee_sets.size() == 2);
  CHECK(r.holes[0].tee_sets[0].first == "white");
  CHECK(r.holes[0].tee_sets[1].first == "red");
  CHECK(std::hypot(r.holes[0].tee_sets[0].second.x - r.holes[0].tee.x, r.holes[0].tee_sets[0].second.z - r.holes[0].tee.z) < 0.5);
  for (std::size_t i = 1; i < r.holes.size(); ++i) CHECK(r.holes[i].tee_sets.empty());
  // Pin sets: up to kPinSets cups a green, each on it, kPinSpread apart.
  for (const ImportedHole& h : r.holes) {
    INFO("hole " << h.number);
    CHECK(h.more_pins.size() == static_cast<std::size_t>(kPinSets - 1));  // the fixture's greens are 32 x 26 m
    std::vector<LocalPoint> all{h.pin};
    all.insert(all.end(), h.more_pins.begin(), h.more_pins.end());
    for (std::size_t a = 0; a < all.size(); ++a)
      for (std::size_t b = a + 1; b < all.size(); ++b) CHECK(std::hypot(all[a].x - all[b].x, all[a].z - all[b].z) >= kPinSpread);
  }
  Course c = load_course(test::assets(), (s.dir / "nine").string());
  CHECK(tee_set_names(c) == std::vector<std::string>{"white", "red"});
  const Course plain = c;
  set_up(c, {"red", 3});
  CHECK(c.holes[0].tee.x() == Approx(plain.holes[0].tee.x() + 40.0).margin(0.5));
  CHECK(c.holes[1].tee.x() == Approx(plain.holes[1].tee.x()).margin(1e-9));  // no red tee there: its own
  for (std::size_t i = 0; i < c.holes.size(); ++i) {
    CHECK(c.holes[i].pin.x() == Approx(r.holes[i].more_pins[1].x).margin(1e-3));
    CHECK(c.holes[i].pin.z() == Approx(r.holes[i].more_pins[1].z).margin(1e-3));
  }
  CHECK(c.setup.tees == "red");
  // Pin set 5 of 4 is refused with the sets there are, never cycled back to the first.
  Course cycled = plain;
  CHECK_THROWS_WITH(set_up(cycled, {"", 5}), Contains("pin set 5") && Contains("has 4 pin sets (allowed 0..4"));
  // Pin set 0, the day's mix: hole n (from 0) takes its set n, cycling through its own, so a
  // round meets its middle pin on some greens and the edge pins on the rest.
  Course mixed = plain;
  set_up(mixed, {"", 0});
  std::size_t middle = 0;
  for (std::size_t i = 0; i < mixed.holes.size(); ++i) {
    const std::size_t k = i % (r.holes[i].more_pins.size() + 1);
    const double want_x = k == 0 ? plain.holes[i].pin.x() : r.holes[i].more_pins[k - 1].x;
    CHECK(mixed.holes[i].pin.x() == Approx(want_x).margin(1e-3));
    middle += k == 0 ? 1 : 0;
  }
  CHECK(middle >= 1);
  CHECK(middle < mixed.holes.size());
  CHECK(mixed.setup.pin_set == 0);
  Course wrong = plain;
  CHECK_THROWS_WITH(set_up(wrong, {"blue", 1}), Contains("no tee set 'blue'") && Contains("allowed: white, red"));
}

TEST_CASE("course import: a cart path is a paved strip of its width; a ball at rest on it is moved off it free, no nearer the hole",
          "[course][import]") {
  Scratch s("path");
  const ImportResult r = import(kData / "nine_holes.osm", s.dir / "nine");
  // scripts/gen_osm_fixture.py: 500 m of path, 3 m wide, clear of every other surface.
  REQUIRE(r.areas.count("cart_path") == 1);
  CHECK(r.areas.at("cart_path") == Approx(500.0 * 3.0).epsilon(0.02));
  const GolfMap map = read_golf_map(kData / "nine_holes.osm");
  REQUIRE(map.paths.size() == 1);
  CHECK(map.paths[0].width == 3.0);
  const LocalPoint on = LocalFrame::around(map).to_local(map.paths[0].line[1]);  // its middle node, on the path
  const Course c = load_course(test::assets(), (s.dir / "nine").string());
  const GolfRound round(test::assets(), c, golfer_skill("tour"));
  const WorldAsset& w = *c.holes[0].world;
  SurfaceContact hit;
  REQUIRE(ground_under(*w.world, on.x, on.z, 100.0, 200.0, &hit));
  CHECK(w.world->material(hit.material).name == "cart_path");
  const Vec3 spot(on.x, hit.point.y(), on.z);
  const Vec3 relief = round.free_relief(spot);
  // The nearest ground off the 3 m strip: 1.5 m to its edge, within the search's 0.25 m rings.
  const double moved = std::hypot(relief.x() - spot.x(), relief.z() - spot.z());
  CHECK(moved > 1.5);
  CHECK(moved <= 2.0);
  const Vec3& pin = c.holes[0].pin;
  CHECK(std::hypot(pin.x() - relief.x(), pin.z() - relief.z()) >= std::hypot(pin.x() - spot.x(), pin.z() - spot.z()));
  REQUIRE(ground_under(*w.world, relief.x(), relief.z(), 100.0, 200.0, &hit));
  CHECK(w.world->material(hit.material).name == "rough");
}

TEST_CASE("course import: a ball on another hole's green is moved off it free (Rule 13.1f); on its own green it is putted",
          "[course][import]") {
  Scratch s("wrong_green");
  import(kData / "nine_holes.osm", s.dir / "nine");
  const Course c = load_course(test::assets(), (s.dir / "nine").string());
  REQUIRE(c.holes.size() >= 2);
  const GolfRound round(test::assets(), c, golfer_skill("tour"));  // on the first hole
  const WorldAsset& w = *c.holes[0].world;
  SurfaceContact hit;
  const auto on_ground = [&](const Vec3& p) {
    REQUIRE(ground_under(*w.world, p.x(), p.z(), 100.0, 200.0, &hit));
    return Vec3(p.x(), hit.point.y(), p.z());
  };
  // Beside the first hole's cup: its own green.
  const Vec3 own = on_ground(c.holes[0].pin + Vec3(1.0, 0.0, 0.0));
  REQUIRE(round.surface_at(own) == "green");
  CHECK_FALSE(round.on_another_green(own));
  // At the second hole's cup: a green no stretch of green joins to the first hole's.
  const Vec3 other = on_ground(c.holes[1].pin);
  REQUIRE(round.surface_at(other) == "green");
  CHECK(round.on_another_green(other));
  const Vec3 relief = round.free_relief(other);
  CHECK(round.surface_at(relief) != "green");
  CHECK(std::hypot(relief.x() - other.x(), relief.z() - other.z()) > 0.0);
  // Off a green there is nothing to take relief from.
  CHECK_FALSE(round.on_another_green(relief));
}

TEST_CASE("course import: a tree row or wood drawn across the country costs no more than the course", "[course][import][hostile]") {
  Scratch s("far_trees");
  // A row 300 km long through the course, and a wood that is a thin sliver as long, beside it.
  const fs::path map = edge_variant(s.dir, "far.osm", "</osm>",
                                    "  <node id='910' lat='56.34030000' lon='-5.00000000'/>\n"
                                    "  <node id='911' lat='56.34030000' lon='0.50000000'/>\n"
                                    "  <way id='920'><nd ref='910'/><nd ref='911'/><tag k='natural' v='tree_row'/></way>\n"
                                    "  <node id='912' lat='56.34035000' lon='-5.00000000'/>\n"
                                    "  <node id='913' lat='56.34035000' lon='0.50000000'/>\n"
                                    "  <node id='914' lat='56.34036000' lon='0.50000000'/>\n"
                                    "  <node id='915' lat='56.34036000' lon='-5.00000000'/>\n"
                                    "  <way id='921'><nd ref='912'/><nd ref='913'/><nd ref='914'/><nd ref='915'/><nd ref='912'/>"
                                    "<tag k='natural' v='wood'/></way>\n</osm>");
  const ImportResult r = import(map, s.dir / "c");
  CHECK(r.trees > 0);
  CHECK(r.trees <= kMaxTrees);
  // Only the stretch over the course's ground is walked: a row of ~60 trees, not ~40 000.
  CHECK(has_report(r, "trees planted:"));
  INFO(r.trees << " trees");
  CHECK(r.trees < 400);
}
