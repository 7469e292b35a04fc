// Seeded random golf worlds and shots for the random-world soak: heightfields with creases
// (V ditches of random depth, width and direction), a step, bumps and random surfaces per
// cell, and random launches from putts to drives. tests/soak/soak_worlds flies thousands of
// them; tests/unit/physics/test_soak_findings.cpp replays the hardest. World i of a seed
// draws from its own generator, so one world is rebuilt alone, bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/world.hpp"
#include "soak/soak_rng.hpp"
#include "support/test_assets.hpp"

namespace sweetspot::test {

/// A heightfield on an nx × nz grid of square cells of side h (m) over x in [x0, x0 + nx h],
/// z in [z0, −z0]; each cell is two triangles split along (i,k)–(i+1,k+1).
struct HeightField {
  int nx = 0, nz = 0;
  double h = 0.0, x0 = 0.0, z0 = 0.0;
  std::vector<double> y;  ///< m, (nx + 1)(nz + 1) corner heights, row k = z index
  double at(int i, int k) const { return y[static_cast<std::size_t>(k * (nx + 1) + i)]; }
  /// The surface height (m) under (x, z); false off the field.
  bool height(double x, double z, double* out) const;
};

/// World `index` of a soak seeded by `seed`: its field, its Bullet world, and the generator
/// positioned after them, from which its shots are drawn in order.
struct RandomWorld {
  soak::Rng rng;
  HeightField field;
  WorldDescription description;
  RandomWorld(std::uint64_t seed, long index);
};

/// A random golf launch from the origin tee: 30 % putts and chips (1–15 mph, −2…5°), the
/// rest 15–175 mph at −5…50°, ±20° aim, 0–10 000 rpm on a ±40° axis. `text` (≥ 120 chars,
/// may be null) receives the launch numbers for a report.
FlightCase random_golf_shot(soak::Rng& g, char* text = nullptr, std::size_t text_size = 0);

}  // namespace sweetspot::test
