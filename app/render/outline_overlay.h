// The snapshot's reference outlines (Snapshot::outlines: an exact ellipse, a measured surge front)
// over a 2D view: thin light polylines (a palette colour per label) on a dark rim, clipped to the
// plot, and a legend of their labels when it fits.
#pragma once
#include "camera.h"
#include "frame_build.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

/// Needs f.layout.plot and plot_to_clip. Outlines with no vertex are skipped, a single vertex is drawn
/// as a dot, mismatched x/y lengths use the shorter, non-finite vertices break the line.
void add_outlines(FrameBuild& f, const sph::Snapshot& snap);

/// The outlines alone (no legend) into `out`, mapped from world rectangle `w` onto pixel box `box` (a
/// plane view's inset), at text scale s.
void add_outlines_in(ShapeBatch& out, const sph::Snapshot& snap, const PixelRect& box, const WorldRect& w, int s);

/// Line width of the outline (its rim is 2 px wider) at text scale s [px].
float outline_width(int s);

}  // namespace sph::render
