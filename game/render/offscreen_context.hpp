// A headless OpenGL 3.3 core context through EGL (DESIGN §7): the EGL device platform when
// a hardware GPU is present, Mesa's surfaceless platform otherwise (llvmpipe on CPU-only
// machines such as CI). The context has no default framebuffer; the Renderer draws into
// its own FBO.
#pragma once

#include <string>
#include <string_view>

namespace sweetspot {

enum class EglPlatform {
  Auto,         ///< device (hardware GPU) if one is found, else surfaceless
  Device,       ///< EGL_EXT_platform_device on a hardware device only
  Surfaceless,  ///< EGL_MESA_platform_surfaceless (software or GPU, whatever Mesa picks)
};

/// Parses "auto", "device", "surfaceless"; throws InputError naming the allowed values.
EglPlatform parse_egl_platform(std::string_view name);
const char* to_string(EglPlatform p);

/// Owns an EGL display + GL 3.3 core context and makes it current on the constructing
/// thread. Not copyable; one per thread. The environment variable SWEETSPOT_EGL_PLATFORM
/// (auto|device|surfaceless) overrides the requested platform (for tests and for forcing
/// llvmpipe on a GPU machine).
class OffscreenContext {
 public:
  /// Throws RenderUnavailable with the failing EGL step and error code when no context can
  /// be made (no EGL vendor, no platform, GL below 3.3); never crashes.
  explicit OffscreenContext(EglPlatform platform = EglPlatform::Auto);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  /// e.g. "EGL surfaceless, llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
  const std::string& description() const { return description_; }
  EglPlatform platform() const { return platform_; }
  /// Makes this context current on the calling thread again.
  void make_current() const;

 private:
  void release();
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  EglPlatform platform_ = EglPlatform::Auto;
  std::string description_;
};

}  // namespace sweetspot
