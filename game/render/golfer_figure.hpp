// The golfer who makes the stroke (issue 44): a right-handed figure whose hands hold the club
// the physics delivered, at every instant of its downswing (swing_pose.hpp), standing where a
// golfer must to hold it there at impact. Articulated boxes, lit like the club and the ball.
#pragma once

#include <array>

#include <Eigen/Core>

#include "game/render/mesh_data.hpp"
#include "physics/math.hpp"

namespace sweetspot {

struct GolferBody {
  enum Joint : int {
    kHead, kChest, kPelvis, kLeadShoulder, kTrailShoulder, kLeadElbow, kTrailElbow, kHands,
    kLeadHip, kTrailHip, kLeadKnee, kTrailKnee, kLeadFoot, kTrailFoot, kJointCount
  };
  std::array<Vec3, kJointCount> joint{};
};

/// The body for hands at `grip` (m, world) when at impact they were at `grip_at_impact`, the
/// shot going along `target` (horizontal unit), the ground at `ground_y` under his feet.
/// At address and impact his shoulders are square to the target line; as the hands go back
/// and up his shoulders turn with them (at the top of the backswing ~90°).
GolferBody golfer_body(const Vec3& grip, const Vec3& grip_at_impact, const Vec3& target, double ground_y);

/// Appends the figure as boxes along its bones (shirt, trousers, skin) to `out`.
void append_golfer(MeshData& out, const GolferBody& body);

/// The club's shaft and grip in his hands: `length` m down `shaft` (unit, from the head
/// toward the grip) from `grip`; the head's mesh carries only the shaft's first 0.65-0.75 m.
void append_club_shaft(MeshData& out, const Vec3& grip, const Vec3& shaft, double length);

/// A box of square section `width` m from `a` to `b`, its faces lit flat.
void append_limb(MeshData& out, const Vec3& a, const Vec3& b, double width, const Eigen::Vector3f& color);

}  // namespace sweetspot
