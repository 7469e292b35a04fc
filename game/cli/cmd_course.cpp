// `sweetspot course import MAP [--dem RASTER] [--name N] [-o DIR] [--cell M]`: an OpenStreetMap golf course
// (OSM XML or PBF) -> a course directory that `round --course DIR` plays (DESIGN §9).
#include <cstdio>
#include <iostream>
#include <memory>

#include "game/cli/command.hpp"
#include "game/courses/course_import.hpp"

namespace sweetspot::cli {
namespace {

RunFn setup_course(CLI::App& sub) {
  sub.require_subcommand(1, 1);
  CLI::App* imp = sub.add_subcommand("import", "read an OpenStreetMap golf course (.osm, .osm.pbf) and write a playable course directory");
  auto o = std::make_shared<ImportOptions>();
  auto map = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  imp->add_option("map", *map, "the map: OSM XML (.osm) or PBF (.osm.pbf) with golf=hole ways and golf areas")->required();
  auto dem = std::make_shared<std::string>();
  imp->add_option("--dem", *dem, "an elevation raster GDAL reads (GeoTIFF, an ASCII grid with its .prj) covering the course; without it the ground is flat");
  imp->add_option("--name", o->name, "the course's name (default: the map's leisure=golf_course name, else the file's)");
  imp->add_option("-o,--out", *out, "the course directory to write (must not exist; default: the name beside the map)");
  imp->add_option("--cell", o->cell, "m, the ground's grid where no mapped edge cuts it, 0.5-50 (default 4)");
  return [o, map, out, dem](const Assets& assets) -> int {
    ImportOptions opt = *o;
    opt.map = *map;
    opt.dem = *dem;
    opt.out = !out->empty() ? std::filesystem::path(*out) : opt.map.parent_path() / opt.map.stem().stem();
    const ImportResult r = import_course(assets, opt);
    std::cout << r.name << ": " << r.holes.size() << " holes, par ";
    int par = 0;
    for (const ImportedHole& h : r.holes) par += h.par;
    std::cout << par << ", written to " << opt.out.string() << "\n";
    for (const ImportedHole& h : r.holes) {
      char line[160];
      std::snprintf(line, sizeof line, "  hole %2d  par %d  %4.0f m (%3.0f yd)%s  %s\n", h.number, h.par, h.length, h.length / 0.9144,
                    h.index > 0 ? ("  index " + std::to_string(h.index)).c_str() : "", h.element.c_str());
      std::cout << line;
    }
    std::cout << "  ground: " << r.triangles << " triangles;";
    for (const auto& [m, a] : r.areas) {
      char line[64];
      std::snprintf(line, sizeof line, " %s %.0f m2", m.c_str(), a);
      std::cout << line;
    }
    std::cout << "\n";
    for (const std::string& s : r.report) std::cout << "  note: " << s << "\n";
    return 0;
  };
}

const CommandRegistrar course_command{34, "course", "course import: an OpenStreetMap golf course -> a playable course directory", setup_course};

}  // namespace
}  // namespace sweetspot::cli
