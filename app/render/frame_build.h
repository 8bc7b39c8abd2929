// Everything the CPU prepares for one frame before any GL call: layout, overlay geometry, text, and
// the particle instances with their camera. The GL passes only upload and draw it.
#pragma once
#include <string>
#include <vector>

#include "camera.h"
#include "colormap.h"
#include "field_range.h"
#include "frame_layout.h"
#include "shape_batch.h"
#include "text_batch.h"

namespace sph {
struct SnapshotField;
}

namespace sph::render {

/// The field shown by colour, resolved from the ViewSettings.
struct ShownField {
  const sph::SnapshotField* field = nullptr;  ///< nullptr: no field (particles drawn in one colour)
  std::string label;                          ///< what the colour bar and axes say
  ValueRange range;                           ///< values mapped to the ends of the colour map
  Colormap cmap = Colormap::Viridis;
  std::string warning;                        ///< shown in the title row when non-empty
};

/// Per-particle instance layout of particles.vert (and cpu_splat): x, y, z, radius [world], value
/// [field units], wall (1: drawn in palette::kWall whatever the value, 0: colour-mapped fluid).
inline constexpr int kInstanceFloats = 6;

struct FrameBuild {
  explicit FrameBuild(const FontAtlas& font) : text(font) {}

  FrameLayout layout;
  PixelRect fill;      ///< plot background, cleared to palette::kPlotFill when non-empty
  ShapeBatch under;    ///< before the particles (grid, domain outline, hidden box edges)
  ShapeBatch clipped;  ///< after the particles, scissored to the plot (exact curves)
  ShapeBatch over;     ///< after the particles (axes, colour bar, legend)
  TextBatch text;      ///< last

  std::vector<float> instances;  ///< kInstanceFloats per particle
  CameraMatrices camera;         ///< plot space -> clip, for the particle pass
  float pixel_radius = 0.f;      ///< > 0: fixed particle radius [px]
  float min_radius = 1.f;        ///< smallest particle radius [px]
  bool shaded = false;           ///< lit spheres with depth (3D)

  void clear() {
    fill = {};
    under.clear();
    clipped.clear();
    over.clear();
    text.clear();
    instances.clear();
    pixel_radius = 0.f;
    min_radius = 1.f;
    shaded = false;
  }
};

}  // namespace sph::render
