// The desktop window: GLFW with an OpenGL 3.3 core context, and Dear ImGui set up on it with the GLFW
// and OpenGL3 backends (as in imgui's example_glfw_opengl3). One per program, on the main thread.
#pragma once
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace sph::gui {

class Window {
 public:
  /// Opens a width x height window (clamped to the screen) titled `title`; nullptr with *err if there is
  /// no display or no GL 3.3 core context.
  static std::unique_ptr<Window> create(int width, int height, const char* title, std::string* err);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  /// Framebuffer size [px] (what GL draws into and what a screenshot holds).
  void framebuffer_size(int* w, int* h) const;
  /// True once after the window system asked for a repaint (uncovered, resized, ...).
  bool take_damage();
  /// GL entry-point loader for sph::render::Renderer::init (glfwGetProcAddress).
  static void* get_proc(const char* name);
  /// Keys pressed since the last call (GLFW key codes, auto-repeats included), in order. Every tap
  /// counts, also one pressed and released between two frames, which polling the key state once per
  /// frame misses. Filled by GLFW's key callback (ImGui's backend chains to it).
  std::vector<int> take_key_presses();
  /// Keys pressed with Ctrl held since the last call (also in take_key_presses): Ctrl+= / Ctrl+- scale the UI.
  std::vector<int> take_ctrl_presses();
  /// Test hook: a press and a release of `key` (with GLFW modifier bits `mods`), delivered through the same
  /// callback as GLFW's events.
  void tap_key(int key, int mods = 0);
  /// The UI font file was missing at start: ImGui's built-in font is used.
  bool font_fallback() const { return font_fallback_; }

 private:
  Window() = default;
  GLFWwindow* window_ = nullptr;
  bool glfw_ = false, imgui_ = false, imgui_glfw_ = false, imgui_gl_ = false;
  bool damaged_ = true;
  bool font_fallback_ = false;
  std::vector<int> presses_, ctrl_presses_;
  static void on_key(GLFWwindow* win, int key, int scancode, int action, int mods);
};

}  // namespace sph::gui
