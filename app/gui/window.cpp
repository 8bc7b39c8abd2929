#include "window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "pin_libraries.h"
#include "ui_look.h"

namespace sph::gui {
namespace {

void glfw_error(int code, const char* text) { std::fprintf(stderr, "sph-gui: GLFW error %d: %s\n", code, text); }

}  // namespace

std::unique_ptr<Window> Window::create(int width, int height, const char* title, std::string* err) {
  std::unique_ptr<Window> w(new Window());
  glfwSetErrorCallback(glfw_error);
  if (!glfwInit()) {
    *err = "cannot initialise GLFW (is there a display? try xvfb-run -a sph-gui ...)";
    return nullptr;
  }
  w->glfw_ = true;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  if (GLFWmonitor* m = glfwGetPrimaryMonitor()) {
    if (const GLFWvidmode* mode = glfwGetVideoMode(m)) {
      width = std::min(width, mode->width);
      height = std::min(height, mode->height);
    }
  }
  w->window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (w->window_ == nullptr) {
    *err = "cannot create a window with an OpenGL 3.3 core context";
    return nullptr;
  }
  glfwMakeContextCurrent(w->window_);
  pin_loaded_libraries();  // the GL driver is loaded now (ASan builds: it stays mapped for LeakSanitizer)
  glfwSetWindowUserPointer(w->window_, w.get());
  glfwSetWindowRefreshCallback(w->window_, [](GLFWwindow* win) {
    static_cast<Window*>(glfwGetWindowUserPointer(win))->damaged_ = true;
  });
  glfwSwapInterval(1);  // vsync where there is one; the frame cap in FrameStats covers the rest
  glfwSetKeyCallback(w->window_, &Window::on_key);  // before ImGui's backend, which then chains to it

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  w->imgui_ = true;
  ImGui::GetIO().IniFilename = nullptr;  // the layout is computed every frame: nothing to save
  apply_ui_look(UiLook{}, false, &w->font_fallback_);  // the font atlas and style at scale 1 (ui_look.h)
  w->imgui_glfw_ = ImGui_ImplGlfw_InitForOpenGL(w->window_, true);
  w->imgui_gl_ = w->imgui_glfw_ && ImGui_ImplOpenGL3_Init("#version 330 core");
  if (!w->imgui_gl_) {
    *err = "cannot initialise the ImGui GLFW/OpenGL3 backends";
    return nullptr;
  }
  return w;
}

Window::~Window() {
  if (imgui_gl_) ImGui_ImplOpenGL3_Shutdown();
  if (imgui_glfw_) ImGui_ImplGlfw_Shutdown();
  if (imgui_) ImGui::DestroyContext();
  if (window_) glfwDestroyWindow(window_);
  if (glfw_) glfwTerminate();
}

void Window::on_key(GLFWwindow* win, int key, int /*scancode*/, int action, int mods) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  Window* w = static_cast<Window*>(glfwGetWindowUserPointer(win));
  (mods & GLFW_MOD_CONTROL ? w->ctrl_presses_ : w->presses_).push_back(key);  // Ctrl+S is not S
}

std::vector<int> Window::take_ctrl_presses() {
  std::vector<int> out;
  out.swap(ctrl_presses_);
  return out;
}

std::vector<int> Window::take_key_presses() {
  std::vector<int> out;
  out.swap(presses_);
  return out;
}

void Window::tap_key(int key, int mods) {
  on_key(window_, key, 0, GLFW_PRESS, mods);
  on_key(window_, key, 0, GLFW_RELEASE, mods);
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }

bool Window::take_damage() {
  const bool d = damaged_;
  damaged_ = false;
  return d;
}

void Window::framebuffer_size(int* w, int* h) const { glfwGetFramebufferSize(window_, w, h); }

void* Window::get_proc(const char* name) {
  const GLFWglproc p = glfwGetProcAddress(name);
  void* v = nullptr;
  static_assert(sizeof(p) == sizeof(v));
  std::memcpy(&v, &p, sizeof v);  // function -> object pointer, as dlsym does
  return v;
}

}  // namespace sph::gui
