// The diamond of a ballpark drawn from the rule-book dimensions (Official Baseball Rules 2.01
// and diagram 2; the 18 in bases of 2023): smooth infield skin, infield grass, mound and
// home-plate circles, warning track, and the white bases, plate, pitcher's rubber, batter's
// boxes and the two yellow foul poles. The world mesh's 2.5 m cells make those shapes
// staircases; this lies on top of them in layers (lowest first), so the park reads as a
// park. scripts/gen_worlds.py builds the ballpark's physics surfaces from the same numbers.
// Pure geometry, world frame of DESIGN §2: home plate's back point at `home`, centre field
// toward +x, first base toward +z.
#pragma once

#include <optional>
#include <vector>

#include "game/render/mesh_data.hpp"
#include "physics/math.hpp"

namespace sweetspot {

struct BallparkDressing {
  /// Flat layers on the field, drawn in order, each over the one before (a decal offset).
  std::vector<MeshData> layers;
  /// The foul poles (lit boxes standing at the fence's ends).
  MeshData poles;
  /// The stands beyond the outfield wall and along the foul lines, and the batter's eye
  /// beyond centre field (lit; decoration: the physics' stands are the ground out of bounds).
  MeshData stands;
};

/// Distance (m) from `origin` along the horizontal direction `dir` (xz used) to where it
/// first crosses the polyline `line` (xz), if it does: where a spray angle meets the fence.
std::optional<double> ray_polyline(const Vec3& origin, const Vec3& dir, const std::vector<Vec3>& line);

/// `fence_line`: foot of the fence, left-field pole to right-field pole (WorldAsset);
/// `fence_height` m. The field is taken as flat at home's height.
BallparkDressing ballpark_dressing(const Vec3& home, const std::vector<Vec3>& fence_line, double fence_height);

}  // namespace sweetspot
