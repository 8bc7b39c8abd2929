// The OSMesa backend of OffscreenContext (Mesa's off-screen library, removed in Mesa 25.1).
#pragma once
#include <memory>
#include <string>

#include "offscreen_context.h"

namespace sph::cli {

/// An OSMesa OpenGL 3.3 core-profile context (llvmpipe gives 4.5 core), nullptr with *err on failure.
std::unique_ptr<OffscreenContext> create_osmesa_context(std::string* err);

}  // namespace sph::cli
