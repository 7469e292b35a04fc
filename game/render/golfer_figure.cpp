#include "game/render/golfer_figure.hpp"

#include <cmath>

namespace sweetspot {
namespace {

// Body proportions of a 1.80 m golfer (ESTIMATES from standard anthropometry: shoulders at
// 0.82 of his height, hips at 0.53, half the shoulders' width 0.2 m): the chest sits 0.55 m
// above and 0.3 m back from his hands at address, the pelvis 0.5 m below the chest and
// 0.2 m farther back (the spine tilted ~35° over the ball), the feet a shoulder-width apart.
constexpr double kChestAboveHands = 0.55, kChestBehindHands = 0.30;
constexpr double kPelvisBelowChest = 0.50, kPelvisBehindChest = 0.20;
constexpr double kHalfShoulders = 0.20, kHalfHips = 0.12, kHalfStance = 0.28;
constexpr double kHeadAboveChest = 0.27;

const Eigen::Vector3f kShirt(0.13f, 0.20f, 0.42f), kTrousers(0.55f, 0.55f, 0.52f), kSkin(0.80f, 0.62f, 0.48f);

}  // namespace

GolferBody golfer_body(const Vec3& grip, const Vec3& grip_at_impact, const Vec3& target, double ground_y) {
  const Vec3 up = Vec3::UnitY();
  const Vec3 a = Vec3(target.x(), 0.0, target.z()).normalized();
  const Vec3 to_ball = a.cross(up).normalized();  // a right-hander faces the ball, his left side to the target
  GolferBody b;
  auto& j = b.joint;
  j[GolferBody::kChest] = grip_at_impact - kChestBehindHands * to_ball + kChestAboveHands * up;
  j[GolferBody::kPelvis] = j[GolferBody::kChest] - kPelvisBehindChest * to_ball - kPelvisBelowChest * up;
  j[GolferBody::kHead] = j[GolferBody::kChest] + kHeadAboveChest * up + 0.08 * to_ball;
  j[GolferBody::kHands] = grip;
  // The shoulders turn about the spine with the hands: their line stays square to the hands'
  // direction from the chest, seen from above.
  Vec3 h = grip - j[GolferBody::kChest];
  h.y() = 0.0;
  if (h.norm() < 1e-6) h = to_ball;
  h.normalize();
  // Turned from the ball's side toward the target: at address (hands toward the ball) it is
  // the target's direction.
  const Vec3 lead_dir(h.z(), 0.0, -h.x());
  j[GolferBody::kLeadShoulder] = j[GolferBody::kChest] + kHalfShoulders * lead_dir;
  j[GolferBody::kTrailShoulder] = j[GolferBody::kChest] - kHalfShoulders * lead_dir;
  // The lead arm straight; the trail elbow folds down and in.
  j[GolferBody::kLeadElbow] = 0.5 * (j[GolferBody::kLeadShoulder] + grip);
  j[GolferBody::kTrailElbow] = 0.5 * (j[GolferBody::kTrailShoulder] + grip) - 0.08 * up - 0.05 * to_ball;
  j[GolferBody::kLeadHip] = j[GolferBody::kPelvis] + kHalfHips * a;
  j[GolferBody::kTrailHip] = j[GolferBody::kPelvis] - kHalfHips * a;
  const Vec3 feet = Vec3(j[GolferBody::kPelvis].x(), ground_y, j[GolferBody::kPelvis].z()) + 0.1 * to_ball;
  j[GolferBody::kLeadFoot] = feet + kHalfStance * a;
  j[GolferBody::kTrailFoot] = feet - kHalfStance * a;
  // Knees flexed toward the ball.
  j[GolferBody::kLeadKnee] = 0.5 * (j[GolferBody::kLeadHip] + j[GolferBody::kLeadFoot]) + 0.10 * to_ball;
  j[GolferBody::kTrailKnee] = 0.5 * (j[GolferBody::kTrailHip] + j[GolferBody::kTrailFoot]) + 0.10 * to_ball;
  return b;
}

void append_limb(MeshData& out, const Vec3& a, const Vec3& b, double width, const Eigen::Vector3f& color) {
  const Vec3 d = b - a;
  const double len = d.norm();
  if (len < 1e-6) return;
  const Vec3 u = d / len;
  const Vec3 side = (std::abs(u.y()) < 0.9 ? u.cross(Vec3::UnitY()) : u.cross(Vec3::UnitX())).normalized();
  const Vec3 other = u.cross(side);
  const double r = 0.5 * width;
  const Vec3 corner[4] = {r * (side + other), r * (other - side), r * (-side - other), r * (side - other)};
  // Four sides and two caps, each face its own vertices so it lights flat.
  const auto face = [&](const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    const Vec3 n = (p1 - p0).cross(p3 - p0).normalized();
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (const Vec3* p : {&p0, &p1, &p2, &p3}) {
      Vertex v;
      v.position = p->cast<float>();
      v.normal = n.cast<float>();
      v.color = color;
      out.vertices.push_back(v);
    }
    out.indices.insert(out.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  };
  for (int k = 0; k < 4; ++k) {
    const Vec3& c0 = corner[k];
    const Vec3& c1 = corner[(k + 1) % 4];
    face(a + c0, a + c1, b + c1, b + c0);
  }
  face(a + corner[3], a + corner[2], a + corner[1], a + corner[0]);
  face(b + corner[0], b + corner[1], b + corner[2], b + corner[3]);
}

void append_club_shaft(MeshData& out, const Vec3& grip, const Vec3& shaft, double length) {
  // A steel shaft of ~13 mm under a ~10 in rubber grip (drawn a little thick to read on screen).
  const Eigen::Vector3f steel(0.62f, 0.64f, 0.68f), rubber(0.08f, 0.08f, 0.08f);
  append_limb(out, grip - 0.9 * length * shaft, grip - 0.25 * shaft, 0.014, steel);
  append_limb(out, grip - 0.27 * shaft, grip + 0.02 * shaft, 0.022, rubber);
}

void append_golfer(MeshData& out, const GolferBody& b) {
  using G = GolferBody;
  const auto& j = b.joint;
  const auto limb = [&](G::Joint p, G::Joint q, double w, const Eigen::Vector3f& c) { append_limb(out, j[p], j[q], w, c); };
  limb(G::kPelvis, G::kChest, 0.26, kShirt);
  limb(G::kLeadShoulder, G::kTrailShoulder, 0.12, kShirt);
  limb(G::kLeadHip, G::kTrailHip, 0.16, kTrousers);
  limb(G::kLeadShoulder, G::kLeadElbow, 0.08, kShirt);
  limb(G::kTrailShoulder, G::kTrailElbow, 0.08, kShirt);
  limb(G::kLeadElbow, G::kHands, 0.07, kSkin);
  limb(G::kTrailElbow, G::kHands, 0.07, kSkin);
  limb(G::kLeadHip, G::kLeadKnee, 0.12, kTrousers);
  limb(G::kTrailHip, G::kTrailKnee, 0.12, kTrousers);
  limb(G::kLeadKnee, G::kLeadFoot, 0.10, kTrousers);
  limb(G::kTrailKnee, G::kTrailFoot, 0.10, kTrousers);
  // The neck and head: a box a head high above the chest.
  append_limb(out, j[G::kChest], j[G::kHead] - Vec3(0.0, 0.1, 0.0), 0.09, kSkin);
  append_limb(out, j[G::kHead] - Vec3(0.0, 0.11, 0.0), j[G::kHead] + Vec3(0.0, 0.11, 0.0), 0.19, kSkin);
}

}  // namespace sweetspot
