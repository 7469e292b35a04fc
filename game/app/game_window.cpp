#include "game/app/game_window.hpp"

#include <stdexcept>
#include <utility>

#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

namespace sweetspot {
namespace {

// Scroll arrives through a callback; ImGui's backend chains to the previous one, so keep
// ours installed first and accumulate until the frame reads it.
double g_scroll = 0.0;
void on_scroll(GLFWwindow*, double, double dy) { g_scroll += dy; }

void on_glfw_error(int code, const char* text) {
  // Kept for the exception message below; GLFW reports failures through this hook only.
  (void)code;
  (void)text;
}

}  // namespace

GameWindow::GameWindow(const WindowOptions& options) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    const char* why = nullptr;
    glfwGetError(&why);
    throw std::runtime_error(std::string("cannot initialise GLFW: ") + (why ? why : "unknown error"));
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!window_) {
    const char* why = nullptr;
    glfwGetError(&why);
    glfwTerminate();
    throw std::runtime_error(std::string("cannot open an OpenGL 3.3 core window: ") +
                             (why ? why : "unknown error"));
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(options.vsync ? 1 : 0);
  glfwSetScrollCallback(window_, on_scroll);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // layout is ours, not a file left in the cwd
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

GameWindow::~GameWindow() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GameWindow::should_close() const { return glfwWindowShouldClose(window_) != 0; }

FrameInput GameWindow::begin_frame() {
  g_scroll = 0.0;
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();

  FrameInput in;
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    // ImGui 1.86 (Debian 12) indexes keys by the backend's codes: GLFW key numbers.
    in.hit_again = ImGui::IsKeyPressed(GLFW_KEY_SPACE, false);
    in.replay = ImGui::IsKeyPressed(GLFW_KEY_R, false);
    for (int i = 0; i < 4; ++i)
      if (ImGui::IsKeyPressed(GLFW_KEY_1 + i, false)) in.camera = i;
  }
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  const bool down = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  if (!io.WantCaptureMouse) {
    if (down && dragging_) {
      in.orbit_dx = x - last_x_;
      in.orbit_dy = y - last_y_;
    }
    dragging_ = down;
    in.zoom = g_scroll;
  } else {
    dragging_ = false;
  }
  last_x_ = x;
  last_y_ = y;
  return in;
}

void GameWindow::render_ui() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void GameWindow::read_pixels(int& width, int& height, std::vector<unsigned char>& rgba) const {
  glfwGetFramebufferSize(window_, &width, &height);
  rgba.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  // GL rows run bottom-up; images are top-down.
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int r = 0; r < height / 2; ++r) {
    unsigned char* a = rgba.data() + static_cast<std::size_t>(r) * row;
    unsigned char* b = rgba.data() + static_cast<std::size_t>(height - 1 - r) * row;
    for (std::size_t i = 0; i < row; ++i) std::swap(a[i], b[i]);
  }
}

void GameWindow::present() { glfwSwapBuffers(window_); }

int GameWindow::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}
int GameWindow::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

}  // namespace sweetspot
