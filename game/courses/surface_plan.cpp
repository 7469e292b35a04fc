#include "game/courses/surface_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>
#include <utility>

#include <geos_c.h>

#include "physics/error.hpp"

namespace sweetspot {
namespace {

// m: the out-of-bounds ring and the course taken around the features when the map has no
// leisure=golf_course boundary.
constexpr double kAssumedCourse = 40.0;
// m: the widest course we lay out (the largest 18- and 36-hole properties are ~3 km across).
constexpr double kMaxSpan = 6000.0;
// Cells in a mesh at most: ~2 triangles each, a few hundred bytes a triangle through the
// overlay, the written OBJ and the collision world (2 million: ~1 GB; a square kilometre at
// the default 4 m grid is ~70 000).
constexpr double kMaxCells = 2.0e6;

// GEOS reports its notices and errors through a handler; every call's result is checked
// where it is used, so they are not printed.
void geos_message(const char*, ...) {}

}  // namespace

const char* material_of(MapSurface s) {
  switch (s) {
    case MapSurface::Green: return "green";
    case MapSurface::Tee: return "tee";
    case MapSurface::Bunker: return "sand";
    case MapSurface::Water:
    case MapSurface::LateralWater: return "water";
    case MapSurface::CartPath: return "cart_path";
    case MapSurface::Fairway: return "fairway";
    case MapSurface::Rough:
    case MapSurface::Course: return "rough";
  }
  return "rough";
}

std::size_t SurfaceMesh::triangle_count() const {
  std::size_t n = 0;
  for (const Group& g : groups) n += g.triangles.size();
  return n;
}

struct SurfacePlan::Impl {
  GEOSContextHandle_t ctx = nullptr;
  struct Region {
    std::string material;
    GEOSGeometry* geom = nullptr;
    const GEOSPreparedGeometry* prepared = nullptr;
  };
  std::vector<Region> regions;  // a partition of the domain, highest surface first
  std::vector<GEOSGeometry*> greens;  // each mapped green as laid (after overlaps)
  double x0 = 0, z0 = 0, x1 = 0, z1 = 0;

  Impl() {
    ctx = GEOS_init_r();
    GEOSContext_setNoticeHandler_r(ctx, geos_message);
    GEOSContext_setErrorHandler_r(ctx, geos_message);
  }
  ~Impl() {
    for (Region& r : regions) {
      if (r.prepared) GEOSPreparedGeom_destroy_r(ctx, r.prepared);
      if (r.geom) GEOSGeom_destroy_r(ctx, r.geom);
    }
    for (GEOSGeometry* g : greens) GEOSGeom_destroy_r(ctx, g);
    GEOS_finish_r(ctx);
  }
  GEOSGeometry* checked(GEOSGeometry* g, const char* what) const {
    if (g == nullptr) throw InputError(std::string("course import: the surfaces' geometry failed (") + what + ")");
    return g;
  }
  GEOSGeometry* ring(const std::vector<GeoPoint>& pts, const LocalFrame& f) const {
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, static_cast<unsigned>(pts.size()), 2);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const LocalPoint p = f.to_local(pts[i]);
      GEOSCoordSeq_setXY_r(ctx, seq, static_cast<unsigned>(i), p.x, p.z);
    }
    return checked(GEOSGeom_createLinearRing_r(ctx, seq), "a ring");
  }
  GEOSGeometry* polygon(const MapPolygon& p, const LocalFrame& f) const {
    GEOSGeometry* shell = ring(p.outer, f);
    std::vector<GEOSGeometry*> holes;
    for (const auto& in : p.inners)
      if (in.size() >= 4) holes.push_back(ring(in, f));
    return checked(GEOSGeom_createPolygon_r(ctx, shell, holes.data(), static_cast<unsigned>(holes.size())), "a polygon");
  }
  // The laid green nearest `p` within `within` m (nullptr: none), and how far.
  const GEOSGeometry* nearest_green(const GEOSGeometry* p, double within, double* distance) const {
    const GEOSGeometry* best = nullptr;
    double best_d = within;
    for (const GEOSGeometry* g : greens) {
      double d = 0.0;
      if (GEOSDistance_r(ctx, g, p, &d) == 1 && d <= best_d) {
        best_d = d;
        best = g;
      }
    }
    if (distance) *distance = best_d;
    return best;
  }
  GEOSGeometry* union_of(std::vector<GEOSGeometry*> parts) const {
    if (parts.empty()) return GEOSGeom_createEmptyPolygon_r(ctx);
    GEOSGeometry* all = checked(GEOSGeom_createCollection_r(ctx, GEOS_GEOMETRYCOLLECTION, parts.data(),
                                                            static_cast<unsigned>(parts.size())), "a collection");
    GEOSGeometry* u = checked(GEOSUnaryUnion_r(ctx, all), "a union");
    GEOSGeom_destroy_r(ctx, all);
    return u;
  }
};

