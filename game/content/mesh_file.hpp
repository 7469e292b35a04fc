// Mesh files through assimp, safely: every file assimp opens (the OBJ and each material
// library it names) must be a regular file under the mesh size limit, read whole into
// memory first, so a FIFO or /dev/zero named as `mtllib` is refused instead of blocking
// the importer. The world loader and the renderer's mesh import both use it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

struct aiScene;
namespace Assimp {
class Importer;
}

namespace sweetspot {

/// An imported scene and the importer that owns it.
struct ImportedMesh {
  std::unique_ptr<Assimp::Importer> importer;
  const aiScene* scene = nullptr;
  ImportedMesh();
  ImportedMesh(ImportedMesh&&) noexcept;
  ImportedMesh& operator=(ImportedMesh&&) noexcept;
  ~ImportedMesh();
};

/// Imports `path` with assimp post-processing `flags` (default: triangulated, identical
/// vertices joined). Throws InputError naming the file (or the material library) that is
/// missing, not a regular file, over `max_bytes`, or unreadable, and assimp's message for a
/// file it cannot parse. `what` names the role.
ImportedMesh import_mesh_file(const std::filesystem::path& path, const char* what, std::uintmax_t max_bytes,
                              unsigned flags = 0);

}  // namespace sweetspot
