// Heights for an imported course's ground (course import --dem): the raster's ground;
// greens smoothed to putting surfaces; bunkers sunk into it; water a flat hazard below its
// banks; and no crack where a finer part of the mesh (a green's grid) meets a coarser one.
#pragma once

#include "game/courses/elevation.hpp"
#include "game/courses/surface_plan.hpp"

namespace sweetspot {

/// Greens: the raster averaged over a disc of this radius (a 1 m lidar grid's noise and the
/// turf's texture gone, the breaks of ~10 m wavelength kept; ESTIMATE).
inline constexpr double kGreenSmoothing = 3.0;  // m
/// Bunkers: sunk this deep at most, the face rising at this depth per metre in from the
/// edge (ESTIMATES of a fairway bunker's 30-40 cm of sand below its lip).
inline constexpr double kBunkerDepth = 0.35, kBunkerFace = 0.6;  // m, m/m
/// Water: a flat plane this far below the lowest point of its bank (ESTIMATE).
inline constexpr double kWaterDrop = 0.3;  // m

/// The raster's ground at `p`, averaged over the green smoothing disc: the putting surface.
double smoothed_height(const ElevationModel& dem, const LocalFrame& frame, const LocalPoint& p);
/// The putting surface's slope at `p` (rise over run, from its height 1 m either way).
double green_slope(const ElevationModel& dem, const LocalFrame& frame, const LocalPoint& p);

/// Sets every vertex's height (y, m above the raster's datum) as above.
void shape_heights(SurfaceMesh& mesh, const SurfacePlan& plan, const ElevationModel& dem, const LocalFrame& frame);

/// Vertices that lie inside an edge used by one triangle only (a T-junction: the finer side
/// has them, the coarser side's edge passes by) take the height of that edge there.
void conform_hanging_vertices(SurfaceMesh& mesh);

}  // namespace sweetspot
