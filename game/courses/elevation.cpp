#include "game/courses/elevation.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <utility>

#include <unistd.h>

#include <gdal.h>
#include <ogr_srs_api.h>

#include "physics/error.hpp"

namespace sweetspot {
namespace {
// m: a height outside these is no ground on Earth (the lowest dry land, the Dead Sea's shore,
// lies ~430 m below the sea; Everest 8849 m above it), but a spike, a no-data value the raster
// does not declare, or feet read as metres.
constexpr double kLowestGround = -500.0, kHighestGround = 9000.0;
}  // namespace

struct ElevationModel::Impl {
  std::filesystem::path path;
  GDALDatasetH ds = nullptr;
  OGRSpatialReferenceH wgs84 = nullptr;
  OGRCoordinateTransformationH to_raster = nullptr;
  double gt[6] = {0, 1, 0, 0, 0, 1};
  int width = 0, height = 0;
  double nodata = 0.0;
  bool has_nodata = false;
  std::vector<float> cells;  // the whole band, row by row (a course's raster is a few million cells)
  ~Impl() {
    if (to_raster) OCTDestroyCoordinateTransformation(to_raster);
    if (wgs84) OSRDestroySpatialReference(wgs84);
    if (ds) GDALClose(ds);
  }
  InputError fail(const std::string& why) const { return InputError(path.string() + ": " + why); }
};

ElevationModel::ElevationModel(const std::filesystem::path& path) : impl_(std::make_unique<Impl>()) {
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  Impl& m = *impl_;
  m.path = path;
  // A missing or unreadable file is said as such, not as a raster GDAL cannot read.
  if (std::error_code ec; !std::filesystem::is_regular_file(path, ec))
    throw m.fail(std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");
  if (::access(path.c_str(), R_OK) != 0) throw m.fail(std::string("cannot be read: ") + std::strerror(errno));
  CPLPushErrorHandler(CPLQuietErrorHandler);
  m.ds = GDALOpen(path.string().c_str(), GA_ReadOnly);
  CPLPopErrorHandler();
  if (m.ds == nullptr) throw m.fail("not an elevation raster GDAL reads (GeoTIFF, an ASCII grid, ...)");
  if (GDALGetRasterCount(m.ds) < 1) throw m.fail("the raster has no band of heights");
  if (GDALGetGeoTransform(m.ds, m.gt) != CE_None) throw m.fail("the raster has no georeference (where on Earth its cells lie)");
  for (const int k : {1, 5})
    if (!std::isfinite(m.gt[k]) || m.gt[k] == 0.0) {
      char msg[160];
      std::snprintf(msg, sizeof msg, "its cells have no size (%s %g): a grid's cells must be wider than 0",
                    k == 1 ? "cell width" : "cell height", m.gt[k]);
      throw m.fail(msg);
    }
  if (!std::isfinite(m.gt[0]) || !std::isfinite(m.gt[3])) throw m.fail("its corner lies nowhere (a coordinate that is not a number)");
  OGRSpatialReferenceH srs = GDALGetSpatialRef(m.ds);
  if (srs == nullptr) throw m.fail("the raster names no coordinate reference system (an ASCII grid needs its .prj beside it)");
  m.wgs84 = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(m.wgs84, 4326);
  OSRSetAxisMappingStrategy(m.wgs84, OAMS_TRADITIONAL_GIS_ORDER);  // x = longitude, y = latitude
  OGRSpatialReferenceH target = OSRClone(srs);
  OSRSetAxisMappingStrategy(target, OAMS_TRADITIONAL_GIS_ORDER);
  m.to_raster = OCTNewCoordinateTransformation(m.wgs84, target);
  OSRDestroySpatialReference(target);
  if (m.to_raster == nullptr) throw m.fail("its coordinate reference system cannot be reached from latitude and longitude");
  m.width = GDALGetRasterXSize(m.ds);
  m.height = GDALGetRasterYSize(m.ds);
  if (static_cast<double>(m.width) * m.height > 64.0e6) throw m.fail("more than 64 million cells: crop it to the course");
  GDALRasterBandH band = GDALGetRasterBand(m.ds, 1);
  int ok = 0;
  m.nodata = GDALGetRasterNoDataValue(band, &ok);
  m.has_nodata = ok != 0;
  m.cells.resize(static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height));
  if (GDALRasterIO(band, GF_Read, 0, 0, m.width, m.height, m.cells.data(), m.width, m.height, GDT_Float32, 0, 0) != CE_None)
    throw m.fail("its heights could not be read");
}

ElevationModel::~ElevationModel() = default;

std::vector<double> ElevationModel::heights(const LocalFrame& frame, const std::vector<LocalPoint>& points) const {
  const Impl& m = *impl_;
  std::vector<double> x(points.size()), y(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const GeoPoint g = frame.to_geo(points[i]);
    x[i] = g.lon;
    y[i] = g.lat;
  }
  std::vector<int> ok(points.size(), 0);
  if (!points.empty() && !OCTTransformEx(m.to_raster, static_cast<int>(points.size()), x.data(), y.data(), nullptr, ok.data()))
    throw m.fail("the course's points could not be carried into the raster's coordinates");
  // Inverse of the geotransform (no rotation terms in the rasters we take).
  if (m.gt[2] != 0.0 || m.gt[4] != 0.0) throw m.fail("a rotated raster (its geotransform turns the grid): warp it north-up first");
  std::vector<double> out(points.size());
  const double cell = std::max(std::abs(m.gt[1]), std::abs(m.gt[5]));
  double worst = -1.0;  // m the farthest point lies outside the raster (infinity: no place in its coordinates)
  std::size_t worst_i = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Cell centres sit half a cell in; heights are held flat over the outer half cell.
    const double col = (x[i] - m.gt[0]) / m.gt[1] - 0.5, row = (y[i] - m.gt[3]) / m.gt[5] - 0.5;
    const double c = std::clamp(col, 0.0, m.width - 1.0), r = std::clamp(row, 0.0, m.height - 1.0);
    const double off = ok[i] ? std::hypot((col - c) * std::abs(m.gt[1]), (row - r) * std::abs(m.gt[5])) : HUGE_VAL;
    if (off > 0.5 * cell + 1e-9) {
      if (off > worst) {
        worst = off;
        worst_i = i;
      }
      continue;
    }
    const int c0 = std::max(0, std::min(static_cast<int>(c), m.width - 2)), r0 = std::max(0, std::min(static_cast<int>(r), m.height - 2));
    const int c1 = std::min(c0 + 1, m.width - 1), r1 = std::min(r0 + 1, m.height - 1);
    const double u = std::clamp(c - c0, 0.0, 1.0), v = std::clamp(r - r0, 0.0, 1.0);
    const auto at = [&](int cc, int rr) { return static_cast<double>(m.cells[static_cast<std::size_t>(rr) * static_cast<std::size_t>(m.width) + static_cast<std::size_t>(cc)]); };
    const double h00 = at(c0, r0), h10 = at(c1, r0), h01 = at(c0, r1), h11 = at(c1, r1);
    for (const double h : {h00, h10, h01, h11})
      if ((m.has_nodata && h == m.nodata) || !std::isfinite(h)) {
        char msg[160];
        std::snprintf(msg, sizeof msg, "has no height (its no-data value) under the course at %.0f m east, %.0f m south of its centre",
                      points[i].x, points[i].z);
        throw m.fail(msg);
      }
    for (const auto& [cc, rr] : {std::pair{c0, r0}, std::pair{c1, r0}, std::pair{c0, r1}, std::pair{c1, r1}})
      if (const double h = at(cc, rr); h < kLowestGround || h > kHighestGround) {
        char msg[260];
        std::snprintf(msg, sizeof msg, "cell (column %d, row %d) under the course reads %.6g m: ground lies between %.0f and %.0f m "
                      "(the Dead Sea's shore, -430 m, to Everest, 8849 m)", cc, rr, h, kLowestGround, kHighestGround);
        throw m.fail(msg);
      }
    out[i] = (1 - v) * ((1 - u) * h00 + u * h10) + v * ((1 - u) * h01 + u * h11);
  }
  if (worst >= 0.0) {
    char msg[220];
    if (std::isinf(worst))
      std::snprintf(msg, sizeof msg, "covers none of the course (its point %.0f m east, %.0f m south of the centre has no place in the raster's coordinates)",
                    points[worst_i].x, points[worst_i].z);
    else
      std::snprintf(msg, sizeof msg, "does not cover the course: the course's point %.0f m east, %.0f m south of its centre lies %.0f m outside it (a raster of another place?)",
                    points[worst_i].x, points[worst_i].z, worst);
    throw m.fail(msg);
  }
  return out;
}

}  // namespace sweetspot
