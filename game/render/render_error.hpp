// Errors of the rendering layer. Both carry a message for the user that names what failed
// (the EGL call, the shader file and its compiler log, the mesh file).
#pragma once

#include <stdexcept>
#include <string>

namespace sweetspot {

/// No usable OpenGL context: EGL missing or refusing every platform, or GL below 3.3.
/// The CLI maps it to exit code 3 ("cannot render here"), distinct from bad input (2).
class RenderUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A rendering resource failed: shader file missing or not compiling/linking, mesh file
/// unreadable, framebuffer incomplete. The message names the file and the GL/assimp log.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sweetspot