SurfacePlan::SurfacePlan(const GolfMap& map, const LocalFrame& frame, std::vector<std::string>& report, double margin)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  GEOSContextHandle_t ctx = m.ctx;
  // A course is a few kilometres across at most: a map that spans more holds something far
  // off (a stray node, another course), and meshing it would take hours. Checked on the
  // map's points before any geometry is made.
  double px0 = HUGE_VAL, pz0 = HUGE_VAL, px1 = -HUGE_VAL, pz1 = -HUGE_VAL;
  const auto take = [&](const GeoPoint& g) {
    const LocalPoint q = frame.to_local(g);
    px0 = std::min(px0, q.x);
    px1 = std::max(px1, q.x);
    pz0 = std::min(pz0, q.z);
    pz1 = std::max(pz1, q.z);
  };
  for_each_point(map, take);
  if (px1 >= px0 && !(px1 - px0 <= kMaxSpan && pz1 - pz0 <= kMaxSpan)) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "the course spans %.1f km by %.1f km (at most %.0f km: does the map hold a far-off feature or another course?)",
                  (px1 - px0) / 1000.0, (pz1 - pz0) / 1000.0, kMaxSpan / 1000.0);
    throw InputError(msg);
  }
  // Each surface's areas, mended where a ring crosses itself.
  constexpr int kSurfaces = static_cast<int>(MapSurface::Course) + 1;
  std::vector<std::vector<GEOSGeometry*>> by(kSurfaces);
  std::vector<std::pair<GEOSGeometry*, std::string>> green_parts;
  for (const MapArea& a : map.areas) {
    for (const MapPolygon& p : a.polygons) {
      GEOSGeometry* g = m.polygon(p, frame);
      if (GEOSisValid_r(ctx, g) != 1) {
        GEOSGeometry* fixed = m.checked(GEOSMakeValid_r(ctx, g), "mending a ring");
        GEOSGeom_destroy_r(ctx, g);
        g = fixed;
        report.push_back(a.element + " (" + to_string(a.surface) + "): its outline crosses itself; mended into valid pieces");
      }
      if (a.surface == MapSurface::Green) green_parts.emplace_back(GEOSGeom_clone_r(ctx, g), a.element);
      by[static_cast<int>(a.surface)].push_back(g);
    }
  }
  // Cart paths: each line widened to its width, flat-ended (a path meets what it joins).
  for (const MapPath& p : map.paths) {
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, static_cast<unsigned>(p.line.size()), 2);
    for (std::size_t i = 0; i < p.line.size(); ++i) {
      const LocalPoint q = frame.to_local(p.line[i]);
      GEOSCoordSeq_setXY_r(ctx, seq, static_cast<unsigned>(i), q.x, q.z);
    }
    GEOSGeometry* line = m.checked(GEOSGeom_createLineString_r(ctx, seq), "a cart path");
    GEOSGeometry* strip = GEOSBufferWithStyle_r(ctx, line, 0.5 * p.width, 4, GEOSBUF_CAP_FLAT, GEOSBUF_JOIN_ROUND, 5.0);
    GEOSGeom_destroy_r(ctx, line);
    by[static_cast<int>(MapSurface::CartPath)].push_back(m.checked(strip, "a cart path's strip"));
  }
  GEOSGeometry* course = nullptr;
  if (by[static_cast<int>(MapSurface::Course)].empty()) {
    std::vector<GEOSGeometry*> all;
    for (int s = 0; s < kSurfaces; ++s)
      for (GEOSGeometry* g : by[s]) all.push_back(GEOSGeom_clone_r(ctx, g));
    if (all.empty()) throw InputError("the map has no golf areas (golf=green, tee, fairway, bunker, ...) to lay a course on");
    for (const MapHole& h : map.holes) {  // the holes' lines too: a tee mapped only as the line's first node
      GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, static_cast<unsigned>(h.line.size()), 2);
      for (std::size_t i = 0; i < h.line.size(); ++i) {
        const LocalPoint p = frame.to_local(h.line[i]);
        GEOSCoordSeq_setXY_r(ctx, seq, static_cast<unsigned>(i), p.x, p.z);
      }
      all.push_back(m.checked(GEOSGeom_createLineString_r(ctx, seq), "a hole's line"));
    }
    GEOSGeometry* u = m.union_of(all);
    course = m.checked(GEOSBuffer_r(ctx, u, kAssumedCourse, 8), "the assumed boundary");
    GEOSGeom_destroy_r(ctx, u);
    char msg[160];
    std::snprintf(msg, sizeof msg, "no leisure=golf_course boundary mapped: the course is taken as the ground within %.0f m of its mapped areas and holes",
                  kAssumedCourse);
    report.push_back(msg);
  } else {
    course = m.union_of(by[static_cast<int>(MapSurface::Course)]);
    by[static_cast<int>(MapSurface::Course)].clear();
  }
  double cx0 = 0, cz0 = 0, cx1 = 0, cz1 = 0;
  GEOSGeom_getXMin_r(ctx, course, &cx0);
  GEOSGeom_getYMin_r(ctx, course, &cz0);
  GEOSGeom_getXMax_r(ctx, course, &cx1);
  GEOSGeom_getYMax_r(ctx, course, &cz1);
  m.x0 = cx0 - margin;
  m.z0 = cz0 - margin;
  m.x1 = cx1 + margin;
  m.z1 = cz1 + margin;
  GEOSGeometry* domain = m.checked(GEOSGeom_createRectangle_r(ctx, m.x0, m.z0, m.x1, m.z1), "the domain");
  // Highest surface first: each takes what is left of the course.
  GEOSGeometry* left = m.checked(GEOSIntersection_r(ctx, course, domain), "the course");
  const auto add = [&](const std::string& material, GEOSGeometry* g) {
    double area = 0.0;
    if (GEOSisEmpty_r(ctx, g) == 1 || GEOSArea_r(ctx, g, &area) != 1 || area <= 0.0) {
      GEOSGeom_destroy_r(ctx, g);
      return;
    }
    for (Impl::Region& r : m.regions)
      if (r.material == material) {  // two mapped surfaces play as one material (water, rough)
        GEOSGeometry* u = m.checked(GEOSUnion_r(ctx, r.geom, g), "a union");
        GEOSGeom_destroy_r(ctx, r.geom);
        GEOSGeom_destroy_r(ctx, g);
        r.geom = u;
        return;
      }
    m.regions.push_back({material, g, nullptr});
  };
  for (int s = 0; s < static_cast<int>(MapSurface::Course); ++s) {
    if (by[s].empty()) continue;
    GEOSGeometry* u = m.union_of(by[s]);
    GEOSGeometry* here = m.checked(GEOSIntersection_r(ctx, u, left), "a surface in the course");
    GEOSGeometry* rest = m.checked(GEOSDifference_r(ctx, left, u), "the rest of the course");
    GEOSGeom_destroy_r(ctx, u);
    GEOSGeom_destroy_r(ctx, left);
    left = rest;
    add(material_of(static_cast<MapSurface>(s)), here);
  }
  add("rough", left);
  add("out_of_bounds", m.checked(GEOSDifference_r(ctx, domain, course), "out of bounds"));
  GEOSGeom_destroy_r(ctx, domain);
  GEOSGeom_destroy_r(ctx, course);
  for (Impl::Region& r : m.regions) r.prepared = GEOSPrepare_r(ctx, r.geom);
  // The greens as they lie after the overlaps (a bunker cut into one takes its bite out).
  const Impl::Region* green = nullptr;
  for (const Impl::Region& r : m.regions)
    if (r.material == "green") green = &r;
  for (auto& [g, element] : green_parts) {
    if (green != nullptr) {
      GEOSGeometry* laid = GEOSIntersection_r(ctx, g, green->geom);
      if (laid != nullptr && GEOSisEmpty_r(ctx, laid) != 1) m.greens.push_back(laid);
      else if (laid != nullptr) GEOSGeom_destroy_r(ctx, laid);
    }
    GEOSGeom_destroy_r(ctx, g);
  }
}

