// What the Renderer draws: plain data built each frame by the shot scene builder (or the
// game). The renderer reads it; it owns no physics state (DESIGN §7).
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "game/render/gpu_mesh.hpp"
#include "game/render/mesh_data.hpp"

namespace sweetspot {

struct MeshInstance {
  MeshInstance() = default;
  MeshInstance(const GpuMesh* m, const Eigen::Matrix4f& to_world, bool is_terrain = false, int decal_layer = 0,
               std::optional<Eigen::AlignedBox3f> box = std::nullopt)
      : mesh(m), model(to_world), terrain(is_terrain), decal(decal_layer), bounds(box) {}
  const GpuMesh* mesh = nullptr;                      ///< not owned
  Eigen::Matrix4f model = Eigen::Matrix4f::Identity();  ///< mesh frame -> world, m
  bool terrain = false;  ///< drawn with a depth offset so ground markers sit on it
  /// 1, 2, ...: flat paint lying on the terrain (a ballpark's skin, bases), each layer drawn
  /// over the terrain and the layers below it by a depth offset; 0 = an ordinary mesh.
  int decal = 0;
  /// The mesh's extent in its own frame, when known: a pass leaves the mesh out where the
  /// box is wholly outside its view (a course's tiles behind the camera).
  std::optional<Eigen::AlignedBox3f> bounds;
};

struct Scene {
  Eigen::Vector3f sky_zenith{0.20f, 0.42f, 0.78f};
  Eigen::Vector3f sky_horizon{0.74f, 0.84f, 0.93f};
  Eigen::Vector3f sun_direction = Eigen::Vector3f(-0.35f, 0.85f, 0.40f).normalized();  ///< toward the sun
  float haze_range = 2500.0f;  ///< m
  /// The sun's shadow map covers a square of 2 shadow_radius m (seen from the sun) about
  /// shadow_centre; 0 = no shadows. Typical: the framed shot (~150 m), 30 m around the ball
  /// when following it.
  Eigen::Vector3f shadow_centre = Eigen::Vector3f::Zero();
  float shadow_radius = 0.0f;
  std::vector<MeshInstance> meshes;  ///< lit
  MeshData figures;         ///< lit, world frame, rebuilt each frame: the people
  MeshData ground_overlay;  ///< unlit, depth-tested: rings and stripes lying on the ground
  MeshData top_overlay;     ///< unlit, drawn over everything: trail, pins, labels
  /// px (x0, y0, x1, y1), y down: where the labels (and the trail's key) were placed, so
  /// words the window draws over the image can keep clear of them.
  std::vector<Eigen::Vector4f> label_boxes;
};

}  // namespace sweetspot
