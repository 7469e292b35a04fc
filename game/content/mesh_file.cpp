#include "game/content/mesh_file.hpp"

#include <cmath>

#include <cstring>
#include <filesystem>
#include <vector>

#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "game/content/toml_file.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

/// A whole file held in memory.
class BufferStream final : public Assimp::IOStream {
 public:
  explicit BufferStream(std::string bytes) : bytes_(std::move(bytes)) {}
  size_t Read(void* out, size_t size, size_t count) override {
    if (size == 0) return 0;
    const size_t n = std::min(count, (bytes_.size() - pos_) / size);
    std::memcpy(out, bytes_.data() + pos_, n * size);
    pos_ += n * size;
    return n;
  }
  size_t Write(const void*, size_t, size_t) override { return 0; }
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    size_t to = 0;
    switch (origin) {
      case aiOrigin_SET: to = offset; break;
      case aiOrigin_CUR: to = pos_ + offset; break;
      case aiOrigin_END: to = bytes_.size() - std::min(offset, bytes_.size()); break;
      default: return aiReturn_FAILURE;
    }
    if (to > bytes_.size()) return aiReturn_FAILURE;
    pos_ = to;
    return aiReturn_SUCCESS;
  }
  size_t Tell() const override { return pos_; }
  size_t FileSize() const override { return bytes_.size(); }
  void Flush() override {}

 private:
  std::string bytes_;
  size_t pos_ = 0;
};

/// Opens only regular files under the size limit, for reading; remembers why it refused.
class BoundedFileSystem final : public Assimp::IOSystem {
 public:
  explicit BoundedFileSystem(std::uintmax_t max_bytes) : max_bytes_(max_bytes) {}
  bool Exists(const char* file) const override {
    std::error_code ec;
    return std::filesystem::is_regular_file(file, ec);
  }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (mode == nullptr || mode[0] != 'r') {
      refusal_ = std::string(file) + ": not opened for writing";
      return nullptr;
    }
    try {
      return new BufferStream(read_data_file(file, "mesh or material library", max_bytes_));
    } catch (const InputError& e) {
      if (refusal_.empty()) refusal_ = e.what();
      return nullptr;
    }
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }
  const std::string& refusal() const { return refusal_; }

 private:
  std::uintmax_t max_bytes_;
  std::string refusal_;
};

}  // namespace

ImportedMesh::ImportedMesh() = default;
ImportedMesh::ImportedMesh(ImportedMesh&&) noexcept = default;
ImportedMesh& ImportedMesh::operator=(ImportedMesh&&) noexcept = default;
ImportedMesh::~ImportedMesh() = default;

ImportedMesh import_mesh_file(const std::filesystem::path& path, const char* what, std::uintmax_t max_bytes,
                              unsigned flags) {
  // The OBJ itself is checked before assimp sees it, for a message naming its role.
  check_data_file(path, what, max_bytes);
  ImportedMesh out;
  out.importer = std::make_unique<Assimp::Importer>();
  auto* io = new BoundedFileSystem(max_bytes);  // owned by the importer
  out.importer->SetIOHandler(io);
  if (flags == 0) flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;
  // Read first without post-processing and check every vertex as the file gives it:
  // triangulating a polygon with a NaN corner drops the corner and its triangles silently
  // (an issue-20 finding: a hole in the ground, the ball fell through it).
  out.scene = out.importer->ReadFile(path.string(), 0);
  if (!io->refusal().empty()) throw InputError(io->refusal() + " (named by " + path.string() + ")");
  if (out.scene != nullptr) {
    for (unsigned mi = 0; mi < out.scene->mNumMeshes; ++mi) {
      const aiMesh* m = out.scene->mMeshes[mi];
      for (unsigned v = 0; v < m->mNumVertices; ++v) {
        const aiVector3D& p = m->mVertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw InputError(path.string() + ": " + what + " '" + m->mName.C_Str() + "' has a vertex that is not a " +
                           "finite number (NaN or infinity); fix the file");
      }
    }
    out.scene = out.importer->ApplyPostProcessing(flags);
  }
  // A material library that could not be opened is reported even when assimp carried on
  // without it (the surfaces would be wrong).
  if (!io->refusal().empty()) throw InputError(io->refusal() + " (named by " + path.string() + ")");
  if (out.scene == nullptr || out.scene->mRootNode == nullptr)
    throw InputError(path.string() + ": cannot read the " + what + ": " + out.importer->GetErrorString());
  return out;
}

}  // namespace sweetspot