SurfacePlan::~SurfacePlan() = default;

LocalPoint SurfacePlan::min() const { return {impl_->x0, impl_->z0}; }
LocalPoint SurfacePlan::max() const { return {impl_->x1, impl_->z1}; }

std::string SurfacePlan::material_at(double x, double z) const {
  GEOSGeometry* p = GEOSGeom_createPointFromXY_r(impl_->ctx, x, z);
  std::string out;
  for (const Impl::Region& r : impl_->regions)
    if (GEOSPreparedIntersects_r(impl_->ctx, r.prepared, p) == 1) {
      out = r.material;
      break;
    }
  GEOSGeom_destroy_r(impl_->ctx, p);
  return out;
}

double SurfacePlan::area(const std::string& material) const {
  for (const Impl::Region& r : impl_->regions)
    if (r.material == material) {
      double a = 0.0;
      GEOSArea_r(impl_->ctx, r.geom, &a);
      return a;
    }
  return 0.0;
}

std::optional<LocalPoint> SurfacePlan::green_spot(double x, double z, double within, double inset) const {
  GEOSContextHandle_t ctx = impl_->ctx;
  GEOSGeometry* p = GEOSGeom_createPointFromXY_r(ctx, x, z);
  double best_d = 0.0;
  const GEOSGeometry* best = impl_->nearest_green(p, within, &best_d);
  std::optional<LocalPoint> out;
  if (best != nullptr) {
    // Inside by `inset`: the point itself; otherwise the green's deepest point.
    GEOSGeometry* boundary = GEOSBoundary_r(ctx, best);
    double edge = 0.0;
    if (best_d == 0.0 && boundary != nullptr && GEOSDistance_r(ctx, boundary, p, &edge) == 1 && edge >= inset) {
      out = LocalPoint{x, z};
    } else if (GEOSGeometry* mic = GEOSMaximumInscribedCircle_r(ctx, best, 0.05)) {
      const GEOSGeometry* centre_line = mic;
      const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(ctx, centre_line);
      double cx = 0, cz = 0;
      if (seq != nullptr && GEOSCoordSeq_getXY_r(ctx, seq, 0, &cx, &cz) == 1) out = LocalPoint{cx, cz};
      GEOSGeom_destroy_r(ctx, mic);
    }
    if (boundary) GEOSGeom_destroy_r(ctx, boundary);
  }
  GEOSGeom_destroy_r(ctx, p);
  return out;
}

