#include "game/app/game_window.hpp"

#include <chrono>
#include <stdexcept>
#include <utility>

#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

namespace sweetspot {
namespace {

// Keys and scroll arrive through callbacks into the window's own queue (its user pointer),
// so a press and release inside one frame is never lost. ImGui's backend chains to the
// callbacks installed before it, so ours go first.
void on_scroll(GLFWwindow* w, double, double dy) {
  static_cast<GameWindow*>(glfwGetWindowUserPointer(w))->queue_scroll(dy);
}
void on_key(GLFWwindow* w, int key, int, int action, int) {
  if (action == GLFW_PRESS) static_cast<GameWindow*>(glfwGetWindowUserPointer(w))->queue_key(key);
}

void on_glfw_error(int code, const char* text) {
  // Kept for the exception message below; GLFW reports failures through this hook only.
  (void)code;
  (void)text;
}

}  // namespace

namespace {
double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

double GameWindow::clock() const { return steady_seconds() - epoch_; }

GameWindow::GameWindow(const WindowOptions& options) : epoch_(steady_seconds()) {
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
  glfwSetWindowUserPointer(window_, this);
  glfwSetScrollCallback(window_, on_scroll);
  glfwSetKeyCallback(window_, on_key);

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
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();

  FrameInput in;
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) in.keys = std::move(keys_);
  keys_.clear();
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  const bool down = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  if (!io.WantCaptureMouse) {
    if (down && dragging_) {
      in.orbit_dx = x - last_x_;
      in.orbit_dy = y - last_y_;
    }
    dragging_ = down;
    in.zoom = scroll_;
  } else {
    dragging_ = false;
  }
  last_x_ = x;
  last_y_ = y;
  scroll_ = 0.0;
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
