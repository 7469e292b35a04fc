#include "game/courses/course_import.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <set>
#include <unistd.h>

#include "game/content/course_file.hpp"
#include "game/courses/course_writer.hpp"
#include "game/courses/elevation.hpp"
#include "game/courses/golf_map.hpp"
#include "game/courses/terrain_heights.hpp"
#include "game/courses/surface_plan.hpp"
#include "game/courses/tree_planting.hpp"
#include "game/util/atomic_file.hpp"
#include "game/util/terminal_text.hpp"
#include "physics/error.hpp"
#include "physics/range.hpp"

namespace sweetspot {
namespace {

constexpr double kGreenSearch = 40.0;  // m: a hole's last node this near a green ends on it
constexpr double kPinInset = 3.0;      // m: a cup this far inside the green's edge at least (ESTIMATE of a fair hole location)

double line_length(const std::vector<LocalPoint>& pts) {
  double s = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) s += std::hypot(pts[i].x - pts[i - 1].x, pts[i].z - pts[i - 1].z);
  return s;
}

// The line's nodes between its ends, the gentlest turns dropped until CourseHole::kMaxBends
// remain (a hole drawn with many nodes along a curve keeps the corners that shape it).
std::vector<LocalPoint> main_bends(const std::vector<LocalPoint>& line) {
  // A line of thousands of nodes (a hand-drawn curve) is first thinned to every k-th node,
  // its ends kept: the gentlest-turn search below is quadratic in the nodes.
  constexpr std::size_t kMaxNodes = 256;
  std::vector<LocalPoint> pts;
  const std::size_t step = line.size() > kMaxNodes ? (line.size() + kMaxNodes - 1) / kMaxNodes : 1;
  for (std::size_t i = 0; i + 1 < line.size(); i += step) pts.push_back(line[i]);
  pts.push_back(line.back());
  const auto turn = [&](std::size_t i) {
    const double a = std::atan2(pts[i].z - pts[i - 1].z, pts[i].x - pts[i - 1].x);
    const double b = std::atan2(pts[i + 1].z - pts[i].z, pts[i + 1].x - pts[i].x);
    return std::abs(std::remainder(b - a, 2.0 * M_PI));
  };
  while (pts.size() > CourseHole::kMaxBends + 2) {
    std::size_t gentlest = 1;
    for (std::size_t i = 2; i + 1 < pts.size(); ++i)
      if (turn(i) < turn(gentlest)) gentlest = i;
    pts.erase(pts.begin() + static_cast<std::ptrdiff_t>(gentlest));
  }
  return std::vector<LocalPoint>(pts.begin() + 1, pts.end() - 1);
}

}  // namespace

int par_for_length(double m) {
  const double yd = m / 0.9144;
  return yd <= 250.0 ? 3 : yd <= 470.0 ? 4 : 5;
}

// The steepest a tee, fairway or green may stand once the raster has shaped it. The steepest
// playing surfaces on hilly courses run ~20-30° (fairway banks); 60° is a cliff, and a raster
// that puts one under a fairway holds a spike or the tops of trees and buildings (a surface
// model, not bare earth), where a ball would never come to rest.
constexpr double kSteepestInPlay = 60.0;  // degrees

