// The parts every frame has: the title row ("scene  t = 0.2000  step 123"), the colour-bar panel
// with the field label and range, and the content area left for the plot.
#pragma once
#include "frame_build.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

/// Sets layout size, text scale, margin, title row, colour-bar panel and content area.
void layout_chrome(FrameBuild& f, const ShownField& shown, int width, int height, int text_scale_request);
/// Title row: scene, time and step; particle count; warning (if any).
void add_title(FrameBuild& f, const sph::Snapshot& snap, const ShownField& shown);
/// Places layout.colorbar level with layout.plot (call once the plot is known) and draws the bar,
/// its outline, ticks, the min and max values and the field label.
void add_colorbar(FrameBuild& f, const ShownField& shown);

}  // namespace sph::render
