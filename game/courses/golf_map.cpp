#include "game/courses/golf_map.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <algorithm>
#include <string_view>

// libosmium's builders trip GCC 12's string over-read check on an inlined strlen of an empty
// tag (a false positive inside the library): silenced for its headers alone.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#endif
#include <osmium/area/assembler.hpp>
#include <osmium/area/multipolygon_manager.hpp>
#include <osmium/area/problem_reporter.hpp>
#include <osmium/handler.hpp>
#include <osmium/handler/node_locations_for_ways.hpp>
#include <osmium/index/map/flex_mem.hpp>
#include <osmium/io/pbf_input.hpp>
#include <osmium/io/xml_input.hpp>
#include <osmium/relations/relations_manager.hpp>
#include <osmium/visitor.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <nlohmann/json.hpp>

#include "game/util/xml_text.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

using Index = osmium::index::map::FlexMem<osmium::unsigned_object_id_type, osmium::Location>;
// Negative ids are an editor's new objects (JOSM's, before upload): they get their own index.
using LocationHandler = osmium::handler::NodeLocationsForWays<Index, Index>;

// The surface an object's tags map, if any.
std::optional<MapSurface> surface_of(const osmium::TagList& tags) {
  const char* golf = tags["golf"];
  if (golf != nullptr) {
    const std::string_view g(golf);
    if (g == "green") return MapSurface::Green;
    if (g == "tee") return MapSurface::Tee;
    if (g == "bunker") return MapSurface::Bunker;
    if (g == "water_hazard") return MapSurface::Water;
    if (g == "lateral_water_hazard") return MapSurface::LateralWater;
    if (g == "fairway") return MapSurface::Fairway;
    if (g == "rough") return MapSurface::Rough;
  }
  if (tags.has_tag("leisure", "golf_course")) return MapSurface::Course;
  if (tags.has_tag("natural", "water")) return MapSurface::Water;
  if (tags.has_tag("natural", "sand")) return MapSurface::Bunker;
  return std::nullopt;
}

// m between two nearby points (an equirectangular step: exact to a part in 10^6 at a few metres).
double metres_between(const GeoPoint& a, const GeoPoint& b) {
  constexpr double kEarth = 6371008.8;  // m, the IUGG mean radius
  constexpr double kRad = 3.14159265358979323846 / 180.0;
  const double x = (b.lon - a.lon) * kRad * std::cos(0.5 * (a.lat + b.lat) * kRad), y = (b.lat - a.lat) * kRad;
  return kEarth * std::hypot(x, y);
}

std::optional<int> whole(const char* text) {
  if (text == nullptr) return std::nullopt;
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 0 || v > 1000) return std::nullopt;
  return static_cast<int>(v);
}

// A length tag (a tree's height=*, a path's width=*): metres ("12", "12 m") within [lo, hi];
// else none.
std::optional<double> metres_tag(const char* text, double lo, double hi) {
  if (text == nullptr) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  std::string_view unit(end);
  while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
  if (end == text || !(v >= lo && v <= hi) || !(unit.empty() || unit == "m")) return std::nullopt;
  return v;
}
std::optional<double> height(const char* text) { return metres_tag(text, 1.0, 100.0); }

// dist=*: metres, or with a unit "m", "yd", "yards".
std::optional<double> distance(const char* text) {
  if (text == nullptr) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || !(v > 0.0) || v > 2000.0) return std::nullopt;
  std::string_view unit(end);
  while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
  if (unit.empty() || unit == "m") return v;
  if (unit == "yd" || unit == "yards") return v * 0.9144;
  return std::nullopt;
}

// Text a name may carry into course.toml: valid UTF-8 with no control bytes (a tag value is
// any bytes the map holds).
bool printable_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) return false;
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return false;
    i += n;
  }
  return true;
}

// A golf=tee box's sets: tee=* ("red;white" is two), else name=*.
std::vector<std::string> tee_sets_of(const osmium::TagList& tags) {
  std::vector<std::string> out;
  if (!tags.has_tag("golf", "tee")) return out;
  const char* v = tags["tee"] != nullptr ? tags["tee"] : tags["name"];
  if (v == nullptr) return out;
  std::string_view rest(v);
  while (!rest.empty()) {
    const std::size_t cut = rest.find(';');
    std::string_view one = rest.substr(0, cut);
    while (!one.empty() && one.front() == ' ') one.remove_prefix(1);
    while (!one.empty() && one.back() == ' ') one.remove_suffix(1);
    if (!one.empty() && one.size() <= 40 && printable_utf8(one) &&
        std::find(out.begin(), out.end(), one) == out.end())
      out.emplace_back(one);
    if (cut == std::string_view::npos) break;
    rest.remove_prefix(cut + 1);
  }
  return out;
}

