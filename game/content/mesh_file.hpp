// Mesh files through assimp, safely:
// - every file assimp opens (the OBJ and each material library it names) must be a regular
//   file under the mesh size limit, read whole into memory first, so a FIFO or /dev/zero
//   named as `mtllib` is refused instead of blocking the importer;
// - assimp runs in a child process (game/util/isolated_call): Debian 12's assimp 5.2.5 has
//   memory-safety bugs a hostile OBJ/MTL reaches (fuzz_world found a wild write in its
//   material-library parser), so a crash or hang there becomes a clear InputError naming
//   the file instead of taking the game down;
// - what comes back is plain data (MeshFile), checked for finite vertices before any
//   post-processing could hide a bad one.
// The world loader and the renderer's mesh import both use it.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sweetspot {

/// One mesh of an imported file, with its node transform applied.
struct MeshPart {
  std::string name;      ///< the mesh's name in the file (may be empty)
  std::string material;  ///< its material's name (OBJ `usemtl`), "" when it has none
  bool has_diffuse = false;
  std::array<float, 3> diffuse{};  ///< the material's diffuse colour (MTL `Kd`), 0..1 each, when has_diffuse
  /// Vertices in the file's frame and units (metres for our assets).
  std::vector<std::array<float, 3>> positions;
  /// Unit normals, one per position, or empty when the file has none and none were made.
  std::vector<std::array<float, 3>> normals;
  /// Triangles as indices into positions, as the importer gives them: callers check the
  /// range (a truncated file can point past the end). Points and lines are left out.
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Every mesh of a file, in node order (a mesh two nodes share appears twice).
struct MeshFile {
  std::vector<MeshPart> parts;
  bool incomplete = false;  ///< assimp flagged the scene incomplete
  /// Every file the importer opened (the mesh and its material libraries), for the
  /// parent's note_input_file: the import runs in a child process.
  std::vector<std::string> files_read;
};

/// A polygon's corners, at most: triangulating an n-gon costs assimp O(n^2) to O(n^3) (a
/// hostile OBJ with one 100 000-corner face keeps the importer busy past its 120 s limit).
/// Modelling tools write n-gons of a few dozen corners; 256 triangulates in milliseconds.
inline constexpr unsigned kMaxFaceCorners = 256;
/// OBJ objects (`o` lines) in one file, at most: assimp's OBJ reader looks each new object
/// up among all before it, so reading n objects costs O(n^2) (measured with one triangle an
/// object: 10 000 take 1.0 s, 20 000 2.5 s, 40 000 10.7 s). Materials come from `usemtl`
/// and groups (`g`, read in linear time: 80 000 in 2.9 s) are not limited.
inline constexpr std::uint64_t kMaxObjObjects = 10'000;
/// Triangles in one file, at most: each costs the world ~0.4 kB (Bullet's tree, adjacency,
/// grid), so 1 000 000 is ~0.4 GB, 50x our largest shipped world (golf_hole, 21 516).
inline constexpr std::uint64_t kMaxMeshTriangles = 1'000'000;

/// Imports `path` with assimp post-processing `flags` (0: triangulated, identical vertices
/// joined). Throws InputError naming the file (or the material library) that is missing,
/// not a regular file, over `max_bytes` or unreadable; assimp's message for a file it
/// cannot parse; a face over kMaxFaceCorners or a file over kMaxMeshTriangles (checked
/// before triangulating); and, naming the file, an importer that crashed or ran past its limits on
/// it. `what` names the role ("world mesh", "mesh").
MeshFile import_mesh_file(const std::filesystem::path& path, const char* what, std::uintmax_t max_bytes,
                          unsigned flags = 0);

}  // namespace sweetspot
