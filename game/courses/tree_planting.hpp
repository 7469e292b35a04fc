// Trees on an imported course (course import): where the map's trees stand (natural=tree),
// along its tree rows and through its woods, each planted on rough or out-of-bounds ground,
// and the shapes the ball strikes: a six-sided trunk under a six-sided double-cone crown, as
// the world's "trunk" and "tree" materials (assets/materials.toml).
#pragma once

#include <cstddef>
#include <vector>

#include "game/courses/golf_map.hpp"
#include "game/courses/local_frame.hpp"
#include "game/courses/surface_plan.hpp"

namespace sweetspot {

/// A tree's height when the map gives none: a parkland tree in middle age (ESTIMATE: the
/// oaks, beeches and pines that line fairways reach 15-25 m when mature, ~10-15 m at 40-60 years).
inline constexpr double kDefaultTreeHeight = 12.0;  // m
/// m between trees along a row and through a wood: crowns of ~7 m (kCrownRadius of a 12 m
/// tree) nearly touching, as in a closed canopy (ESTIMATE).
inline constexpr double kTreeSpacing = 8.0;
/// Trees on one course at most: 24 triangles each, 4000 trees add ~96 000 triangles, about
/// what an 18-hole ground takes (a shot's cost stays within bench's course_cost_ratio). Woods
/// beyond it are planted sparser, and the import says so.
inline constexpr std::size_t kMaxTrees = 4000;
/// The crown's shape as shares of the tree's height: it starts at kCrownBase and is
/// kCrownRadius wide at its middle (ESTIMATE of a broadleaf's ovoid crown, ~2/3 of its height).
inline constexpr double kCrownBase = 0.35, kCrownRadius = 0.3;
/// Grid cells tried through woods at most (each a point-in-polygon test): a few times what
/// kMaxTrees needs where woods fill their boxes; a sliver drawn across the course's box
/// stops here instead of walking its empty cells.
inline constexpr std::size_t kMaxWoodCells = 200'000;
inline constexpr double kTrunkRadius = 0.2;  // m, a 40 cm trunk (ESTIMATE)

struct PlantedTree {
  LocalPoint at;
  double height = kDefaultTreeHeight;  ///< m
};

struct TreePlanting {
  std::vector<PlantedTree> trees;
  std::size_t mapped = 0, in_rows = 0, in_woods = 0;  ///< planted, by where the map put them
  std::size_t left_out = 0;     ///< on fairway, green, tee, bunker, water or off the ground
  std::size_t over_limit = 0;   ///< past kMaxTrees
  double wood_spacing = kTreeSpacing;  ///< m, wider than kTreeSpacing when kMaxTrees binds
};

/// Where the map's trees stand on `plan`: every mapped tree, one each kTreeSpacing along each
/// row, and through each wood a jittered grid (seeded by the wood's element id, so a re-import
/// plants the same trees); those not on rough or out-of-bounds ground are left out, and none
/// past kMaxTrees is planted. Rows and woods are walked within the plan's rectangle only.
TreePlanting plant_trees(const GolfMap& map, const LocalFrame& frame, const SurfacePlan& plan);

/// Adds each tree to `mesh` standing on the ground at `base[i]` (m, y of the ground there):
/// a trunk (material "trunk") from below the ground into the crown, and the crown ("tree"),
/// each face pointing out.
void add_tree_meshes(SurfaceMesh& mesh, const std::vector<PlantedTree>& trees, const std::vector<double>& base);

}  // namespace sweetspot
