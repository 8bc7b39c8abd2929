// A small legend box in a corner of a plot where it covers no data (top right unless data is there):
// one row per entry, a sample (a line, with an optional dark rim, or a dot) and its label. Used by the
// profile plots (exact curve, particles) and by the 2D view (reference outlines).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "frame_build.h"

namespace sph::render {

struct LegendEntry {
  std::string label;
  bool dot = false;       ///< a dot of radius `size` [px]; else a line `size` px wide
  Rgba color;
  float size = 1.f;       ///< line width or dot radius [px]
  Rgba halo{0, 0, 0, 0};  ///< line only: drawn first, 2 px wider (alpha 0: none)
};

/// Where a w x h legend goes in `box`, `pad` px from its edges: the first of the top-right, top-left,
/// bottom-right, bottom-left corners, then the top and bottom middles, whose rectangle grown by `clear`
/// px contains none of the points `xy` (x, y pairs [px]); if each contains some, the one with fewest.
PixelRect place_legend(const PixelRect& box, float w, float h, float pad, float clear, std::span<const float> xy);

/// Appends points along the polyline `xy` (x, y pairs [px]; NaN breaks it) at most `step` px apart
/// to *out, so that a long segment (a shock's jump) counts as data along its whole length.
void densify(std::span<const float> xy, float step, std::vector<float>* out);

/// Draws the box (into f.over) and its text where it covers none of the data points `avoid_xy` (see
/// place_legend; `clear` px around them) and records it in f.layout.legend; false, drawing nothing, if
/// it does not fit within `box` (wider than the box less its margins, or taller than half of it) or
/// has no entries. text_scale > 0: its text at that scale instead of the frame's (small panels).
bool add_legend(FrameBuild& f, const PixelRect& box, std::span<const LegendEntry> entries,
                std::span<const float> avoid_xy = {}, float clear = 0.f, int text_scale = 0);

}  // namespace sph::render
