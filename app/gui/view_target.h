// An off-screen colour + depth target the particle view is rendered into: the renderer draws a whole
// frame at origin (0,0), and the GUI blits it into its place in the window (or reads it back to record).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace sph::gui {

class ViewTarget {
 public:
  ViewTarget() = default;
  ~ViewTarget();
  ViewTarget(const ViewTarget&) = delete;
  ViewTarget& operator=(const ViewTarget&) = delete;

  /// (Re)allocates to width x height if the size changed; false with *err if incomplete.
  bool resize(int width, int height, std::string* err);
  /// Binds as the draw framebuffer (the renderer then draws into it).
  void bind() const;
  /// Binds the window's framebuffer again.
  static void unbind();
  /// Waits until GL has finished all drawing (glFinish).
  static void finish();
  /// Copies the target to the window's back buffer with its top-left corner at (x, y) [px, y down].
  void blit_to_window(int x, int y, int window_height) const;
  /// RGBA8, rows top-down (image order).
  void read_rgba(std::vector<std::uint8_t>* rgba) const;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void release();
  unsigned fbo_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

/// Reads the window's back buffer (after everything is drawn) as RGBA8, rows top-down.
void read_window_rgba(int width, int height, std::vector<std::uint8_t>* rgba);

}  // namespace sph::gui
