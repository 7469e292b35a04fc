// The ground's height from an elevation raster (course import's --dem): anything GDAL reads
// (GeoTIFF, an ASCII grid with its .prj, ...) in any coordinate reference system it knows;
// the course's points are carried into the raster's system (GDAL's OSR, through PROJ) and
// the height taken bilinearly between its four nearest cells.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "game/courses/local_frame.hpp"

namespace sweetspot {

class ElevationModel {
 public:
  /// Opens `path`. Throws InputError naming it: not a raster GDAL reads, no coordinate
  /// reference system.
  explicit ElevationModel(const std::filesystem::path& path);
  ~ElevationModel();
  ElevationModel(const ElevationModel&) = delete;
  ElevationModel& operator=(const ElevationModel&) = delete;

  /// m above the raster's datum at each point of `frame`, in order. Throws InputError naming
  /// the raster when a point lies outside it or on a cell without data ("a raster of another
  /// place": it says how far the course lies from the raster's extent).
  std::vector<double> heights(const LocalFrame& frame, const std::vector<LocalPoint>& points) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sweetspot
