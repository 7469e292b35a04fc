#include "game/content/mesh_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "game/content/gzip_file.hpp"
#include "game/content/obj_scan.hpp"
#include "game/content/toml_file.hpp"
#include "game/util/atomic_file.hpp"
#include "game/util/isolated_call.hpp"
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

/// Opens only regular files under the size limit in the mesh's own folder tree (a
/// material library named "../../etc/passwd" is refused), for reading; remembers why it
/// refused and what it opened.
class BoundedFileSystem final : public Assimp::IOSystem {
 public:
  BoundedFileSystem(std::uintmax_t max_bytes, const std::filesystem::path& mesh)
      : max_bytes_(max_bytes), mesh_(mesh), folder_(folder_of(mesh)) {}
  /// Serves `bytes` as the file `name` (the inflated text of a gzip mesh, under its name
  /// without ".gz", so that the importer picks its reader by that name).
  void serve(std::filesystem::path name, std::string bytes) {
    served_name_ = std::move(name);
    served_ = std::move(bytes);
  }
  bool Exists(const char* file) const override {
    if (!served_name_.empty() && std::filesystem::path(file) == served_name_) return true;
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
      const std::filesystem::path p(file);
      if (!served_name_.empty() && p == served_name_) {
        files_.push_back(mesh_.string());
        return new BufferStream(served_);
      }
      std::error_code ec;
      const bool is_mesh = std::filesystem::equivalent(p, mesh_, ec) && !ec;
      if (!is_mesh) {
        const std::filesystem::path real = std::filesystem::weakly_canonical(p, ec);
        const auto [end, unused] = std::mismatch(folder_.begin(), folder_.end(), real.begin(), real.end());
        (void)unused;
        if (ec || end != folder_.end())
          throw InputError(std::string(file) + ": a material library outside the mesh's folder " + folder_.string() +
                           " (libraries must lie beside the mesh or below it)");
      }
      BufferStream* stream = new BufferStream(read_data_file(file, "mesh or material library", max_bytes_));
      files_.push_back(file);
      return stream;
    } catch (const InputError& e) {
      if (refusal_.empty()) refusal_ = e.what();
      return nullptr;
    }
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }
  const std::string& refusal() const { return refusal_; }
  const std::vector<std::string>& files() const { return files_; }

 private:
  static std::filesystem::path folder_of(const std::filesystem::path& mesh) {
    std::error_code ec;
    const std::filesystem::path real = std::filesystem::weakly_canonical(mesh, ec);
    return (ec ? std::filesystem::absolute(mesh, ec) : real).parent_path();
  }
  std::uintmax_t max_bytes_;
  std::filesystem::path mesh_, folder_;
  std::filesystem::path served_name_;
  std::string served_;
  std::string refusal_;
  std::vector<std::string> files_;
};


// ---- the answer's bytes: the child writes them, the parent reads them back ---------------
void put_u32(std::string* out, std::uint32_t v) { out->append(reinterpret_cast<const char*>(&v), sizeof v); }
void put_string(std::string* out, const std::string& s) {
  put_u32(out, static_cast<std::uint32_t>(s.size()));
  out->append(s);
}
template <class T>
void put_array(std::string* out, const std::vector<T>& v) {
  put_u32(out, static_cast<std::uint32_t>(v.size()));
  if (!v.empty()) out->append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

std::string encode(const MeshFile& m) {
  std::string out;
  put_u32(&out, m.incomplete ? 1 : 0);
  put_u32(&out, static_cast<std::uint32_t>(m.parts.size()));
  for (const MeshPart& p : m.parts) {
    put_string(&out, p.name);
    put_string(&out, p.material);
    put_u32(&out, p.has_diffuse ? 1 : 0);
    out.append(reinterpret_cast<const char*>(p.diffuse.data()), sizeof p.diffuse);
    put_array(&out, p.positions);
    put_array(&out, p.normals);
    put_array(&out, p.triangles);
  }
  put_u32(&out, static_cast<std::uint32_t>(m.files_read.size()));
  for (const std::string& f : m.files_read) put_string(&out, f);
  return out;
}

/// Reads the child's answer back, every length checked against what is left.
class Decoder {
 public:
  explicit Decoder(const std::string& bytes) : bytes_(bytes) {}
  MeshFile mesh_file() {
    MeshFile m;
    m.incomplete = u32() != 0;
    const std::uint32_t parts = u32();
    for (std::uint32_t k = 0; k < parts; ++k) {
      MeshPart p;
      p.name = string();
      p.material = string();
      p.has_diffuse = u32() != 0;
      take(p.diffuse.data(), sizeof p.diffuse);
      array(&p.positions);
      array(&p.normals);
      array(&p.triangles);
      m.parts.push_back(std::move(p));
    }
    const std::uint32_t files = u32();
    for (std::uint32_t k = 0; k < files; ++k) m.files_read.push_back(string());
    if (pos_ != bytes_.size()) fail();
    return m;
  }

 private:
  [[noreturn]] static void fail() { throw std::runtime_error("the mesh importer's answer is malformed"); }
  void take(void* out, std::size_t n) {
    if (n == 0) return;  // an empty vector's data() may be null
    if (n > bytes_.size() - pos_) fail();
    std::memcpy(out, bytes_.data() + pos_, n);
    pos_ += n;
  }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    take(&v, sizeof v);
    return v;
  }
  std::string string() {
    const std::uint32_t n = u32();
    if (n > bytes_.size() - pos_) fail();
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  template <class T>
  void array(std::vector<T>* v) {
    const std::uint32_t n = u32();
    if (n > (bytes_.size() - pos_) / sizeof(T)) fail();
    v->resize(n);
    take(v->data(), n * sizeof(T));
  }
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

// ---- in the child: assimp's scene to plain data -----------------------------------------
void add_node(const aiScene* scene, const aiNode* node, const aiMatrix4x4& parent, MeshFile* out) {
  const aiMatrix4x4 xf = parent * node->mTransformation;
  const aiMatrix3x3 turn(xf);
  for (unsigned k = 0; k < node->mNumMeshes; ++k) {
    if (node->mMeshes[k] >= scene->mNumMeshes) continue;
    const aiMesh* am = scene->mMeshes[node->mMeshes[k]];
    MeshPart p;
    p.name = am->mName.C_Str();
    if (am->mMaterialIndex < scene->mNumMaterials) {
      const aiMaterial* mat = scene->mMaterials[am->mMaterialIndex];
      aiString name;
      if (mat->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) p.material = name.C_Str();
      aiColor3D kd;
      if (mat->Get(AI_MATKEY_COLOR_DIFFUSE, kd) == AI_SUCCESS) {
        p.has_diffuse = true;
        p.diffuse = {kd.r, kd.g, kd.b};
      }
    }
    p.positions.reserve(am->mNumVertices);
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D q = xf * am->mVertices[v];
      p.positions.push_back({q.x, q.y, q.z});
    }
    if (am->HasNormals()) {
      p.normals.reserve(am->mNumVertices);
      for (unsigned v = 0; v < am->mNumVertices; ++v) {
        const aiVector3D n = turn * am->mNormals[v];
        p.normals.push_back({n.x, n.y, n.z});
      }
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices == 3) p.triangles.push_back({face.mIndices[0], face.mIndices[1], face.mIndices[2]});
    }
    out->parts.push_back(std::move(p));
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) add_node(scene, node->mChildren[c], xf, out);
}