void refuse_cliffs_in_play(const SurfaceMesh& mesh, const std::filesystem::path& dem) {
  // Along the triangles' edges a metre or longer: a sliver where a mapped edge meets the grid
  // can tilt steeply over a few centimetres without any slope a ball would meet.
  constexpr double kShortestEdge = 1.0;  // m
  const double steepest = std::tan(kSteepestInPlay * kPi / 180.0);
  for (const SurfaceMesh::Group& g : mesh.groups) {
    if (g.material != "tee" && g.material != "fairway" && g.material != "green") continue;
    for (const auto& t : g.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3& a = mesh.vertices[t[k]];
        const Vec3& b = mesh.vertices[t[(k + 1) % 3]];
        const double run = std::hypot(b.x() - a.x(), b.z() - a.z());
        if (run < kShortestEdge || std::abs(b.y() - a.y()) <= steepest * run) continue;
        char msg[320];
        std::snprintf(msg, sizeof msg, "%s: the %s at %.0f m east, %.0f m south of the course's centre rises %.0f m over %.1f m "
                      "(at most %.0f deg on tees, fairways and greens): a spike, or a surface model with trees and buildings "
                      "(give bare-earth heights)", dem.string().c_str(), g.material.c_str(), a.x(), a.z(),
                      std::abs(b.y() - a.y()), run, kSteepestInPlay);
        throw InputError(msg);
      }
  }
}

// Characters a course's name may have: a card's title line.
constexpr std::size_t kLongestCourseName = 80;

