// The course or ballpark as Bullet sees it (DESIGN §5): a btCollisionWorld of triangle
// meshes, one btBvhTriangleMeshShape per surface material (material id in the collision
// object's user index). Bullet only answers queries: its BVH finds the triangles a sphere
// sweep may touch (the exact first contact is ours, physics/sphere_sweep), and it casts
// rays; our integrator moves the ball. Contacts report the
// triangle's face normal, never Bullet's interpolated or edge normal, so a ball rolling
// across the internal edges of a flat mesh does not hop.
//
// Physics takes plain vertex/index arrays; loading files (assimp, TOML) is game/assets.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "physics/ground.hpp"
#include "physics/math.hpp"

namespace sweetspot {

/// Triangles of one material, world frame (m).
struct WorldMesh {
  int material = 0;                     ///< index into WorldDescription::materials
  std::vector<Vec3> vertices;           ///< m
  std::vector<std::uint32_t> indices;   ///< 3 per triangle, counter-clockwise seen from the side the normal points to
};

/// Everything a World is built from: plain data, loaded by game/assets or built in tests.
struct WorldDescription {
  std::string name;                       ///< "golf_hole", "ballpark"
  std::vector<SurfaceMaterial> materials;
  std::vector<WorldMesh> meshes;
  /// m; the ground reference (the tee, home plate): wind heights and field level count from it.
  Vec3 origin = Vec3::Zero();
  Vec3 bounds_min = Vec3::Constant(-1e4); ///< m; leaving the box ends the shot (EndReason::LeftWorld)
  Vec3 bounds_max = Vec3::Constant(1e4);  ///< m
  std::vector<std::string> notes;         ///< repairs made while loading or building (dropped triangles)
};

/// Empty when valid, otherwise a message naming the world, mesh and field.
std::string validate_world(const WorldDescription& d);

/// How a sphere sweep finds its first contact. Both report the same face-normal contacts.
enum class SweepMethod {
  /// Bullet's BVH (processAllTriangles over the sweep's box) picks candidate triangles and
  /// physics/sphere_sweep gives the exact first contact in closed form. The default: about
  /// twice as fast per whole shot (README "Performance").
  BvhExact,
  /// DESIGN §5 as written: btCollisionWorld::convexSweepTest of a btSphereShape (GJK
  /// conservative advancement per triangle). Kept as the reference the default is tested
  /// and benchmarked against.
  BulletConvexSweep,
};

/// A collision world built once from a description. Not copyable. With the default
/// SweepMethod::BvhExact every query only reads the world, so one World may serve many
/// threads at once; BulletConvexSweep queries go through the btCollisionWorld's broadphase
/// and a shared sphere shape, so that mode needs one World per thread.
class World final : public Terrain {
 public:
  /// Throws InputError on a non-finite vertex, an index out of range or a bad material;
  /// drops zero-area triangles (noted in description().notes).
  explicit World(WorldDescription description, SweepMethod method = SweepMethod::BvhExact);
  ~World() override;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  const WorldDescription& description() const;
  /// Triangles handed to Bullet (decorations and dropped triangles excluded).
  int collision_triangles() const;

  bool sweep(const Vec3& from, const Vec3& to, double radius, SurfaceContact* hit,
             const Vec3* follow) const override;
  bool support(const Vec3& centre, double radius, double reach, SurfaceContact* hit) const override;
  bool may_touch(const Vec3& from, const Vec3& to, double radius) const override;
  double top_under(const Vec3& from, const Vec3& to, double radius) const override;
  bool may_touch_steep(const Vec3& from, const Vec3& to, double radius) const override;
  const SurfaceMaterial& material(int index) const override;
  /// In the declared bounds and not below the floor: 1 m under the lowest collidable vertex
  /// (or the origin, if lower), where nothing can be touched again.
  bool inside(const Vec3& centre) const override;
  double reference_height() const override;
  /// The vertex normals interpolated over c's triangle at c.point (Phong's rule), each
  /// vertex normal the angle-weighted mean of the faces at that vertex within 10° of c's
  /// face (sharper bends, banks, lips and walls, keep their edge).
  Vec3 bounce_normal(const SurfaceContact& c) const override;
  void refine_contact(const Vec3& centre, SurfaceContact* c) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sweetspot
