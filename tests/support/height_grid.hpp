// A height field [-half, half]² split into n×n cells of two triangles each, for tests that
// need a ground of their own (a plane, a bowl): vertex heights from `height(x, z)` (m),
// wound counter-clockwise seen from above so every normal points up.
#pragma once

#include <cstdint>

#include "physics/world.hpp"

namespace sweetspot::test {

template <class Height>
WorldMesh height_grid(int material, double half, int n, const Height& height) {
  WorldMesh m;
  m.material = material;
  const double cell = 2.0 * half / n;
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n; ++i) {
      const double x = -half + i * cell, z = -half + k * cell;
      m.vertices.emplace_back(x, height(x, z), z);
    }
  const auto at = [n](int i, int k) { return static_cast<std::uint32_t>(k * (n + 1) + i); };
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) {
      m.indices.insert(m.indices.end(), {at(i, k), at(i, k + 1), at(i + 1, k)});
      m.indices.insert(m.indices.end(), {at(i + 1, k), at(i, k + 1), at(i + 1, k + 1)});
    }
  return m;
}

}  // namespace sweetspot::test