std::vector<GeoPoint> ring_of(const osmium::NodeRefList& nodes) {
  std::vector<GeoPoint> ring;
  for (const osmium::NodeRef& n : nodes)
    if (n.location().valid()) ring.push_back({n.location().lat(), n.location().lon()});
  return ring;
}

class Collector : public osmium::handler::Handler {
 public:
  explicit Collector(GolfMap& map) : map_(map) {}

  void node(const osmium::Node& n) {
    // A node off the globe would drop out of every way it is on, silently reshaping a green.
    if (!n.location().valid())
      throw InputError("node " + std::to_string(n.id()) +
                       ": its location is missing or off the globe (allowed: latitude -90..90, longitude -180..180)");
    const GeoPoint at{n.location().lat(), n.location().lon()};
    if (n.tags().has_tag("golf", "pin")) map_.pins.push_back({"node " + std::to_string(n.id()), at});
    if (n.tags().has_tag("natural", "tree"))
      map_.trees.push_back({"node " + std::to_string(n.id()), {at}, height(n.tags()["height"])});
  }

  void way(const osmium::Way& w) {
    const std::string element = "way " + std::to_string(w.id());
    if (w.tags().has_tag("golf", "hole")) {
      MapHole h;
      h.element = element;
      if (const char* ref = w.tags()["ref"]) h.ref = ref;
      h.par = whole(w.tags()["par"]);
      h.handicap = whole(w.tags()["handicap"]);
      h.dist = distance(w.tags()["dist"]);
      h.line = ring_of(w.nodes());
      if (h.line.size() < 2) throw InputError(element + " (golf=hole): fewer than two located nodes: a hole runs from its tee to its green");
      map_.holes.push_back(std::move(h));
      return;
    }
    if (w.tags().has_tag("golf", "cart_path") || w.tags().has_tag("golf", "path")) {
      std::vector<GeoPoint> line = ring_of(w.nodes());
      if (line.size() >= 2) {
        map_.paths.push_back({element, std::move(line), metres_tag(w.tags()["width"], 1.0, 10.0).value_or(kCartPathWidth)});
      }
      return;
    }
    if (w.tags().has_tag("natural", "tree_row")) {
      std::vector<GeoPoint> line = ring_of(w.nodes());
      if (line.size() >= 2) map_.trees.push_back({element, std::move(line), height(w.tags()["height"])});
      return;
    }
    const std::optional<MapSurface> s = surface_of(w.tags());
    if (!s) return;
    if (*s == MapSurface::Course && map_.name.empty())
      if (const char* name = w.tags()["name"]) map_.name = name;
    // A way tagged as an area: closed ways (its two ends one node) are assembled with the
    // relations; one whose ends only nearly meet is closed here.
    if (w.nodes().size() < 3 || w.ends_have_same_id()) return;
    std::vector<GeoPoint> ring = ring_of(w.nodes());
    if (ring.size() < 3) return;
    const double gap = metres_between(ring.front(), ring.back());
    if (gap > kRingGap) {
      char msg[160];
      std::snprintf(msg, sizeof msg, " (%s=%s): its ring is not closed, its ends %.1f m apart (closed when within %.0f m)",
                    w.tags()["golf"] ? "golf" : "area", w.tags()["golf"] ? w.tags()["golf"] : to_string(*s), gap, kRingGap);
      throw InputError(element + msg);
    }
    ring.push_back(ring.front());
    char msg[120];
    std::snprintf(msg, sizeof msg, "%s (%s): ring closed across its %.2f m gap", element.c_str(), to_string(*s), gap);
    map_.repairs.push_back(msg);
    map_.areas.push_back({*s, element, {{std::move(ring), {}}}, tee_sets_of(w.tags())});
  }

  void area(const osmium::Area& a) {
    const bool wood = a.tags().has_tag("natural", "wood") || a.tags().has_tag("landuse", "forest");
    const std::optional<MapSurface> s = wood ? std::optional<MapSurface>(MapSurface::Rough) : surface_of(a.tags());
    if (!s) return;
    if (*s == MapSurface::Course && map_.name.empty())
      if (const char* name = a.tags()["name"]) map_.name = name;
    MapArea out;
    out.surface = *s;
    out.element = std::string(a.from_way() ? "way " : "relation ") + std::to_string(a.orig_id());
    out.tee_sets = tee_sets_of(a.tags());
    for (const osmium::OuterRing& outer : a.outer_rings()) {
      MapPolygon p;
      p.outer = ring_of(outer);
      for (const osmium::InnerRing& inner : a.inner_rings(outer)) p.inners.push_back(ring_of(inner));
      if (p.outer.size() >= 4) out.polygons.push_back(std::move(p));
    }
    if (!out.polygons.empty()) (wood ? map_.woods : map_.areas).push_back(std::move(out));
  }

