// `sweetspot course import` (DESIGN §9): OpenStreetMap golf data -> a course directory that
// `round`, `play --mode golf`, `connect --course` and `render` take like the built-in one:
// course.toml (the holes with their par, stroke index, tee and cup) over one world
// (world.toml, world.obj, world.mtl) whose ground follows the map's surfaces.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "game/content/assets.hpp"
#include "game/courses/local_frame.hpp"

namespace sweetspot {

struct ImportOptions {
  std::filesystem::path map;   ///< .osm or .osm.pbf
  std::filesystem::path dem;   ///< an elevation raster GDAL reads; empty: flat ground
  std::string name;            ///< the course's name ("" : the map's, else the file's stem)
  std::filesystem::path out;   ///< the course directory to write; must not exist yet
  double cell = 4.0;           ///< m, the ground's grid where no mapped edge cuts it
  double green_cell = 0.5;     ///< m, the greens' grid where the ground has heights
};

struct ImportedHole {
  int number = 0, par = 0;
  int index = 0;               ///< stroke index from handicap=*, 0 when the map gives none
  LocalPoint tee, pin;
  std::vector<LocalPoint> bends;  ///< the mapped line's nodes between tee and green
  std::vector<LocalPoint> more_pins;  ///< pin sets 2.. (kPinSets in all where the green holds them)
  std::vector<std::pair<std::string, LocalPoint>> tee_sets;  ///< named tee boxes of this hole
  double length = 0.0;         ///< m along the mapped line, tee to cup
  double pin_slope = 0.0;      ///< the putting surface's slope at the cup (rise over run)
  std::string element;         ///< the golf=hole way
};

struct ImportResult {
  std::string name;
  std::vector<ImportedHole> holes;
  std::vector<std::string> report;   ///< what was mended or assumed, one line each
  std::size_t triangles = 0;
  std::size_t trees = 0;              ///< planted (tree_planting.hpp)
  std::map<std::string, double> areas;  ///< m² by material
};

/// Cup positions per green, the mapped (or central) one first, each at least kPinSpread m
/// from the others: front, middle and back pins as a green staff rotates them (ESTIMATE of
/// a week's rotation on a ~30 m green).
inline constexpr int kPinSets = 4;
inline constexpr double kPinSpread = 7.0;  // m
/// A named tee box belongs to the hole whose tee (its line's first node) is nearest, within this.
inline constexpr double kTeeSearch = 150.0;  // m

/// A cup sits where the green slopes this much at most (the USGA's guidance on hole
/// locations: ~3 % at most at green speeds of 10-11 ft).
inline constexpr double kMaxPinSlope = 0.03;

/// Reads the map, lays the course out and writes it to `options.out` (a temporary directory
/// renamed into place once the course loads, so nothing half-written is ever left). Throws
/// InputError naming the file or the OSM element: not OSM data, no golf holes, a hole whose
/// last node has no green near it, a tee in water, an output that exists.
ImportResult import_course(const Assets& assets, const ImportOptions& options);

/// par from a hole's length where the map gives none: the USGA's guideline yardages for men
/// (Handicap System manual, §16-2 before 2020): up to 250 yd a par 3, to 470 yd a par 4, a
/// par 5 beyond.
int par_for_length(double metres);

}  // namespace sweetspot