std::vector<LocalPoint> SurfacePlan::green_grid(double x, double z, double within, double inset, double step) const {
  GEOSContextHandle_t ctx = impl_->ctx;
  GEOSGeometry* p = GEOSGeom_createPointFromXY_r(ctx, x, z);
  const GEOSGeometry* best = impl_->nearest_green(p, within, nullptr);
  GEOSGeom_destroy_r(ctx, p);
  std::vector<LocalPoint> out;
  if (best == nullptr) return out;
  GEOSGeometry* core = GEOSBuffer_r(ctx, best, -inset, 8);  // the green shrunk by the inset
  if (core == nullptr) return out;
  const GEOSPreparedGeometry* prep = GEOSPrepare_r(ctx, core);
  double x0 = 0, z0 = 0, x1 = 0, z1 = 0;
  GEOSGeom_getXMin_r(ctx, core, &x0);
  GEOSGeom_getYMin_r(ctx, core, &z0);
  GEOSGeom_getXMax_r(ctx, core, &x1);
  GEOSGeom_getYMax_r(ctx, core, &z1);
  if (GEOSisEmpty_r(ctx, core) != 1)
    for (double qz = std::floor(z0 / step) * step; qz <= z1; qz += step)
      for (double qx = std::floor(x0 / step) * step; qx <= x1; qx += step) {
        GEOSGeometry* q = GEOSGeom_createPointFromXY_r(ctx, qx, qz);
        if (GEOSPreparedContains_r(ctx, prep, q) == 1) out.push_back({qx, qz});
        GEOSGeom_destroy_r(ctx, q);
      }
  GEOSPreparedGeom_destroy_r(ctx, prep);
  GEOSGeom_destroy_r(ctx, core);
  std::stable_sort(out.begin(), out.end(), [&](const LocalPoint& a, const LocalPoint& b) {
    return std::hypot(a.x - x, a.z - z) < std::hypot(b.x - x, b.z - z);
  });
  return out;
}

