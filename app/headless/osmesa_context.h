// Off-screen GL contexts for the headless program. OffscreenContext is the seam: the OSMesa backend
// lives in osmesa_context.cpp; an EGL surfaceless backend (Mesa removed OSMesa in 25.1) can be added
// beside it without touching the renderer or the frame recorder.
#pragma once
#include <cstdint>
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
  /// "OSMesa 22.3.6, OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe ..." (after make_current).
  virtual std::string description() const = 0;
};

/// An OSMesa OpenGL 3.3 core-profile context (llvmpipe gives 4.5 core), nullptr with *err on failure.
std::unique_ptr<OffscreenContext> create_osmesa_context(std::string* err);

}  // namespace sph::cli
