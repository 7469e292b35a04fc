#include "game/render/shader_program.hpp"

#include <fstream>
#include <sstream>
#include <vector>

#include "game/render/gl.hpp"
#include "game/render/render_error.hpp"

namespace sweetspot {
namespace {

std::string read_source(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RenderError("shader file " + path.string() + " cannot be read (set SWEETSPOT_SHADERS to the shaders/ folder)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string info_log(GLuint object, bool is_program) {
  GLint len = 0;
  if (is_program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &len);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &len);
  std::vector<char> log(static_cast<std::size_t>(len > 1 ? len : 1), '\0');
  if (is_program) glGetProgramInfoLog(object, len, nullptr, log.data());
  else glGetShaderInfoLog(object, len, nullptr, log.data());
  return std::string(log.data());
}

}  // namespace

unsigned compile_shader_source(unsigned stage, const std::string& source, const std::string& path) {
  GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(shader, false);
    glDeleteShader(shader);
    throw RenderError("shader " + path + " failed to compile:\n" + log);
  }
  return shader;
}

ShaderProgram::ShaderProgram(const std::filesystem::path& dir, const std::string& name) {
  const auto vert_path = dir / (name + ".vert");
  const auto frag_path = dir / (name + ".frag");
  const std::string vert_src = read_source(vert_path);
  const std::string frag_src = read_source(frag_path);
  const GLuint vs = compile_shader_source(GL_VERTEX_SHADER, vert_src, vert_path.string());
  GLuint fs = 0;
  try {
    fs = compile_shader_source(GL_FRAGMENT_SHADER, frag_src, frag_path.string());
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  // Attribute slots are fixed so every program shares the mesh vertex layout.
  glBindAttribLocation(program_, 0, "a_position");
  glBindAttribLocation(program_, 1, "a_normal");
  glBindAttribLocation(program_, 2, "a_color");
  glBindAttribLocation(program_, 3, "a_pattern");
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(program_, true);
    glDeleteProgram(program_);
    program_ = 0;
    throw RenderError("shader program " + (dir / name).string() + ".{vert,frag} failed to link:\n" + log);
  }
}

ShaderProgram::~ShaderProgram() {
  if (program_ != 0) glDeleteProgram(program_);
}

void ShaderProgram::use() const { glUseProgram(program_); }

void ShaderProgram::set(const char* name, const Eigen::Matrix4f& m) const {
  glUniformMatrix4fv(glGetUniformLocation(program_, name), 1, GL_FALSE, m.data());
}
void ShaderProgram::set(const char* name, const Eigen::Matrix3f& m) const {
  glUniformMatrix3fv(glGetUniformLocation(program_, name), 1, GL_FALSE, m.data());
}
void ShaderProgram::set(const char* name, const Eigen::Vector3f& v) const {
  glUniform3f(glGetUniformLocation(program_, name), v.x(), v.y(), v.z());
}
void ShaderProgram::set(const char* name, float v) const { glUniform1f(glGetUniformLocation(program_, name), v); }
void ShaderProgram::set(const char* name, int v) const { glUniform1i(glGetUniformLocation(program_, name), v); }

}  // namespace sweetspot