double SurfacePlan::depth_inside(double x, double z) const {
  GEOSContextHandle_t ctx = impl_->ctx;
  GEOSGeometry* p = GEOSGeom_createPointFromXY_r(ctx, x, z);
  double d = 0.0;
  for (const Impl::Region& r : impl_->regions)
    if (GEOSPreparedIntersects_r(ctx, r.prepared, p) == 1) {
      GEOSGeometry* edge = GEOSBoundary_r(ctx, r.geom);
      if (edge == nullptr || GEOSDistance_r(ctx, edge, p, &d) != 1) d = 0.0;
      if (edge) GEOSGeom_destroy_r(ctx, edge);
      break;
    }
  GEOSGeom_destroy_r(ctx, p);
  return d;
}

namespace {
// The polygons of a polygonal geometry.
std::vector<const GEOSGeometry*> polygons_of(GEOSContextHandle_t ctx, const GEOSGeometry* g) {
  std::vector<const GEOSGeometry*> out;
  if (GEOSGeomTypeId_r(ctx, g) == GEOS_POLYGON) out.push_back(g);
  else
    for (int i = 0; i < GEOSGetNumGeometries_r(ctx, g); ++i) {
      const GEOSGeometry* part = GEOSGetGeometryN_r(ctx, g, i);
      if (GEOSGeomTypeId_r(ctx, part) == GEOS_POLYGON) out.push_back(part);
    }
  return out;
}
}  // namespace

std::vector<std::vector<LocalPoint>> SurfacePlan::water_outlines() const {
  GEOSContextHandle_t ctx = impl_->ctx;
  std::vector<std::vector<LocalPoint>> out;
  for (const Impl::Region& r : impl_->regions) {
    if (r.material != "water") continue;
    for (const GEOSGeometry* poly : polygons_of(ctx, r.geom)) {
      const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(ctx, GEOSGetExteriorRing_r(ctx, poly));
      unsigned n = 0;
      GEOSCoordSeq_getSize_r(ctx, seq, &n);
      std::vector<LocalPoint> ring;
      for (unsigned i = 0; i < n; ++i) {
        double x = 0, z = 0;
        GEOSCoordSeq_getXY_r(ctx, seq, i, &x, &z);
        ring.push_back({x, z});
      }
      out.push_back(std::move(ring));
    }
  }
  return out;
}

int SurfacePlan::water_at(double x, double z) const {
  GEOSContextHandle_t ctx = impl_->ctx;
  GEOSGeometry* p = GEOSGeom_createPointFromXY_r(ctx, x, z);
  int k = 0, found = -1;
  for (const Impl::Region& r : impl_->regions) {
    if (r.material != "water") continue;
    for (const GEOSGeometry* poly : polygons_of(ctx, r.geom)) {
      if (found < 0 && GEOSIntersects_r(ctx, poly, p) == 1) found = k;
      ++k;
    }
  }
  GEOSGeom_destroy_r(ctx, p);
  return found;
}

