// Off-screen GL contexts for the headless program. OffscreenContext is the seam: OSMesa
// (osmesa_context.cpp) and EGL without a window system (egl_context.cpp: Mesa's surfaceless platform, or
// the device platform) sit behind it; the renderer and the frame recorder never see which one runs.
// Both libraries can live in one binary: libEGL exports only egl* symbols, libOSMesa the GL entry
// points, and the renderer loads GL through the context's own get_proc_address.
#pragma once
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "gl_api.h"

namespace sph::cli {

class OffscreenContext {
 public:
  virtual ~OffscreenContext() = default;
  /// Makes the context current on this thread with a width x height colour + depth target,
  /// (re)allocating it when the size changes.
  virtual bool make_current(int width, int height, std::string* err) = 0;
  /// GL entry-point loader for sph::render::Renderer::init (valid while the context exists).
  virtual render::GetProcFn proc_loader() const = 0;
  /// Copies the finished frame as RGBA8 with rows top-down (image order), width*height*4 bytes.
  virtual bool read_pixels(std::vector<std::uint8_t>* rgba, std::string* err) = 0;
  virtual int width() const = 0;
  virtual int height() const = 0;
  /// "OSMesa, OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe ..." or "EGL (surfaceless), ..." (after
  /// make_current).
  virtual std::string description() const = 0;
};

/// Which library makes the context: `--gl osmesa|egl|auto` (auto: OSMesa where it is built and works,
/// else EGL).
enum class GlBackend { Auto, OSMesa, Egl };

/// "auto", "osmesa", "egl" -> the backend; false for anything else.
bool parse_gl_backend(const std::string& name, GlBackend* out);
/// The backend named by the environment variable SPH_GL (the default of --gl; tests run the renderer
/// on both), Auto when it is unset or empty.
GlBackend gl_backend_from_environment();
/// The backends this build has, e.g. "osmesa egl".
std::string built_gl_backends();

/// A context of that backend (Auto: OSMesa, then EGL), nullptr with *err saying why each failed.
std::unique_ptr<OffscreenContext> create_offscreen_context(GlBackend backend, std::string* err);

}  // namespace sph::cli

namespace sph::cli {

/// A function pointer (what a get_proc_address returns) as the object pointer the renderer's seam takes.
template <class Fn>
void* object_pointer(Fn f) {
  void* p = nullptr;
  static_assert(sizeof(p) == sizeof(f));
  std::memcpy(&p, &f, sizeof(p));
  return p;
}

/// glReadPixels of the bound framebuffer (rows bottom-up in GL) into rgba with rows top-down.
void read_top_down(const render::GlApi& gl, int width, int height, std::vector<std::uint8_t>* scratch,
                   std::vector<std::uint8_t>* rgba);

}  // namespace sph::cli
