// A putt to start a test round with: a hole of the national course with its tee moved onto
// its green, a given distance and direction from the cup.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>

#include "game/content/course_file.hpp"
#include "physics/world.hpp"
#include "support/test_assets.hpp"

namespace sweetspot::test {

/// The national course (loaded once).
inline const Course& national() {
  static const Course c = load_course(assets(), "national");
  return c;
}

/// A one-hole course of the national course's hole `n` (0-based) whose tee is on its green
/// `dist` m from the cup in direction `angle` (rad from +x). None when that spot is not green.
inline std::optional<Course> national_hole_from_green(std::size_t n, double dist, double angle) {
  Course c = national();
  c.holes = {national().holes.at(n)};
  c.holes[0].number = 1;
  const Vec3 pin = c.holes[0].pin;
  SurfaceContact hit;
  if (!ground_under(*c.holes[0].world->world, pin.x() + dist * std::cos(angle), pin.z() + dist * std::sin(angle), 400.0,
                    420.0, &hit))
    return std::nullopt;
  if (c.holes[0].world->world->material(hit.material).kind != SurfaceKind::Green) return std::nullopt;
  c.holes[0].tee = hit.point;
  return c;
}

}  // namespace sweetspot::test
