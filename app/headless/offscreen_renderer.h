// An off-screen OpenGL context (OSMesa or EGL) with the shared renderer in it: snapshots in, RGBA pixels out.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "frame_scene.h"
#include "offscreen_context.h"
#include "renderer.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::cli {

/// An off-screen context plus a renderer: snapshot in, RGBA pixels out.
class OffscreenRenderer {
 public:
  /// A context of `backend` (default: SPH_GL from the environment, else auto) and a renderer in it.
  static std::unique_ptr<OffscreenRenderer> create(std::string* err, GlBackend backend = gl_backend_from_environment());
  ~OffscreenRenderer();  ///< frees the GL objects with its own context current
  /// Renders into an RGBA8 buffer of width*height*4 bytes, rows top-down.
  bool render(const sph::Snapshot& snap, const render::ViewSettings& view, int width, int height,
              std::vector<std::uint8_t>* rgba, std::string* err);
  bool render(const render::FrameScene& scene, const render::ViewSettings& view, int width, int height,
              std::vector<std::uint8_t>* rgba, std::string* err);
  /// glGetError() after the last render (GL_NO_ERROR = 0 when all went well).
  unsigned gl_error() const { return last_gl_error_; }
  const render::FrameLayout& last_layout() const { return renderer_.last_layout(); }
  render::Renderer& renderer() { return renderer_; }
  std::string description() const { return context_->description(); }

 private:
  std::unique_ptr<OffscreenContext> context_;  // declared first: destroyed after the renderer
  render::Renderer renderer_;
  unsigned last_gl_error_ = 0;
};

/// Renders one snapshot to RGBA8 (rows top-down) with a temporary context (tests, one-off images).
bool render_snapshot_rgba(const sph::Snapshot& snap, const render::ViewSettings& view, int width, int height,
                          std::vector<std::uint8_t>* rgba, std::string* err);

}  // namespace sph::cli
