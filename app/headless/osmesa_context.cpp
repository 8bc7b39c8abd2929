// OSMesa backend of OffscreenContext: renders into a client-memory RGBA buffer (the default
// framebuffer of the context). Reads back with glReadPixels and flips OSMesa's bottom-up rows.
#include "osmesa_context.h"

#include <GL/osmesa.h>

#include <cstring>

namespace sph::cli {

namespace {

void* osmesa_get_proc(const char* name) { return object_pointer(OSMesaGetProcAddress(name)); }

class OsmesaContext final : public OffscreenContext {
 public:
  explicit OsmesaContext(OSMesaContext ctx) : ctx_(ctx) {}
  ~OsmesaContext() override {
    if (OSMesaGetCurrentContext() == ctx_) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(ctx_);
  }

  bool make_current(int width, int height, std::string* err) override {
    if (width <= 0 || height <= 0) {
      if (err) *err = "invalid frame size " + std::to_string(width) + "x" + std::to_string(height);
      return false;
    }
    if (width != width_ || height != height_) {
      buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
      width_ = width;
      height_ = height;
    }
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      if (err) *err = "OSMesaMakeCurrent failed";
      return false;
    }
    if (!gl_loaded_) {
      if (!gl_.load(osmesa_get_proc, err)) return false;
      gl_loaded_ = true;
    }
    return true;
  }

  render::GetProcFn proc_loader() const override { return osmesa_get_proc; }

  bool read_pixels(std::vector<std::uint8_t>* rgba, std::string* err) override {
    if (!gl_loaded_) {
      if (err) *err = "no current OSMesa context";
      return false;
    }
    read_top_down(gl_, width_, height_, &scratch_, rgba);
    return true;
  }

  int width() const override { return width_; }
  int height() const override { return height_; }

  std::string description() const override {
    if (!gl_loaded_) return "OSMesa (not current)";
    auto str = [&](GLenum e) {
      const GLubyte* s = gl_.GetString(e);
      return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return "OSMesa, OpenGL " + str(GL_VERSION) + ", " + str(GL_RENDERER);
  }

 private:
  OSMesaContext ctx_;
  std::vector<std::uint8_t> buffer_, scratch_;
  int width_ = 0, height_ = 0;
  render::GlApi gl_;  // only what readback needs; the renderer loads its own table
  bool gl_loaded_ = false;
};

}  // namespace

std::unique_ptr<OffscreenContext> create_osmesa_context(std::string* err) {
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                         OSMESA_DEPTH_BITS, 24,
                         OSMESA_STENCIL_BITS, 0,
                         OSMESA_ACCUM_BITS, 0,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 3,
                         OSMESA_CONTEXT_MINOR_VERSION, 3,
                         0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (ctx == nullptr) {
    if (err) *err = "OSMesaCreateContextAttribs failed (need Mesa with OpenGL 3.3 core support)";
    return nullptr;
  }
  return std::make_unique<OsmesaContext>(ctx);
}

}  // namespace sph::cli
