// Everything the CPU prepares for one frame before any GL call: layout, overlay geometry, text, and
// the particle instances with their camera. The GL passes only upload and draw it.
#pragma once
#include <string>
#include <vector>

#include <cstdint>

#include "camera.h"
#include "colormap.h"
#include "cpu_splat.h"
#include "field_range.h"
#include "frame_layout.h"
#include "palette.h"
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

/// Particles drawn into a plot of their own: the panels of a multi-panel frame and the runs of a
/// comparison. A solid set flags every instance as a wall and draws it in colors.wall (one colour per
/// run); otherwise values go through the colour map over `range`.
struct ParticleBatch {
  PixelRect rect;                    ///< the plot (viewport) [px]
  PixelRect fill;                    ///< cleared to palette::kPlotFill first (its axes box), when not empty
  CameraMatrices camera;             ///< plot space -> clip
  std::vector<float> instances;      ///< kInstanceFloats per particle
  std::vector<std::uint32_t> index;  ///< snapshot index of each instance (picking, highlights)
  int run = 0;                       ///< 0: FrameScene::a, 1: FrameScene::b
  float pixel_radius = 0.f;          ///< > 0: fixed radius [px]
  float min_radius = 1.f;            ///< smallest radius [px]
  bool shaded = false;               ///< lit spheres with depth (3D)
  Colormap cmap = Colormap::Viridis;
  ValueRange range;
  FixedColors colors;
  ShapeBatch clipped;                ///< drawn after the particles, scissored to rect (exact curves)
  bool opaque = false;               ///< fill cleared again just before it is drawn: it hides what is under it
};

struct FrameBuild {
  explicit FrameBuild(const FontAtlas& font) : text(font) {}

  FrameLayout layout;
  palette::Chrome pal = palette::kStandard;  ///< the frame's chrome colours (ViewSettings::high_contrast)
  PixelRect fill;      ///< plot background, cleared to pal.plot_fill when non-empty
  ShapeBatch under;    ///< before the particles (grid, domain outline, hidden box edges)
  ShapeBatch clipped;  ///< after the particles, scissored to the plot (exact curves)
  ShapeBatch over;     ///< after the particles (axes, colour bar, legend)
  TextBatch text;      ///< last

  std::vector<float> instances;  ///< kInstanceFloats per particle
  std::vector<std::uint32_t> index;  ///< snapshot index of each instance (picking, highlights)
  CameraMatrices camera;         ///< plot space -> clip, for the particle pass
  float pixel_radius = 0.f;      ///< > 0: fixed particle radius [px]
  float min_radius = 1.f;        ///< smallest particle radius [px]
  bool shaded = false;           ///< lit spheres with depth (3D)
  std::vector<ParticleBatch> batches;  ///< more plots, drawn after the primary one (panels, run B)

  void clear() {
    fill = {};
    under.clear();
    clipped.clear();
    over.clear();
    text.clear();
    instances.clear();
    index.clear();
    batches.clear();
    pixel_radius = 0.f;
    min_radius = 1.f;
    shaded = false;
  }

  /// Moves the primary plot (particles, their camera, layout.plot, its fill and clipped overlays) into
  /// a new batch of run `run` drawn with `cmap`, `range` and `colors`: a frame of several plots
  /// composes each as the primary one, then detaches it.
  ParticleBatch& detach_primary(int run, Colormap cmap, ValueRange range, FixedColors colors) {
    ParticleBatch& b = batches.emplace_back();
    b.rect = layout.plot;
    b.fill = fill;
    b.camera = camera;
    b.instances = std::move(instances);
    b.index = std::move(index);
    b.run = run;
    b.pixel_radius = pixel_radius;
    b.min_radius = min_radius;
    b.shaded = shaded;
    b.cmap = cmap;
    b.range = range;
    b.colors = colors;
    std::swap(b.clipped, clipped);
    instances.clear();
    index.clear();
    clipped.clear();
    fill = {};
    return b;
  }
};

}  // namespace sph::render
