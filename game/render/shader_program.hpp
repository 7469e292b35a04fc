// A GLSL program built from shaders/<name>.vert + shaders/<name>.frag at run time, so a
// shader edit needs no rebuild. Needs a current GL 3.3 context.
#pragma once

#include <filesystem>
#include <string>

#include <Eigen/Core>

namespace sweetspot {

class ShaderProgram {
 public:
  /// Reads <dir>/<name>.vert and <dir>/<name>.frag, compiles and links them. Throws
  /// RenderError naming the file and quoting the compiler or linker log.
  ShaderProgram(const std::filesystem::path& dir, const std::string& name);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  unsigned id() const { return program_; }
  /// Setters on the program in use; a uniform the compiler optimised away is ignored.
  void set(const char* name, const Eigen::Matrix4f& m) const;
  void set(const char* name, const Eigen::Matrix3f& m) const;
  void set(const char* name, const Eigen::Vector3f& v) const;
  void set(const char* name, float v) const;
  void set(const char* name, int v) const;  ///< ints and sampler texture units

 private:
  unsigned program_ = 0;
};

/// Compiles one shader stage from `source`; `path` only names it in errors. Returns the GL
/// shader id; throws RenderError with "<path>: <compiler log>".
unsigned compile_shader_source(unsigned stage, const std::string& source, const std::string& path);

}  // namespace sweetspot
