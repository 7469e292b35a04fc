// The ground a course covers, surface by surface (course import): each mapped area in the
// course's frame; where areas overlap, the one higher in MapSurface's order covers the ground
// (a green inside a fairway, a bunker in the rough); the rest of the course is rough, and
// outside its boundary lies out of bounds. Its triangulation follows every mapped edge: a grid
// of cells cut along the surfaces' boundaries and each piece triangulated with its edges kept
// (GEOS: polygon overlay, rectangle clipping, constrained Delaunay triangulation), so a
// bunker's edge is the mapped curve, not a staircase of cells.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "game/courses/local_frame.hpp"
#include "physics/math.hpp"

namespace sweetspot {

/// A triangle mesh by material, vertices shared, every triangle facing up (+y).
struct SurfaceMesh {
  std::vector<Vec3> vertices;
  struct Group {
    std::string material;  ///< assets/materials.toml's name
    std::vector<std::array<std::uint32_t, 3>> triangles;
  };
  std::vector<Group> groups;
  std::size_t triangle_count() const;
};

/// The material (assets/materials.toml) a mapped surface plays as.
const char* material_of(MapSurface s);

class SurfacePlan {
 public:
  /// Lays out `map` in `frame`: what it mends (an area whose rings cross themselves, no
  /// course boundary mapped) is added to `report`. `margin` m of out of bounds ring the
  /// course. Throws InputError when nothing is mapped to play on.
  SurfacePlan(const GolfMap& map, const LocalFrame& frame, std::vector<std::string>& report, double margin = 30.0);
  ~SurfacePlan();
  SurfacePlan(const SurfacePlan&) = delete;
  SurfacePlan& operator=(const SurfacePlan&) = delete;

  /// The material of the ground at (x, z); "" outside the plan.
  std::string material_at(double x, double z) const;
  /// m² of ground of `material`.
  double area(const std::string& material) const;
  /// A spot on the green that holds (x, z) or lies within `within` m of it: (x, z) itself when
  /// it is on the green and at least `inset` m from its edge, else the point of that green
  /// farthest inside it (its pole of inaccessibility). None when no green is that near.
  std::optional<LocalPoint> green_spot(double x, double z, double within, double inset) const;
  /// Points `step` m apart on the green nearest (x, z) within `within` m, each at least
  /// `inset` m inside its edge, nearest (x, z) first. Empty when no green is that near.
  std::vector<LocalPoint> green_grid(double x, double z, double within, double inset, double step) const;
  /// m from (x, z) to the edge of the surface it lies on (0 on an edge or off the plan).
  double depth_inside(double x, double z) const;
  /// The outline of each body of water (its outer ring), and which holds (x, z) (-1: none).
  std::vector<std::vector<LocalPoint>> water_outlines() const;
  int water_at(double x, double z) const;
  /// The ground cut into cells of `cell` m along every surface edge, the greens into cells of
  /// `green_cell` m (no finer than `cell`); flat (y = 0).
  SurfaceMesh triangulate(double cell, double green_cell) const;
  LocalPoint min() const;
  LocalPoint max() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sweetspot
