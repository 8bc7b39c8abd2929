// A small legend box in the top-right corner of a plot: one row per entry, a sample (a line, with
// an optional dark rim, or a dot) and its label. Used by the profile plots (exact curve, particles)
// and by the 2D view (reference outlines).
#pragma once
#include <span>
#include <string>

#include "frame_build.h"

namespace sph::render {

struct LegendEntry {
  std::string label;
  bool dot = false;       ///< a dot of radius `size` [px]; else a line `size` px wide
  Rgba color;
  float size = 1.f;       ///< line width or dot radius [px]
  Rgba halo{0, 0, 0, 0};  ///< line only: drawn first, 2 px wider (alpha 0: none)
};

/// Draws the box (into f.over) and its text; false, drawing nothing, if it does not fit within
/// `box` (wider than the box less its margins, or taller than half of it) or has no entries.
bool add_legend(FrameBuild& f, const PixelRect& box, std::span<const LegendEntry> entries);

}  // namespace sph::render
