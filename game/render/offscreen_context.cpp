#include "game/render/offscreen_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "game/render/gl.hpp"
#include "game/render/render_error.hpp"
#include "physics/error.hpp"

namespace sweetspot {
namespace {

std::string egl_error_text(const char* step) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04X)", step, static_cast<unsigned>(eglGetError()));
  return buf;
}

bool has_word(const char* list, const char* word) {
  if (list == nullptr) return false;
  const std::string s = std::string(" ") + list + " ";
  return s.find(std::string(" ") + word + " ") != std::string::npos;
}

// eglTerminate ends every context on a display, and displays are shared per platform, so
// the display is terminated only when the last OffscreenContext on it goes away.
std::mutex& display_mutex() {
  static std::mutex m;
  return m;
}
std::map<EGLDisplay, int>& display_refs() {
  static std::map<EGLDisplay, int> refs;
  return refs;
}

/// A hardware EGL device (not Mesa's software device), or EGL_NO_DISPLAY.
EGLDisplay hardware_device_display(std::string* why) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_word(client, "EGL_EXT_device_enumeration") && !has_word(client, "EGL_EXT_device_base")) {
    *why = "EGL has no device enumeration (EGL_EXT_device_enumeration)";
    return EGL_NO_DISPLAY;
  }
  auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto device_string =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  if (query_devices == nullptr || device_string == nullptr) {
    *why = "eglQueryDevicesEXT is missing";
    return EGL_NO_DISPLAY;
  }
  EGLint count = 0;
  if (!query_devices(0, nullptr, &count) || count <= 0) {
    *why = "no EGL devices";
    return EGL_NO_DISPLAY;
  }
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  query_devices(count, devices.data(), &count);
  for (EGLint i = 0; i < count; ++i) {
    // Mesa lists llvmpipe as a "software" device; that is what surfaceless gives anyway.
    if (has_word(device_string(devices[static_cast<std::size_t>(i)], EGL_EXTENSIONS), "EGL_MESA_device_software")) continue;
    EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)], nullptr);
    if (d != EGL_NO_DISPLAY) return d;
  }
  *why = "no hardware EGL device (only Mesa's software device)";
  return EGL_NO_DISPLAY;
}

}  // namespace

EglPlatform parse_egl_platform(std::string_view name) {
  if (name == "auto") return EglPlatform::Auto;
  if (name == "device") return EglPlatform::Device;
  if (name == "surfaceless") return EglPlatform::Surfaceless;
  throw InputError("EGL platform '" + std::string(name) + "' is not one of: auto, device, surfaceless");
}

const char* to_string(EglPlatform p) {
  switch (p) {
    case EglPlatform::Auto: return "auto";
    case EglPlatform::Device: return "device";
    case EglPlatform::Surfaceless: return "surfaceless";
  }
  return "?";
}

OffscreenContext::OffscreenContext(EglPlatform platform) {
  if (const char* env = std::getenv("SWEETSPOT_EGL_PLATFORM"); env != nullptr && *env != '\0') {
    try {
      platform = parse_egl_platform(env);
    } catch (const InputError& e) {
      throw InputError(std::string("SWEETSPOT_EGL_PLATFORM: ") + e.what());
    }
  }
  const std::string prefix = "cannot create an off-screen OpenGL context: ";

  EGLDisplay display = EGL_NO_DISPLAY;
  std::string device_why;
  if (platform != EglPlatform::Surfaceless) {
    display = hardware_device_display(&device_why);
    if (display != EGL_NO_DISPLAY) {
      platform_ = EglPlatform::Device;
    } else if (platform == EglPlatform::Device) {
      throw RenderUnavailable(prefix + "EGL device platform: " + device_why);
    }
  }
  if (display == EGL_NO_DISPLAY) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (client == nullptr) {
      throw RenderUnavailable(prefix + "EGL is not usable here (no client extensions; is an EGL "
                              "vendor such as libegl-mesa0 installed?) " +
                              egl_error_text("eglQueryString"));
    }
    if (!has_word(client, "EGL_MESA_platform_surfaceless")) {
      throw RenderUnavailable(prefix + "EGL lacks EGL_MESA_platform_surfaceless and " +
                              (device_why.empty() ? "the device platform was not tried" : device_why));
    }
    display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) throw RenderUnavailable(prefix + egl_error_text("eglGetPlatformDisplay(surfaceless)"));
    platform_ = EglPlatform::Surfaceless;
  }

  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) throw RenderUnavailable(prefix + egl_error_text("eglInitialize"));
  {
    std::lock_guard<std::mutex> lock(display_mutex());
    ++display_refs()[display];
  }
  display_ = display;
  auto fail = [&](const std::string& what) {
    const std::string msg = prefix + what;
    release();  // drops the display reference taken above
    throw RenderUnavailable(msg);
  };
  if (!eglBindAPI(EGL_OPENGL_API)) fail(egl_error_text("eglBindAPI(EGL_OPENGL_API)"));

  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n_configs = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &n_configs) || n_configs < 1) {
    // Surfaceless contexts need no config where EGL_KHR_no_config_context is offered.
    if (!has_word(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
      fail("no EGL config renders OpenGL");
    }
    config = nullptr;  // EGL_NO_CONFIG_KHR
  }
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_NONE};
  EGLContext ctx = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  if (ctx == EGL_NO_CONTEXT) fail(egl_error_text("eglCreateContext(OpenGL 3.3 core)"));
  context_ = ctx;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) fail(egl_error_text("eglMakeCurrent(surfaceless)"));

  GLint gl_major = 0, gl_minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &gl_major);
  glGetIntegerv(GL_MINOR_VERSION, &gl_minor);
  if (gl_major * 10 + gl_minor < 33) {
    fail("OpenGL " + std::to_string(gl_major) + "." + std::to_string(gl_minor) + " found, 3.3 core needed");
  }
  auto gl_string = [](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(glGetString(e));
    return std::string(s ? s : "?");
  };
  description_ = std::string("EGL ") + to_string(platform_) + ", " + gl_string(GL_RENDERER) + ", OpenGL " +
                 gl_string(GL_VERSION);
}

OffscreenContext::~OffscreenContext() { release(); }

void OffscreenContext::release() {
  if (display_ == nullptr) return;
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != nullptr) eglDestroyContext(display, static_cast<EGLContext>(context_));
  context_ = nullptr;
  bool last = false;
  {
    std::lock_guard<std::mutex> lock(display_mutex());
    last = --display_refs()[display] == 0;
    if (last) display_refs().erase(display);
  }
  if (last) eglTerminate(display);
  eglReleaseThread();
  display_ = nullptr;
}

void OffscreenContext::make_current() const {
  if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                      static_cast<EGLContext>(context_))) {
    throw RenderUnavailable(egl_error_text("eglMakeCurrent"));
  }
}

}  // namespace sweetspot
