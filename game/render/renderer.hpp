// The OpenGL 3.3 core renderer (DESIGN §7). It draws a Scene into a multisampled
// framebuffer object it owns, resolves it into a single-sample FBO, and from there either
// reads the pixels back (off-screen) or blits them to a window's framebuffer, so the
// window and an off-screen image of the same state match.
//
// Needs a current GL 3.3 core context (OffscreenContext or a GLFW window) for its whole
// life; not thread-safe.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "game/render/camera.hpp"
#include "game/render/scene.hpp"

namespace sweetspot {

struct RendererOptions {
  /// MSAA samples, clamped to GL_MAX_SAMPLES; 1 = no multisampling; 0 = auto: 4 on a GPU,
  /// 1 on a software rasteriser (llvmpipe), where 4x MSAA costs about 3x the CPU time of a
  /// frame (measured: 36-50 ms vs 13-17 ms CPU per 1280x720 frame) and the trail is
  /// anti-aliased in its shader anyway. Tests ask for 4 explicitly to cover the resolve.
  int samples = 0;
  /// GLSL source folder; empty = shader_dir().
  std::filesystem::path shader_dir;
  /// Shadow-mapped sunlight: 1 on, 0 off, -1 auto: on with a GPU, off on a software
  /// rasteriser, where the shadow pass and a filtered depth fetch per pixel cost more than
  /// the 16 ms window frame leaves (`frame_ms_1280x720_shadows` in `bench`). The ball's
  /// shadow is a ground decal either way.
  int shadows = -1;
  int shadow_map_size = 2048;  ///< texels per side (256..8192)
};

class Renderer {
 public:
  /// Throws RenderError when a shader is missing or fails (path + log) or the FBO is
  /// incomplete; InputError for a size outside 16..8192 px.
  Renderer(int width, int height, const RendererOptions& options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Reallocates the framebuffers (window resize).
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  bool shadows() const { return shadows_; }
  /// True on a software rasteriser (llvmpipe, softpipe, swrast).
  bool software() const { return software_; }

  /// Draws sky, lit meshes, ground overlay, top overlay into the MSAA FBO and resolves it.
  void draw(const Scene& scene, const Camera& camera);
  /// The resolved image, RGBA8, top row first (GL's bottom-up rows flipped).
  std::vector<std::uint8_t> read_pixels() const;
  /// Copies the resolved image into `framebuffer` (0 = the window) scaled to w x h.
  void blit_to(unsigned framebuffer, int w, int h) const { blit_to(framebuffer, 0, 0, w, h); }
  /// Copies the resolved image into the rectangle (x, y, w, h) of `framebuffer`, GL window
  /// coordinates (origin bottom-left): the 3D view beside the panels.
  void blit_to(unsigned framebuffer, int x, int y, int w, int h) const;
  /// The resolved colour texture (RGBA8), e.g. for an ImGui image.
  unsigned resolved_texture() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int width_ = 0, height_ = 0, samples_ = 1;
  bool software_ = false;
  bool shadows_ = false;
};

}  // namespace sweetspot
