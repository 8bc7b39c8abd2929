// The inset of a plane view (Snapshot::inset, a scene's hint): its region drawn enlarged in the plot's
// lower-right corner, over the view, with its particles, outlines and trails, framed and captioned ("inner
// planets  x12"). Left out where the view already shows the region at half the inset's size or more
// (zoomed in) and where the plot is too small for it.
#pragma once
#include "frame_build.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

/// Needs the plane view's layout (f.layout.plot, plot_to_clip) and primary particles composed.
void add_plane_inset(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown);

}  // namespace sph::render
