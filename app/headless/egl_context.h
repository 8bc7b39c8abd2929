// The EGL backend of OffscreenContext: an OpenGL 3.3 core context without a window system (Mesa's
// EGL_MESA_platform_surfaceless, else the first device of EGL_EXT_platform_device) rendering into a
// framebuffer object. What a machine whose Mesa no longer has OSMesa (25.1 on) uses.
#pragma once
#include <memory>
#include <string>

#include "offscreen_context.h"

namespace sph::cli {

/// nullptr with *err naming the EGL call that failed.
std::unique_ptr<OffscreenContext> create_egl_context(std::string* err);

}  // namespace sph::cli
