// A MeshData uploaded to the GPU: one VAO with the Vertex layout on attribute slots 0..3.
// Needs a current GL context for its whole life.
#pragma once

#include "game/render/mesh_data.hpp"

namespace sweetspot {

class GpuMesh {
 public:
  GpuMesh();
  explicit GpuMesh(const MeshData& data);
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  /// Replaces the contents (used each frame for the overlay geometry).
  void upload(const MeshData& data);
  void draw() const;
  std::size_t index_count() const { return count_; }

 private:
  unsigned vao_ = 0, vbo_ = 0, ebo_ = 0;
  std::size_t count_ = 0;
};

}  // namespace sweetspot
