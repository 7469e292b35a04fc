// Where a world's trees stand, as a map draws them: each crown's centre, top and spread,
// read from the world's meshes (a crown is one connected piece of a "tree" surface).
#pragma once

#include <vector>

#include "physics/math.hpp"
#include "physics/world.hpp"

namespace sweetspot {

struct TreeCrown {
  Vec3 centre;          ///< m: the middle of its footprint, at the crown's top
  double radius = 0.0;  ///< m: the footprint's farthest vertex from that middle, across the ground
};

/// One crown per connected piece of the world's tree surfaces (material kind Tree whose
/// name is not "trunk"). Empty for a world without trees.
std::vector<TreeCrown> tree_crowns(const WorldDescription& world);

}  // namespace sweetspot