 private:
  GolfMap& map_;
};

// Rings osmium could not assemble: the area is left out, and the report names it.
class Problems : public osmium::area::ProblemReporter {
 public:
  explicit Problems(std::vector<std::string>& out) : out_(out) {}
  void report_ring_not_closed(const osmium::NodeRef& nr, const osmium::Way*) override {
    note("a ring is not closed at node " + std::to_string(nr.ref()));
  }
  void report_intersection(osmium::object_id_type way1, osmium::Location, osmium::Location, osmium::object_id_type way2,
                           osmium::Location, osmium::Location, osmium::Location) override {
    note("ways " + std::to_string(way1) + " and " + std::to_string(way2) + " cross");
  }
  void report_invalid_location(osmium::object_id_type way_id, osmium::object_id_type node_id) override {
    note("way " + std::to_string(way_id) + " refers to node " + std::to_string(node_id) + ", which the file lacks");
  }

 private:
  void note(const std::string& what) {
    const char* kind = m_object_type == osmium::item_type::relation ? "relation " : "way ";
    out_.push_back(kind + std::to_string(object_id()) + ": " + what + "; left out");
  }
  std::vector<std::string>& out_;
};

}  // namespace

const char* to_string(MapSurface s) {
  switch (s) {
    case MapSurface::Green: return "green";
    case MapSurface::Tee: return "tee";
    case MapSurface::Bunker: return "bunker";
    case MapSurface::Water: return "water_hazard";
    case MapSurface::LateralWater: return "lateral_water_hazard";
    case MapSurface::CartPath: return "cart_path";
    case MapSurface::Fairway: return "fairway";
    case MapSurface::Rough: return "rough";
    case MapSurface::Course: return "golf_course";
  }
  return "?";
}

namespace {

// Overpass API JSON ({"elements": [{"type": "node", "id", "lat", "lon", "tags"}, {"type":
// "way", "nodes"}, {"type": "relation", "members": [{"type", "ref", "role"}]}]}) as OSM XML,
// so the one reader assembles it.
std::string overpass_to_xml(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ": not Overpass JSON (" + e.what() + ")");
  }
  if (!doc.is_object() || !doc.contains("elements") || !doc["elements"].is_array())
    throw InputError(path.string() + ": not Overpass JSON (no \"elements\" array: export with [out:json] and out geom or out body)");
  std::ostringstream x;
  x.precision(10);
  x << "<?xml version='1.0'?>\n<osm version='0.6'>\n";
  const auto tags = [&](const nlohmann::json& e) {
    if (!e.contains("tags") || !e["tags"].is_object()) return;
    for (const auto& [k, v] : e["tags"].items())
      if (v.is_string()) x << "<tag k='" << xml_escape(k) << "' v='" << xml_escape(v.get<std::string>()) << "'/>";
  };
  const auto id_of = [&](const nlohmann::json& e, const char* what) {
    if (!e.contains("id") || !e["id"].is_number_integer())
      throw InputError(path.string() + ": an element without a whole-number id (" + what + ")");
    return e["id"].get<long long>();
  };
  // XML wants nodes, then ways, then relations.
  for (const char* kind : {"node", "way", "relation"})
    for (const nlohmann::json& e : doc["elements"]) {
      if (!e.is_object() || e.value("type", "") != kind) continue;
      const long long id = id_of(e, kind);
      if (std::string_view(kind) == "node") {
        if (!e.contains("lat") || !e.contains("lon") || !e["lat"].is_number() || !e["lon"].is_number())
          throw InputError(path.string() + ": node " + std::to_string(id) + " has no lat and lon");
        x << "<node id='" << id << "' lat='" << e["lat"].get<double>() << "' lon='" << e["lon"].get<double>() << "'>";
        tags(e);
        x << "</node>\n";
      } else if (std::string_view(kind) == "way") {
        x << "<way id='" << id << "'>";
        if (e.contains("nodes") && e["nodes"].is_array())
          for (const auto& n : e["nodes"])
            if (n.is_number_integer()) x << "<nd ref='" << n.get<long long>() << "'/>";
        tags(e);
        x << "</way>\n";
      } else {
        x << "<relation id='" << id << "'>";
        if (e.contains("members") && e["members"].is_array())
          for (const auto& m : e["members"])
            if (m.is_object() && m.contains("ref") && m["ref"].is_number_integer())
              x << "<member type='" << xml_escape(m.value("type", "way")) << "' ref='" << m["ref"].get<long long>()
                << "' role='" << xml_escape(m.value("role", "")) << "'/>";
        tags(e);
        x << "</relation>\n";
      }
    }
  x << "</osm>\n";
  return x.str();
}

