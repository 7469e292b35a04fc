// Exact time of first contact of a moving sphere with a triangle: the narrow phase of the
// world's sweeps. Bullet's BVH picks the candidate triangles; this replaces its per-triangle
// GJK conservative advancement, which would be the largest single cost of a whole shot (profile
// in docs/performance.md), with closed-form face, edge and corner tests.
#pragma once

#include "physics/math.hpp"

namespace sweetspot {

/// The first fraction f in [0, 1] at which a sphere of `radius` (m) whose centre moves from
/// `from` to `from + motion` touches triangle (a, b, c). A sphere already touching or
/// overlapping the triangle at the start gives 0. Returns false when it never touches.
/// Degenerate (zero-area) triangles and a zero motion give false unless touching at start.
bool sphere_triangle_sweep(const Vec3& from, const Vec3& motion, double radius, const Vec3& a, const Vec3& b,
                           const Vec3& c, double* fraction);

/// Closest point of triangle (a, b, c) to p (Voronoi-region walk).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace sweetspot