ImportResult import_course(const Assets& assets, const ImportOptions& o) {
  std::error_code ec;
  // A link counts, dangling or not: the new directory is never written through one.
  if (const std::filesystem::file_status out = std::filesystem::symlink_status(o.out, ec); std::filesystem::exists(out))
    throw InputError(o.out.string() + (std::filesystem::is_symlink(out) ? ": already exists (a link)" : ": already exists") +
                     " (course import writes a new directory; remove it or give another -o)");
  const std::filesystem::path parent = o.out.has_parent_path() ? o.out.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, ec)) throw InputError(o.out.string() + ": its folder " + parent.string() + " does not exist");
  if (!(o.cell >= 0.5 && o.cell <= 50.0)) {
    static constexpr Range kCell{0.5, 50.0};
    throw InputError(range_refusal("--cell", o.cell, kCell, "m"));
  }
  note_input_file(o.map);
  std::unique_ptr<ElevationModel> dem;
  if (!o.dem.empty()) {
    note_input_file(o.dem);
    dem = std::make_unique<ElevationModel>(o.dem);
  }
  const GolfMap map = read_golf_map(o.map);
  const std::string where = o.map.string() + ": ";
  if (map.holes.empty())
    throw InputError(where + "no golf=hole ways: nothing to play (a course's holes are mapped as golf=hole lines from tee to green)");
  ImportResult r;
  r.report = map.repairs;
  if (!o.name.empty())
    if (const std::string why = name_problem(o.name, kLongestCourseName); !why.empty())
      throw InputError("--name: " + why + " (a course's name of 1 to " + std::to_string(kLongestCourseName) + " characters)");
  // A mapped name keeps its words: line breaks and other controls dropped, what a terminal
  // could still act on shown escaped, cut to a title's length.
  std::string mapped;
  for (const char c : map.name)
    if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) mapped += c;
  const auto title = [](std::string t) {  // at most kLongestCourseName bytes, cut between characters
    if (t.size() <= kLongestCourseName) return t;
    std::size_t cut = kLongestCourseName;
    while (cut > 0 && (static_cast<unsigned char>(t[cut]) & 0xC0) == 0x80) --cut;
    return t.substr(0, cut);
  };
  mapped = title(terminal_safe(mapped));
  r.name = !o.name.empty() ? o.name : !mapped.empty() ? mapped : title(terminal_safe(o.map.stem().stem().string()));
  const LocalFrame frame = LocalFrame::around(map);
  SurfacePlan plan(map, frame, r.report);
  // The holes in the order of their refs, numbered 1..n.
  std::vector<std::pair<int, const MapHole*>> order;
  for (const MapHole& h : map.holes) {
    char* end = nullptr;
    const long ref = std::strtol(h.ref.c_str(), &end, 10);
    if (h.ref.empty() || *end != '\0' || ref < 1 || ref > 36)
      throw InputError(where + h.element + " (golf=hole): ref=" + (h.ref.empty() ? "(none)" : h.ref) +
                       ": give each hole its number, 1-18, as ref");
    order.emplace_back(static_cast<int>(ref), &h);
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (order.size() > 18) throw InputError(where + std::to_string(order.size()) + " golf=hole ways: a round plays at most 18");
  for (std::size_t i = 1; i < order.size(); ++i)
    if (order[i].first != order[i - 1].first + 1)
      throw InputError(where + order[i].second->element + " (golf=hole ref=" + order[i].second->ref + "): holes " +
                       std::to_string(order[i - 1].first) + " and " + std::to_string(order[i].first) +
                       (order[i].first == order[i - 1].first ? " share a number" : ": the holes between are missing"));
  if (order.front().first != 1)
    r.report.push_back("holes numbered from " + std::to_string(order.front().first) + " in the map are played as 1.." +
                       std::to_string(order.size()));
  std::set<int> indexes;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const MapHole& m = *order[i].second;
    ImportedHole h;
    h.number = static_cast<int>(i) + 1;
    h.element = m.element;
    std::vector<LocalPoint> line;
    for (const GeoPoint& g : m.line) line.push_back(frame.to_local(g));
    h.tee = line.front();
    const std::string tee_on = plan.material_at(h.tee.x, h.tee.z);
    if (tee_on != "tee" && tee_on != "fairway" && tee_on != "rough")
      throw InputError(where + m.element + " (hole " + m.ref + "): its first node, the tee, lies on " +
                       (tee_on.empty() ? "no ground" : tee_on) + " (a tee needs dry ground: tee, fairway or rough)");
    // The cup: a mapped pin on the green the hole ends at, else a fair spot on that green.
    const LocalPoint end = line.back();
    std::optional<LocalPoint> pin;
    for (const MapPin& p : map.pins) {
      const LocalPoint q = frame.to_local(p.at);
      if (std::hypot(q.x - end.x, q.z - end.z) <= kGreenSearch && plan.material_at(q.x, q.z) == "green") pin = q;
    }
    if (!pin) pin = plan.green_spot(end.x, end.z, kGreenSearch, kPinInset);
    if (!pin) {
      char msg[96];
      std::snprintf(msg, sizeof msg, "): no golf=green within %.0f m of its last node (a hole ends on its green)", kGreenSearch);
      throw InputError(where + m.element + " (hole " + m.ref + msg);
    }
    if (dem) {
      // On a sloping green the cup goes where the putting surface is nearly level: the spot
      // nearest the mapped one, 1 m apart, with a slope of kMaxPinSlope at most.
      double slope = green_slope(*dem, frame, *pin);
      if (slope > kMaxPinSlope) {
        std::optional<LocalPoint> level;
        double flattest = slope;
        LocalPoint flat = *pin;
        for (const LocalPoint& q : plan.green_grid(pin->x, pin->z, 1.0, kPinInset, 1.0)) {
          const double sq = green_slope(*dem, frame, q);
          if (sq <= kMaxPinSlope) {
            level = q;
            slope = sq;
            break;
          }
          if (sq < flattest) {
            flattest = sq;
            flat = q;
          }
        }
        if (!level) {
          char msg[200];
          std::snprintf(msg, sizeof msg, "%s (hole %s): no spot on its green slopes %.0f %% or less; the cup is at its flattest, %.1f %%",
                        m.element.c_str(), m.ref.c_str(), 100.0 * kMaxPinSlope, 100.0 * flattest);
          r.report.push_back(msg);
          level = flat;
          slope = flattest;
        }
        pin = level;
      }
      h.pin_slope = slope;
    }
    h.pin = *pin;
    // More cup positions for other days: spread over the green, each where it is level
    // enough, the farthest from those chosen first.
    {
      std::vector<LocalPoint> grid;
      for (const LocalPoint& q : plan.green_grid(pin->x, pin->z, 1.0, kPinInset, 2.0))
        if (!dem || green_slope(*dem, frame, q) <= kMaxPinSlope) grid.push_back(q);
      std::vector<LocalPoint> chosen{*pin};
      while (static_cast<int>(chosen.size()) < kPinSets) {
        double best = kPinSpread;
        const LocalPoint* far = nullptr;
        for (const LocalPoint& q : grid) {
          double near = HUGE_VAL;
          for (const LocalPoint& c : chosen) near = std::min(near, std::hypot(q.x - c.x, q.z - c.z));
          if (near >= best) {
            best = near;
            far = &q;
          }
        }
        if (far == nullptr) break;
        chosen.push_back(*far);
      }
      h.more_pins.assign(chosen.begin() + 1, chosen.end());
    }
    line.back() = h.pin;
    h.bends = main_bends(line);
    h.length = line_length(line);
    if (m.par) {
      h.par = *m.par;
      if (h.par < 3 || h.par > 6) throw InputError(where + m.element + " (hole " + m.ref + "): par=" + std::to_string(h.par) + " (allowed 3-6)");
    } else {
      h.par = par_for_length(h.length);
      char msg[200];
      std::snprintf(msg, sizeof msg, "%s (hole %s): no par mapped; par %d from its %.0f m (%.0f yd; USGA guideline: par 3 to 250 yd, par 4 to 470)",
                    m.element.c_str(), m.ref.c_str(), h.par, h.length, h.length / 0.9144);
      r.report.push_back(msg);
    }
    if (m.handicap && *m.handicap >= 1 && *m.handicap <= static_cast<int>(order.size())) {
      h.index = *m.handicap;
      indexes.insert(h.index);
    }
    r.holes.push_back(h);
  }
  // Named tee boxes (tee=*, name=*) to the hole whose tee is nearest.
  for (const MapArea& a : map.areas) {
    if (a.surface != MapSurface::Tee || a.tee_sets.empty() || a.polygons.empty()) continue;
    double sx = 0.0, sz = 0.0;
    const std::vector<GeoPoint>& ring = a.polygons.front().outer;
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
      const LocalPoint q = frame.to_local(ring[i]);
      sx += q.x;
      sz += q.z;
    }
    const double n = static_cast<double>(std::max<std::size_t>(ring.size() - 1, 1));
    const LocalPoint at{sx / n, sz / n};
    if (plan.material_at(at.x, at.z) != "tee") {
      r.report.push_back(a.element + " (golf=tee " + a.tee_sets.front() + "): its middle is not on the tee; left out of the tee sets");
      continue;
    }
    ImportedHole* nearest = nullptr;
    double best = kTeeSearch;
    for (ImportedHole& h : r.holes) {
      const double d = std::hypot(h.tee.x - at.x, h.tee.z - at.z);
      if (d < best) {
        best = d;
        nearest = &h;
      }
    }
    if (nearest == nullptr) continue;
    for (const std::string& name : a.tee_sets) {
      bool dup = false;
      for (const auto& [have, p] : nearest->tee_sets) dup = dup || have == name;
      if (dup) continue;
      if (nearest->tee_sets.size() >= CourseHole::kMaxTeeSets) {
        r.report.push_back(a.element + " (golf=tee " + name + "): hole " + std::to_string(nearest->number) + " has " +
                           std::to_string(CourseHole::kMaxTeeSets) + " tee sets already; left out");
        continue;
      }
      nearest->tee_sets.emplace_back(name, at);
    }
  }
  if (indexes.size() != r.holes.size()) {
    if (!indexes.empty()) r.report.push_back("handicap=* is not given once for each of 1.." + std::to_string(r.holes.size()) +
                                             ": stroke indexes by length instead");
    for (ImportedHole& h : r.holes) h.index = 0;
  }
  SurfaceMesh mesh = plan.triangulate(o.cell, dem ? std::min(o.green_cell, o.cell) : o.cell);
  r.triangles = mesh.triangle_count();
  for (const SurfaceMesh::Group& g : mesh.groups) r.areas[g.material] = plan.area(g.material);
  double tee_height = 0.0;
  if (dem) {
    shape_heights(mesh, plan, *dem, frame);
    refuse_cliffs_in_play(mesh, o.dem);
    // Heights from hole 1's tee, which stands at y = 0 as every world's origin does.
    tee_height = dem->heights(frame, {r.holes.front().tee}).front();
    for (Vec3& v : mesh.vertices) v.y() -= tee_height;
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (const Vec3& v : mesh.vertices) {
      low = std::min(low, v.y());
      high = std::max(high, v.y());
    }
    char msg[160];
    std::snprintf(msg, sizeof msg, "ground from %s: %.1f m to %.1f m about hole 1's tee (%.1f m above the raster's datum)",
                  o.dem.filename().string().c_str(), low, high, tee_height);
    r.report.push_back(msg);
  } else {
    r.report.push_back("no elevation given: the ground is flat");
  }
  // Trees after the ground is shaped: they stand on it, their own shapes untouched.
  const TreePlanting planting = plant_trees(map, frame, plan);
  if (!planting.trees.empty() || planting.left_out > 0) {
    if (!planting.trees.empty()) {
      std::vector<LocalPoint> at;
      for (const PlantedTree& t : planting.trees) at.push_back(t.at);
      std::vector<double> base = dem ? dem->heights(frame, at) : std::vector<double>(at.size(), 0.0);
      if (dem)
        for (double& y : base) y -= tee_height;
      add_tree_meshes(mesh, planting.trees, base);
    }
    r.trees = planting.trees.size();
    char msg[240];
    std::snprintf(msg, sizeof msg, "trees planted: %zu (%zu mapped, %zu along tree rows, %zu in woods); %zu left out (not on rough)",
                  planting.trees.size(), planting.mapped, planting.in_rows, planting.in_woods, planting.left_out);
    r.report.push_back(msg);
    if (planting.over_limit > 0) {
      std::snprintf(msg, sizeof msg, "%zu more trees past the limit of %zu were not planted", planting.over_limit, kMaxTrees);
      r.report.push_back(msg);
    }
    if (planting.wood_spacing > kTreeSpacing) {
      std::snprintf(msg, sizeof msg, "woods planted %.0f m apart instead of %.0f m (at most %zu trees on a course)",
                    planting.wood_spacing, kTreeSpacing, kMaxTrees);
      r.report.push_back(msg);
    }
  }
  r.triangles = mesh.triangle_count();
  // Written beside the target and renamed into place once it loads as a course.
  std::string tmpl = (parent / (".course-import-XXXXXX")).string();
  if (mkdtemp(tmpl.data()) == nullptr) throw InputError(parent.string() + ": cannot create a working directory there");
  const std::filesystem::path tmp(tmpl);
  try {
    write_world(tmp, r.name, mesh, plan.min(), plan.max(), r.holes.front().tee);
    write_course(tmp, r);
    (void)load_course(assets, (tmp / "course.toml").string());
    std::filesystem::permissions(tmp, std::filesystem::perms::owner_all | std::filesystem::perms::group_read |
                                          std::filesystem::perms::group_exec | std::filesystem::perms::others_read |
                                          std::filesystem::perms::others_exec);  // as mkdir would make it (mkdtemp: owner only)
    std::filesystem::rename(tmp, o.out);
  } catch (const InputError& e) {
    // What was written does not load back: said of the course being made, never of the
    // working directory that is removed now.
    std::filesystem::remove_all(tmp, ec);
    std::string why = e.what();
    const std::string from = tmp.string() + "/";
    for (std::size_t at = why.find(from); at != std::string::npos; at = why.find(from, at))
      why.replace(at, from.size(), o.out.string() + "/");
    throw InputError(why + " (nothing written)");
  } catch (...) {
    std::filesystem::remove_all(tmp, ec);
    throw;
  }
  return r;
}

}  // namespace sweetspot