SurfaceMesh SurfacePlan::triangulate(double cell, double green_cell) const {
  const Impl& m = *impl_;
  // The mesh's size before it is made: the grid's cells, and the greens' finer ones.
  const double cells = (m.x1 - m.x0) * (m.z1 - m.z0) / (cell * cell) + area("green") / (green_cell * green_cell);
  if (cells > kMaxCells) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "--cell %.2f m (greens %.2f m) would cut this course into %.1f million cells (at most %.0f million): a coarser grid",
                  cell, green_cell, cells / 1e6, kMaxCells / 1e6);
    throw InputError(msg);
  }
  GEOSContextHandle_t ctx = m.ctx;
  SurfaceMesh mesh;
  std::unordered_map<std::string, std::size_t> group_of;
  std::map<std::pair<long long, long long>, std::uint32_t> vertex_of;  // shared vertices, on a micrometre grid
  const auto vertex = [&](double x, double z) {
    const std::pair<long long, long long> key(std::llround(x * 1e6), std::llround(z * 1e6));
    const auto [it, fresh] = vertex_of.emplace(key, static_cast<std::uint32_t>(mesh.vertices.size()));
    if (fresh) mesh.vertices.emplace_back(x, 0.0, z);
    return it->second;
  };
  const auto emit = [&](const std::string& material, double ax, double az, double bx, double bz, double cx, double cz) {
    // Facing up: (b - a) x (c - a) has +y when the turn a -> b -> c is clockwise in (x, z).
    const double up = (cx - ax) * (bz - az) - (bx - ax) * (cz - az);
    if (std::abs(up) < 1e-10) return;  // a sliver with no area
    auto [it, fresh] = group_of.emplace(material, mesh.groups.size());
    if (fresh) mesh.groups.push_back({material, {}});
    auto& tris = mesh.groups[it->second].triangles;
    const std::uint32_t a = vertex(ax, az), b = vertex(bx, bz), c = vertex(cx, cz);
    if (up > 0.0) tris.push_back({a, b, c});
    else tris.push_back({a, c, b});
  };
  std::string failure;
  const auto triangulate_piece = [&](const std::string& material, const GEOSGeometry* piece) {
    const int type = GEOSGeomTypeId_r(ctx, piece);
    std::vector<const GEOSGeometry*> polys;
    if (type == GEOS_POLYGON) polys.push_back(piece);
    else if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION)
      for (int i = 0; i < GEOSGetNumGeometries_r(ctx, piece); ++i) {
        const GEOSGeometry* g = GEOSGetGeometryN_r(ctx, piece, i);
        if (GEOSGeomTypeId_r(ctx, g) == GEOS_POLYGON) polys.push_back(g);
      }
    for (const GEOSGeometry* poly : polys) {
      double a = 0.0;
      if (GEOSArea_r(ctx, poly, &a) != 1 || a < 1e-8) continue;
      GEOSGeometry* tris = GEOSConstrainedDelaunayTriangulation_r(ctx, poly);
      if (tris == nullptr) {
        // A clipped piece that touches itself: mended, then triangulated; a piece left out
        // would be a hole in the ground that a ball falls through.
        if (GEOSGeometry* fixed = GEOSMakeValid_r(ctx, poly)) {
          tris = GEOSConstrainedDelaunayTriangulation_r(ctx, fixed);
          GEOSGeom_destroy_r(ctx, fixed);
        }
        if (tris == nullptr) {
          if (failure.empty()) {  // said once the loops below have freed what they hold
            double px = 0.0, pz = 0.0;
            GEOSGeom_getXMin_r(ctx, poly, &px);
            GEOSGeom_getYMin_r(ctx, poly, &pz);
            char msg[160];
            std::snprintf(msg, sizeof msg, "course import: the %s at %.1f m east, %.1f m south could not be triangulated", material.c_str(), px, pz);
            failure = msg;
          }
          continue;
        }
      }
      for (int i = 0; i < GEOSGetNumGeometries_r(ctx, tris); ++i) {
        const GEOSGeometry* t = GEOSGetGeometryN_r(ctx, tris, i);
        const GEOSGeometry* shell = GEOSGetExteriorRing_r(ctx, t);
        const GEOSCoordSequence* seq = shell ? GEOSGeom_getCoordSeq_r(ctx, shell) : nullptr;
        double x[3], z[3];
        bool ok = seq != nullptr;
        for (unsigned k = 0; ok && k < 3; ++k) ok = GEOSCoordSeq_getXY_r(ctx, seq, k, &x[k], &z[k]) == 1;
        if (ok) emit(material, x[0], z[0], x[1], z[1], x[2], z[2]);
      }
      GEOSGeom_destroy_r(ctx, tris);
    }
  };
  const int nx = std::max(1, static_cast<int>(std::ceil((m.x1 - m.x0) / cell)));
  const int nz = std::max(1, static_cast<int>(std::ceil((m.z1 - m.z0) / cell)));
  for (int j = 0; j < nz; ++j) {
    const double za = m.z0 + j * cell, zb = std::min(m.z1, za + cell);
    // Each region clipped to this row first: the cells then clip small pieces.
    std::vector<GEOSGeometry*> rows(m.regions.size(), nullptr);
    for (std::size_t r = 0; r < m.regions.size(); ++r) rows[r] = GEOSClipByRect_r(ctx, m.regions[r].geom, m.x0, za, m.x1, zb);
    for (int i = 0; i < nx; ++i) {
      const double xa = m.x0 + i * cell, xb = std::min(m.x1, xa + cell);
      GEOSGeometry* box = GEOSGeom_createRectangle_r(ctx, xa, za, xb, zb);
      for (std::size_t r = 0; r < m.regions.size(); ++r) {
        if (rows[r] == nullptr || GEOSisEmpty_r(ctx, rows[r]) == 1) continue;
        if (GEOSPreparedContains_r(ctx, m.regions[r].prepared, box) == 1) {
          const double step = m.regions[r].material == "green" && green_cell < cell ? green_cell : cell;
          for (double sz = za; sz < zb - 1e-9; sz += step)
            for (double sx = xa; sx < xb - 1e-9; sx += step) {
              const double ex = std::min(xb, sx + step), ez = std::min(zb, sz + step);
              emit(m.regions[r].material, sx, sz, ex, sz, ex, ez);
              emit(m.regions[r].material, sx, sz, ex, ez, sx, ez);
            }
          break;
        }
        if (GEOSPreparedIntersects_r(ctx, m.regions[r].prepared, box) != 1) continue;
        GEOSGeometry* piece = GEOSClipByRect_r(ctx, rows[r], xa, za, xb, zb);
        if (piece == nullptr) continue;
        if (m.regions[r].material == "green" && green_cell < cell) {
          // The green's finer grid inside this cell.
          for (double sz = za; sz < zb - 1e-9; sz += green_cell)
            for (double sx = xa; sx < xb - 1e-9; sx += green_cell) {
              GEOSGeometry* sub = GEOSClipByRect_r(ctx, piece, sx, sz, std::min(xb, sx + green_cell), std::min(zb, sz + green_cell));
              if (sub != nullptr) {
                triangulate_piece(m.regions[r].material, sub);
                GEOSGeom_destroy_r(ctx, sub);
              }
            }
        } else {
          triangulate_piece(m.regions[r].material, piece);
        }
        GEOSGeom_destroy_r(ctx, piece);
      }
      GEOSGeom_destroy_r(ctx, box);
    }
    for (GEOSGeometry* g : rows)
      if (g) GEOSGeom_destroy_r(ctx, g);
  }
  if (!failure.empty()) throw InputError(failure);
  return mesh;
}

}  // namespace sweetspot
