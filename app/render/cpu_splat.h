// The particle stage on the CPU: the same discs (antialiased, drawn in order over each other) and lit
// spheres (nearest wins) as particles.vert/.frag, into a premultiplied RGBA8 image of the plot.
// Used on software GL, where rasterising one primitive per particle is the bottleneck. Blending
// happens in 8 bits per channel like a GL framebuffer, so both paths agree to about 1/255.
#pragma once
#include <cstdint>
#include <vector>

#include "colormap.h"
#include "field_range.h"
#include "mat4.h"
#include "overlay_types.h"

namespace sph::render {

/// Colours that do not come from the map: non-finite values, and wall particles.
struct FixedColors {
  Rgba invalid;
  Rgba wall;
};

struct SplatParams {
  Mat4 view, proj;            ///< world -> eye -> clip, as for the GPU path
  int width = 0, height = 0;  ///< plot viewport [px]
  float pixel_radius = 0.f;   ///< > 0: fixed radius [px]; else the instance radius [world units]
  float min_radius = 1.f;     ///< smallest radius [px]
  ValueRange range;
  Colormap cmap = Colormap::Viridis;
  FixedColors colors;         ///< colour of non-finite values and of walls
  bool shaded = false;        ///< lit spheres with depth (3D) instead of flat discs
};

struct SplatProjected;  // one particle in window coordinates (cpu_splat.cpp)

struct SplatImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  ///< premultiplied RGBA8, rows bottom-up (GL texture order)
  // Working buffers, kept between frames to spare allocations.
  std::vector<float> depth;                    ///< eye-space z of the nearest surface (3D)
  std::vector<SplatProjected> projected;       ///< particles in drawing order
  std::vector<SplatProjected> binned;          ///< the same, grouped by tile
  std::vector<std::uint32_t> tile_start, tile_fill;
  SplatImage();
  ~SplatImage();
};

/// Draws instances (kInstanceFloats per particle: x, y, z, radius, value, wall; in order) into out.
void splat_particles(const std::vector<float>& instances, const SplatParams& p, SplatImage* out);

}  // namespace sph::render
