// What a golf course's OpenStreetMap data says (DESIGN §9, course import): its mapped areas
// (greens, tees, fairways, bunkers, water, rough, the course's boundary), its holes (the
// tee-to-green line with ref, par and handicap), its pins and its trees and woods, in
// latitude and longitude.
// read_golf_map() reads OSM XML or PBF through libosmium, which assembles multipolygon
// relations (a green with a hole in it, a fairway in several parts) into areas.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sweetspot {

struct GeoPoint {
  double lat = 0.0, lon = 0.0;  ///< degrees, WGS84
};

/// The surfaces a golf map draws, highest first: where two areas overlap (a green inside a
/// fairway, a bunker inside the rough) the one earlier here covers the ground.
enum class MapSurface { Green, Tee, Bunker, Water, LateralWater, CartPath, Fairway, Rough, Course };
const char* to_string(MapSurface s);

/// One area: outer rings with their holes, as mapped.
struct MapPolygon {
  std::vector<GeoPoint> outer;
  std::vector<std::vector<GeoPoint>> inners;
};
struct MapArea {
  MapSurface surface = MapSurface::Rough;
  std::string element;  ///< "way 123", "relation 45": what the map calls it, for messages
  std::vector<MapPolygon> polygons;
  /// A tee box's sets (tee=* split at ';', "blue", "white", ...; else its name=*): empty for
  /// other surfaces and for an unnamed box.
  std::vector<std::string> tee_sets;
};

/// A golf=hole way: from the tee (its first node) to the green (its last).
struct MapHole {
  std::string element;
  std::string ref;                 ///< the hole's number as mapped ("7")
  std::optional<int> par, handicap;
  std::optional<double> dist;      ///< m, the mapped length (dist=*), when given
  std::vector<GeoPoint> line;
};

/// A golf=pin node.
struct MapPin {
  std::string element;
  GeoPoint at;
};

/// A tree (natural=tree, a node) or a row of them (natural=tree_row, a way: trees along it).
struct MapTrees {
  std::string element;
  std::vector<GeoPoint> line;      ///< one point for a tree, the row's line for a row
  std::optional<double> height;    ///< m, height=* when mapped
};

/// A golf=cart_path way: a paved strip along its line.
struct MapPath {
  std::string element;
  std::vector<GeoPoint> line;
  double width = 0.0;  ///< m, width=* when mapped, else kCartPathWidth
};
/// A cart path's width when the map gives none: 8 ft, room for one cart (ESTIMATE of the
/// usual poured path; club guidance runs 6-10 ft).
inline constexpr double kCartPathWidth = 2.4;  // m

struct GolfMap {
  std::vector<MapArea> areas;
  std::vector<MapHole> holes;
  std::vector<MapPin> pins;
  std::vector<MapTrees> trees;     ///< single trees and tree rows
  std::vector<MapArea> woods;      ///< natural=wood and landuse=forest (the ground under them plays as rough)
  std::vector<MapPath> paths;      ///< golf=cart_path lines
  std::string name;                    ///< the leisure=golf_course name, when mapped
  std::vector<std::string> repairs;    ///< what was mended while reading, one line each
};

/// Calls `f(GeoPoint)` for every point of the course the map draws: each area's outer rings
/// each hole's line and each cart path (trees and woods stand where they stand: a forest reaching far off
/// does not widen the course).
template <class F>
void for_each_point(const GolfMap& map, F&& f) {
  for (const MapArea& a : map.areas)
    for (const MapPolygon& p : a.polygons)
      for (const GeoPoint& g : p.outer) f(g);
  for (const MapHole& h : map.holes)
    for (const GeoPoint& g : h.line) f(g);
  for (const MapPath& p : map.paths)
    for (const GeoPoint& g : p.line) f(g);
}

/// Reads `path` (.osm XML, .osm.pbf, or an Overpass API JSON export: .json or a file opening
/// with `{`). Throws InputError naming the file for one that is
/// not OSM data, and naming the element for a ring that is not closed by more than
/// kRingGap (a gap up to it is closed, and said in `repairs`). Areas whose rings do not
/// assemble are left out and said in `repairs`.
GolfMap read_golf_map(const std::filesystem::path& path);

/// m: a way meant as an area whose ends lie this close is closed with a last segment.
inline constexpr double kRingGap = 2.0;

}  // namespace sweetspot
