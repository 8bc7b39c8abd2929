// OffscreenRenderer: the renderer made current in its own off-screen context for every frame.
#include "offscreen_renderer.h"

namespace sph::cli {

std::unique_ptr<OffscreenRenderer> OffscreenRenderer::create(std::string* err, GlBackend backend) {
  auto r = std::unique_ptr<OffscreenRenderer>(new OffscreenRenderer());
  r->context_ = create_offscreen_context(backend, err);
  if (!r->context_) return nullptr;
  // A small target first: the renderer needs a current context to compile its shaders.
  if (!r->context_->make_current(16, 16, err)) return nullptr;
  if (!r->renderer_.init(r->context_->proc_loader(), err)) return nullptr;
  return r;
}

OffscreenRenderer::~OffscreenRenderer() {
  // Another context may be current on this thread: the renderer's GL objects live in this one.
  std::string ignored;
  if (context_ && context_->width() > 0 && context_->make_current(context_->width(), context_->height(), &ignored))
    renderer_.shutdown();
}

bool OffscreenRenderer::render(const sph::Snapshot& snap, const render::ViewSettings& view, int width, int height,
                               std::vector<std::uint8_t>* rgba, std::string* err) {
  render::FrameScene scene;
  scene.a = &snap;
  return render(scene, view, width, height, rgba, err);
}

bool OffscreenRenderer::render(const render::FrameScene& scene, const render::ViewSettings& view, int width,
                               int height, std::vector<std::uint8_t>* rgba, std::string* err) {
  if (!context_->make_current(width, height, err)) return false;
  renderer_.render(scene, view, width, height);
  last_gl_error_ = renderer_.gl().GetError();
  return context_->read_pixels(rgba, err);
}

bool render_snapshot_rgba(const sph::Snapshot& snap, const render::ViewSettings& view, int width, int height,
                          std::vector<std::uint8_t>* rgba, std::string* err) {
  auto r = OffscreenRenderer::create(err);
  return r && r->render(snap, view, width, height, rgba, err);
}

}  // namespace sph::cli
