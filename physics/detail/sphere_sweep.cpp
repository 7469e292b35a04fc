#include "physics/detail/sphere_sweep.hpp"

#include <algorithm>
#include <cmath>

namespace sweetspot {
namespace {

/// Smallest root in [0, 1] of a t² + b t + c = 0 entered from outside (c > 0), if any.
bool first_entry(double a, double b, double c, double* t) {
  if (!(a > 0.0)) return false;  // no relative motion across this feature
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return false;
  const double root = (-b - std::sqrt(disc)) / (2.0 * a);
  if (!(root >= 0.0 && root <= 1.0)) return false;
  *t = root;
  return true;
}

}  // namespace

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

bool sphere_triangle_sweep(const Vec3& from, const Vec3& motion, double radius, const Vec3& a, const Vec3& b,
                           const Vec3& c, double* fraction) {
  const double r2 = radius * radius;
  const Vec3 cross = (b - a).cross(c - a);
  const double cross2 = cross.squaredNorm();
  // The centre's distance to the triangle's plane is linear along the sweep: when both ends
  // are farther than the radius on the same side, no point of the path comes within reach
  // of the plane, let alone of the triangle. Most candidates of a sweep end here, before the
  // closest-point search (a sweep's triangles are ~4 m boxes, the ball's reach cm).
  // Compared squared (|s| > r·|cross| as s² > r²·|cross|²), so no square root is waited for.
  {
    const double s_from = cross.dot(from - a), s_to = s_from + cross.dot(motion);
    const double reach2 = r2 * cross2;
    if (cross2 > 0.0 && ((s_from > 0.0 && s_to > 0.0) || (s_from < 0.0 && s_to < 0.0)) && s_from * s_from > reach2 &&
        s_to * s_to > reach2)
      return false;
  }
  const double area2 = std::sqrt(cross2);
  if ((closest_point_on_triangle(from, a, b, c) - from).squaredNorm() <= r2) {
    *fraction = 0.0;
    return true;
  }
  if (!(area2 > 0.0)) return false;
  const Vec3 n = cross / area2;

  // Face: the sphere meets the plane on the side it starts from; when that first touch
  // lies inside the triangle it is the earliest contact with any part of it.
  const double s0 = n.dot(from - a);
  const double ds = n.dot(motion);
  if (s0 * ds < 0.0) {
    const double side = s0 > 0.0 ? 1.0 : -1.0;
    // A sphere already reaching the plane at the start (t < 0) touches it at once: the
    // closest-point test above says so too, but only up to rounding. A ball placed exactly
    // on the plane (its centre r off it) and moving into it could pass both tests by an ulp
    // each (s0 a hair under r here, the distance a hair over r there) and miss the face
    // entirely: a launch along a slope would pass 7 mm into it (test_world.cpp).
    const double t = std::max((s0 - side * radius) / -ds, 0.0);
    if (t <= 1.0) {
      const Vec3 q = from + t * motion - side * radius * n;
      const double eps = -1e-12 * area2;
      if (n.dot((b - a).cross(q - a)) >= eps && n.dot((c - b).cross(q - b)) >= eps &&
          n.dot((a - c).cross(q - c)) >= eps) {
        *fraction = t;
        return true;
      }
    }
  }

  // Otherwise the first touch is on an edge (a cylinder about it, within the segment) or
  // a corner (a sphere about it): the earliest of the six.
  bool found = false;
  double best = 2.0;
  const Vec3* corners[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = *corners[k];
    const Vec3& q = *corners[(k + 1) % 3];
    const Vec3 e = q - p;
    const double ee = e.dot(e);
    const Vec3 m = from - p;
    double t = 0.0;
    if (ee > 0.0) {
      const Vec3 m_perp = m - (m.dot(e) / ee) * e;
      const Vec3 d_perp = motion - (motion.dot(e) / ee) * e;
      if (first_entry(d_perp.dot(d_perp), 2.0 * m_perp.dot(d_perp), m_perp.dot(m_perp) - r2, &t) && t < best) {
        const double u = (m + t * motion).dot(e) / ee;
        if (u >= 0.0 && u <= 1.0) {
          best = t;
          found = true;
        }
      }
    }
    if (first_entry(motion.dot(motion), 2.0 * m.dot(motion), m.dot(m) - r2, &t) && t < best) {
      best = t;
      found = true;
    }
  }
  if (found) *fraction = best;
  return found;
}

}  // namespace sweetspot
