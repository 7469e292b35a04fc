#include "game/render/renderer.hpp"

#include <array>

#include <algorithm>
#include <string>

#include "game/render/camera.hpp"
#include "game/render/gl.hpp"
#include "game/render/image.hpp"
#include "game/render/render_error.hpp"
#include "game/render/render_paths.hpp"
#include "game/render/shader_program.hpp"
#include "physics/error.hpp"

namespace sweetspot {

struct Renderer::Impl {
  ShaderProgram lit, flat, sky, depth;
  GpuMesh ground_overlay, top_overlay, figures;
  GLuint empty_vao = 0;
  GLuint msaa_fbo = 0, msaa_color = 0, msaa_depth = 0;
  GLuint resolve_fbo = 0, resolve_color = 0;
  GLuint shadow_fbo = 0, shadow_depth = 0;  // the sun's shadow map (depth texture)
  int shadow_size = 0;

  explicit Impl(const std::filesystem::path& dir)
      : lit(dir, "lit"), flat(dir, "flat"), sky(dir, "sky"), depth(dir, "depth") {
    glGenVertexArrays(1, &empty_vao);
  }
  ~Impl() {
    release_targets();
    glDeleteVertexArrays(1, &empty_vao);
    if (shadow_fbo != 0) glDeleteFramebuffers(1, &shadow_fbo);
    if (shadow_depth != 0) glDeleteTextures(1, &shadow_depth);
  }
  void make_shadow_map(int size);
  void release_targets() {
    if (msaa_fbo != 0) glDeleteFramebuffers(1, &msaa_fbo);
    if (resolve_fbo != 0) glDeleteFramebuffers(1, &resolve_fbo);
    if (msaa_color != 0) glDeleteRenderbuffers(1, &msaa_color);
    if (msaa_depth != 0) glDeleteRenderbuffers(1, &msaa_depth);
    if (resolve_color != 0) glDeleteTextures(1, &resolve_color);
    msaa_fbo = resolve_fbo = msaa_color = msaa_depth = resolve_color = 0;
  }
};

namespace {

void check_size(int w, int h) {
  if (w < 16 || w > 8192 || h < 16 || h > 8192) {
    throw InputError("image size " + std::to_string(w) + "x" + std::to_string(h) +
                     " is outside 16..8192 pixels per side");
  }
}

void check_fbo(const char* which) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw RenderError(std::string(which) + " framebuffer incomplete (status 0x" + std::to_string(status) + ")");
  }
}

Eigen::Matrix3f normal_matrix(const Eigen::Matrix4f& model) {
  return model.block<3, 3>(0, 0).inverse().transpose();
}

}  // namespace

Renderer::Renderer(int width, int height, const RendererOptions& options) {
  check_size(width, height);
  impl_ = std::make_unique<Impl>(options.shader_dir.empty() ? shader_dir() : options.shader_dir);
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  const auto* renderer_name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = renderer_name ? renderer_name : "";
  software_ = name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
              name.find("swrast") != std::string::npos;
  const int wanted = options.samples > 0 ? options.samples : (software_ ? 1 : 4);
  samples_ = std::clamp(wanted, 1, std::max(1, static_cast<int>(max_samples)));
  shadows_ = options.shadows > 0 || (options.shadows < 0 && !software_);
  if (shadows_) {
    if (options.shadow_map_size < 256 || options.shadow_map_size > 8192)
      throw InputError("shadow map size " + std::to_string(options.shadow_map_size) + " is outside 256..8192 texels");
    GLint max_tex = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
    impl_->make_shadow_map(std::min(options.shadow_map_size, static_cast<int>(max_tex)));
  }
  resize(width, height);
}

Renderer::~Renderer() = default;

void Renderer::Impl::make_shadow_map(int size) {
  shadow_size = size;
  glGenTextures(1, &shadow_depth);
  glBindTexture(GL_TEXTURE_2D, shadow_depth);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  // Hardware depth comparison, 2x2 filtered: soft-edged shadows for one fetch.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenFramebuffers(1, &shadow_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_depth, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  check_fbo("shadow map");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::resize(int width, int height) {
  check_size(width, height);
  width_ = width;
  height_ = height;
  Impl& m = *impl_;
  m.release_targets();

  glGenRenderbuffers(1, &m.msaa_color);
  glBindRenderbuffer(GL_RENDERBUFFER, m.msaa_color);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &m.msaa_depth);
  glBindRenderbuffer(GL_RENDERBUFFER, m.msaa_depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &m.msaa_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, m.msaa_fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m.msaa_color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m.msaa_depth);
  check_fbo("multisampled");

  glGenTextures(1, &m.resolve_color);
  glBindTexture(GL_TEXTURE_2D, m.resolve_color);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenFramebuffers(1, &m.resolve_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, m.resolve_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m.resolve_color, 0);
  check_fbo("resolve");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

