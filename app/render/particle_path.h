// How particles reach the framebuffer (see particle_pass.h).
#pragma once

namespace sph::render {

enum class ParticlePath {
  Auto,  ///< CPU splat on software GL (llvmpipe, softpipe, swrast), GPU quads otherwise
  Gpu,   ///< one instanced quad per particle
  Cpu,   ///< cpu_splat.h into an image, drawn as one quad
};

}  // namespace sph::render