/// The import itself, run in the child.
std::string import_in_child(const std::filesystem::path& path, const char* what, std::uintmax_t max_bytes,
                            unsigned flags) {
  Assimp::Importer importer;
  auto* io = new BoundedFileSystem(max_bytes, path);  // owned by the importer
  importer.SetIOHandler(io);
  std::filesystem::path read_as = path;
  if (is_gzip_path(path)) {
    std::string text = read_gzip_file(path, what, max_bytes);
    check_obj_text(text, path, what);
    read_as = without_gzip_suffix(path);
    io->serve(read_as, std::move(text));
  } else {
    check_obj_text(path, what);
  }
  if (flags == 0) flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;
  // Read first without post-processing and check every vertex as the file gives it:
  // triangulating a polygon with a NaN corner drops the corner and its triangles silently
  // (a hole in the ground: the ball falls through it).
  const aiScene* scene = importer.ReadFile(read_as.string(), 0);
  if (!io->refusal().empty()) throw InputError(io->refusal() + " (named by " + path.string() + ")");
  if (scene != nullptr) {
    std::uint64_t triangles = 0;
    for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
      const aiMesh* m = scene->mMeshes[mi];
      for (unsigned f = 0; f < m->mNumFaces; ++f) {
        const unsigned corners = m->mFaces[f].mNumIndices;
        if (corners > kMaxFaceCorners)
          throw InputError(path.string() + ": " + what + " '" + m->mName.C_Str() + "' face " + std::to_string(f) +
                           " has " + std::to_string(corners) + " corners (allowed at most " +
                           std::to_string(kMaxFaceCorners) + "); split it into smaller polygons");
        triangles += corners >= 3 ? corners - 2 : 0;
      }
      if (triangles > kMaxMeshTriangles)
        throw InputError(path.string() + ": " + what + " has over " + std::to_string(kMaxMeshTriangles) +
                         " triangles (the limit); decimate it");
      for (unsigned v = 0; v < m->mNumVertices; ++v) {
        const aiVector3D& p = m->mVertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw InputError(path.string() + ": " + what + " '" + m->mName.C_Str() + "' has a vertex that is not a " +
                           "finite number (NaN, infinity, or past the mesh reader's 32-bit float range, 3.4e38); fix the file");
      }
    }
    scene = importer.ApplyPostProcessing(flags);
  }
  // A material library that could not be opened is reported even when assimp carried on
  // without it (the surfaces would be wrong).
  if (!io->refusal().empty()) throw InputError(io->refusal() + " (named by " + path.string() + ")");
  if (scene == nullptr || scene->mRootNode == nullptr)
    throw InputError(path.string() + ": cannot read the " + what + ": " + importer.GetErrorString());
  MeshFile out;
  out.incomplete = (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0;
  add_node(scene, scene->mRootNode, aiMatrix4x4(), &out);
  out.files_read = io->files();
  return encode(out);
}

}  // namespace

MeshFile import_mesh_file(const std::filesystem::path& path, const char* what, std::uintmax_t max_bytes,
                          unsigned flags) {
  // The OBJ itself is checked before assimp sees it, for a message naming its role.
  check_data_file(path, what, max_bytes);
  std::string answer;
  try {
    answer = run_isolated([&] { return import_in_child(path, what, max_bytes, flags); });
  } catch (const IsolationFailure& e) {
    if (e.thrown_by_work()) throw InputError(e.what());
    throw InputError(path.string() + ": the " + what + " importer (assimp) " + e.what() +
                     " reading this file; it is malformed or hostile, so it was not loaded");
  }
  MeshFile mesh;
  try {
    mesh = Decoder(answer).mesh_file();
  } catch (const std::runtime_error& e) {
    throw InputError(path.string() + ": " + e.what());
  }
  for (const std::string& f : mesh.files_read) note_input_file(f);  // no output may replace them
  return mesh;
}

}  // namespace sweetspot