namespace {

// True when `box` (in the mesh's frame) lies wholly outside one side of the clip volume of
// `clip` (view-projection times model): none of its corners is inside that plane.
bool outside_view(const Eigen::Matrix4f& clip, const Eigen::AlignedBox3f& box) {
  std::array<int, 6> out{};  // corners beyond -x, +x, -y, +y, -z, +z
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3f p = box.corner(static_cast<Eigen::AlignedBox3f::CornerType>(c));
    const Eigen::Vector4f q = clip * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
    for (int a = 0; a < 3; ++a) {
      out[static_cast<std::size_t>(2 * a)] += q[a] < -q.w();
      out[static_cast<std::size_t>(2 * a + 1)] += q[a] > q.w();
    }
  }
  return std::any_of(out.begin(), out.end(), [](int n) { return n == 8; });
}

bool culled(const MeshInstance& inst, const Eigen::Matrix4f& view_proj) {
  return inst.bounds && outside_view(view_proj * inst.model, *inst.bounds);
}

}  // namespace

void Renderer::draw(const Scene& scene, const Camera& camera) {
  Impl& m = *impl_;
  const double aspect = double(width_) / height_;
  const Eigen::Matrix4d view_proj_d = camera.projection(aspect) * camera.view();
  const Eigen::Matrix4f view_proj = view_proj_d.cast<float>();
  const Eigen::Vector3f eye = camera.eye.cast<float>();

  // The sun's shadow map: an orthographic view along the sunlight over the scene's shadow
  // square, depth only, every mesh a caster (the ground too: hills shade). A slope-scaled
  // depth offset keeps lit surfaces from shadowing themselves (acne).
  if (!scene.figures.indices.empty()) m.figures.upload(scene.figures);
  const bool shadows = shadows_ && scene.shadow_radius > 0.0f;
  Eigen::Matrix4f light_view_proj = Eigen::Matrix4f::Identity();
  if (shadows) {
    const double r = scene.shadow_radius;
    Camera sun;
    const Vec3 centre = scene.shadow_centre.cast<double>();
    const Vec3 to_sun = scene.sun_direction.cast<double>().normalized();
    sun.eye = centre + 4.0 * r * to_sun;
    sun.target = centre;
    sun.up = std::abs(to_sun.y()) < 0.99 ? Vec3::UnitY() : Vec3::UnitX();
    Eigen::Matrix4d ortho = Eigen::Matrix4d::Identity();
    const double n = 0.1, f = 8.0 * r;
    ortho(0, 0) = 1.0 / r;
    ortho(1, 1) = 1.0 / r;
    ortho(2, 2) = -2.0 / (f - n);
    ortho(2, 3) = -(f + n) / (f - n);
    light_view_proj = (ortho * sun.view()).cast<float>();
    glBindFramebuffer(GL_FRAMEBUFFER, m.shadow_fbo);
    glViewport(0, 0, m.shadow_size, m.shadow_size);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    m.depth.use();
    m.depth.set("u_light_view_proj", light_view_proj);
    for (const auto& inst : scene.meshes) {
      if (inst.mesh == nullptr || inst.decal > 0) continue;  // flat paint casts nothing
      if (culled(inst, light_view_proj)) continue;
      m.depth.set("u_model", inst.model);
      inst.mesh->draw();
    }
    if (!scene.figures.indices.empty()) {
      m.depth.set("u_model", Eigen::Matrix4f(Eigen::Matrix4f::Identity()));
      m.figures.draw();
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
  }

  glBindFramebuffer(GL_FRAMEBUFFER, m.msaa_fbo);
  glViewport(0, 0, width_, height_);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glClearColor(scene.sky_horizon.x(), scene.sky_horizon.y(), scene.sky_horizon.z(), 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  m.lit.use();
  m.lit.set("u_view_proj", view_proj);
  m.lit.set("u_eye", eye);
  m.lit.set("u_sun_dir", scene.sun_direction);
  m.lit.set("u_haze", scene.sky_horizon);
  m.lit.set("u_haze_range", scene.haze_range);
  m.lit.set("u_light_view_proj", light_view_proj);
  m.lit.set("u_shadows", shadows ? 1.0f : 0.0f);
  if (shadows) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m.shadow_depth);
    m.lit.set("u_shadow_map", 0);
  }
  // Front to back, so the depth test rejects hidden fragments before they are shaded (a
  // software rasteriser's cost is the fragments it shades): small meshes first, then the
  // ground paint from its top layer down, then the terrain under it all.
  std::vector<const MeshInstance*> order;
  order.reserve(scene.meshes.size());
  for (const auto& inst : scene.meshes) order.push_back(&inst);
  auto rank = [](const MeshInstance* i) { return i->terrain ? 1000000 : i->decal > 0 ? 1000 - i->decal : 0; };
  std::stable_sort(order.begin(), order.end(), [&](const MeshInstance* a, const MeshInstance* b) { return rank(a) < rank(b); });
  for (const MeshInstance* instance : order) {
    const MeshInstance& inst = *instance;
    if (inst.mesh == nullptr || culled(inst, view_proj)) continue;
    // Terrain is pushed back a little in depth so markers lying on it win the depth test.
    if (inst.terrain) {
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.0f, 4.0f);
    } else if (inst.decal > 0) {
      // Each decal layer one step in front of the one below (terrain is 1, 4), still behind
      // the ground overlays, which are lifted by centimetres.
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.0f - 0.5f * static_cast<float>(inst.decal), 4.0f - 4.0f * static_cast<float>(inst.decal));
    }
    m.lit.set("u_specular", inst.terrain || inst.decal > 0 ? 0.0f : 1.0f);
    m.lit.set("u_model", inst.model);
    m.lit.set("u_normal_matrix", normal_matrix(inst.model));
    inst.mesh->draw();
    if (inst.terrain || inst.decal > 0) glDisable(GL_POLYGON_OFFSET_FILL);
  }

  if (!scene.figures.indices.empty()) {
    m.lit.set("u_specular", 0.0f);
    m.lit.set("u_model", Eigen::Matrix4f(Eigen::Matrix4f::Identity()));
    m.lit.set("u_normal_matrix", Eigen::Matrix3f(Eigen::Matrix3f::Identity()));
    m.figures.draw();
  }

  // Sky after the opaque meshes, at the far plane with LEQUAL: only pixels nothing covered
  // are shaded (early depth test), which matters on a software rasteriser.
  glDepthMask(GL_FALSE);
  m.sky.use();
  m.sky.set("u_inv_view_proj", Eigen::Matrix4f(view_proj_d.inverse().cast<float>()));
  m.sky.set("u_eye", eye);
  m.sky.set("u_sun_dir", scene.sun_direction);
  m.sky.set("u_horizon", scene.sky_horizon);
  m.sky.set("u_zenith", scene.sky_zenith);
  glBindVertexArray(m.empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);

  m.flat.use();
  m.flat.set("u_view_proj", view_proj);
  glEnable(GL_BLEND);
  // Colour blends; the stored alpha stays 1 so images are opaque.
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  m.ground_overlay.upload(scene.ground_overlay);
  m.ground_overlay.draw();
  glDisable(GL_DEPTH_TEST);
  m.top_overlay.upload(scene.top_overlay);
  m.top_overlay.draw();
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);

  // Resolve the samples into the single-sample FBO that read-back and windows use.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m.msaa_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m.resolve_fbo);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<std::uint8_t> Renderer::read_pixels() const {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width_) * height_ * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->resolve_fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  flip_rows(rgba, width_, height_, 4);
  return rgba;
}

void Renderer::blit_to(unsigned framebuffer, int x, int y, int w, int h) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->resolve_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glBlitFramebuffer(0, 0, width_, height_, x, y, x + w, y + h, GL_COLOR_BUFFER_BIT,
                    (w == width_ && h == height_) ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

unsigned Renderer::resolved_texture() const { return impl_->resolve_color; }

}  // namespace sweetspot
