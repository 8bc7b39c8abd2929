// Choosing the off-screen backend at run time (--gl, SPH_GL), and the read-back both backends share.
#include "offscreen_context.h"

#include <cstdlib>
#include <cstring>

#ifdef SPH_HAVE_OSMESA
#include "osmesa_context.h"
#endif
#ifdef SPH_HAVE_EGL
#include "egl_context.h"
#endif

namespace sph::cli {

bool parse_gl_backend(const std::string& name, GlBackend* out) {
  if (name == "auto") *out = GlBackend::Auto;
  else if (name == "osmesa") *out = GlBackend::OSMesa;
  else if (name == "egl") *out = GlBackend::Egl;
  else return false;
  return true;
}

GlBackend gl_backend_from_environment() {
  const char* env = std::getenv("SPH_GL");
  GlBackend b = GlBackend::Auto;
  if (env != nullptr && *env != '\0') parse_gl_backend(env, &b);
  return b;
}

std::string built_gl_backends() {
  std::string s;
#ifdef SPH_HAVE_OSMESA
  s += "osmesa";
#endif
#ifdef SPH_HAVE_EGL
  s += s.empty() ? "egl" : " egl";
#endif
  return s;
}

std::unique_ptr<OffscreenContext> create_offscreen_context(GlBackend backend, std::string* err) {
  std::string why;
  auto attempt = [&](const char* name, auto&& create) -> std::unique_ptr<OffscreenContext> {
    std::string e;
    auto c = create(&e);
    if (!c) why += (why.empty() ? "" : "; ") + std::string(name) + ": " + e;
    return c;
  };
  if (backend == GlBackend::OSMesa || backend == GlBackend::Auto) {
#ifdef SPH_HAVE_OSMESA
    if (auto c = attempt("OSMesa", create_osmesa_context)) return c;
#else
    why += "OSMesa: not in this build (built: " + built_gl_backends() + ")";
#endif
  }
  if (backend == GlBackend::Egl || backend == GlBackend::Auto) {
#ifdef SPH_HAVE_EGL
    if (auto c = attempt("EGL", create_egl_context)) return c;
#else
    why += std::string(why.empty() ? "" : "; ") + "EGL: not in this build (built: " + built_gl_backends() + ")";
#endif
  }
  if (err) *err = "no off-screen OpenGL context (" + why + ")";
  return nullptr;
}

void read_top_down(const render::GlApi& gl, int width, int height, std::vector<std::uint8_t>* scratch,
                   std::vector<std::uint8_t>* rgba) {
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  scratch->resize(row * static_cast<std::size_t>(height));
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, scratch->data());
  rgba->resize(scratch->size());
  for (int y = 0; y < height; ++y)  // GL row 0 is the bottom of the image
    std::memcpy(rgba->data() + static_cast<std::size_t>(y) * row,
                scratch->data() + static_cast<std::size_t>(height - 1 - y) * row, row);
}

}  // namespace sph::cli