// OSM XML's coordinates, checked before libosmium reads them: its reader scales a value's
// digits by its exponent in a 64-bit integer, so `lat="1e308"` wraps (to ~0) instead of being
// refused. Each lat and lon attribute must be a plain number on the globe.
void check_xml_coordinates(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char first = 0;
  while (in.get(first) && std::isspace(static_cast<unsigned char>(first))) {
  }
  if (first != '<') return;  // PBF or compressed: its coordinates are whole numbers of 1e-7 degree
  in.seekg(0);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    for (const char* name : {"lat", "lon"}) {
      const std::string key = std::string(name) + "=";
      for (std::size_t at = line.find(key); at != std::string::npos; at = line.find(key, at + 1)) {
        if (at > 0 && !std::isspace(static_cast<unsigned char>(line[at - 1]))) continue;  // part of a longer name
        const std::size_t open = at + key.size();
        if (open >= line.size() || (line[open] != '"' && line[open] != '\'')) continue;
        const std::size_t close = line.find(line[open], open + 1);
        if (close == std::string::npos) continue;  // the XML parser names an unclosed attribute
        const std::string value = line.substr(open + 1, close - open - 1);
        const double limit = key[1] == 'a' ? 90.0 : 180.0;
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        const bool plain = !value.empty() && end == value.c_str() + value.size() && value.size() <= 32;
        if (!plain || !std::isfinite(v) || std::abs(v) > limit) {
          // The element by its id when it is on the same line, as OSM's writers put it.
          std::string element;
          if (const std::size_t id = line.find(" id="); id != std::string::npos && id + 5 < line.size()) {
            const std::size_t end = line.find(line[id + 4], id + 5);
            if (end != std::string::npos) element = "node " + line.substr(id + 5, std::min<std::size_t>(end - id - 5, 20)) + ": ";
          }
          throw InputError(path.string() + ":" + std::to_string(number) + ": " + element + name + "=\"" + value.substr(0, 32) +
                           "\" is off the globe (allowed: " + (limit == 90.0 ? "latitude -90..90" : "longitude -180..180") + " degrees)");
        }
      }
    }
  }
}

// An Overpass export: .json, or a file that opens with '{'.
bool is_overpass_json(const std::filesystem::path& path) {
  if (path.extension() == ".json") return true;
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c) && std::isspace(static_cast<unsigned char>(c))) {
  }
  return c == '{';
}
}  // namespace

GolfMap read_golf_map(const std::filesystem::path& path) {
  GolfMap map;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path.string() + ": a directory, not a map (give an .osm or .osm.pbf file)");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string() + (std::filesystem::exists(path, ec) ? ": not a regular file (give an .osm or .osm.pbf file)"
                                                                        : ": no such file"));
  const std::string overpass = is_overpass_json(path) ? overpass_to_xml(path) : std::string();
  if (overpass.empty()) check_xml_coordinates(path);
  try {
    const osmium::io::File file = overpass.empty() ? osmium::io::File(path.string())
                                                   : osmium::io::File(overpass.data(), overpass.size(), "osm");
    Problems problems(map.repairs);
    osmium::area::Assembler::config_type config;
    config.problem_reporter = &problems;
    osmium::TagsFilter filter(false);
    filter.add_rule(true, osmium::TagMatcher("golf"));
    filter.add_rule(true, osmium::TagMatcher("leisure", "golf_course"));
    filter.add_rule(true, osmium::TagMatcher("natural", "water"));
    filter.add_rule(true, osmium::TagMatcher("natural", "sand"));
    filter.add_rule(true, osmium::TagMatcher("natural", "wood"));
    filter.add_rule(true, osmium::TagMatcher("landuse", "forest"));
    osmium::area::MultipolygonManager<osmium::area::Assembler> manager(config, filter);
    osmium::relations::read_relations(file, manager);
    Index index, negative_index;
    LocationHandler locations(index, negative_index);
    locations.ignore_errors();
    Collector collector(map);
    osmium::io::Reader reader(file, osmium::io::read_meta::no);
    osmium::apply(reader, locations, collector, manager.handler([&collector](osmium::memory::Buffer&& buffer) {
                    osmium::apply(buffer, collector);
                  }));
    reader.close();
  } catch (const InputError& e) {
    throw InputError(path.string() + ": " + e.what());
  } catch (const std::exception& e) {
    throw InputError(path.string() + ": not OpenStreetMap XML or PBF data (" + e.what() + ")");
  }
  return map;
}

}  // namespace sweetspot
