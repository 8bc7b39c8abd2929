// Profile plots: a coordinate (x in 1D; x or y of a 2D snapshot) against the shown field, particles
// as dots coloured by value (walls left out), and the exact/reference curve of that field along that
// coordinate drawn over them in a contrasting colour.
#pragma once
#include "frame_build.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

/// Fills layout.plot, the camera, the axes, the dots and the exact curve with its legend. `axis`
/// (0 x, 1 y, 2 z) is the horizontal coordinate; the curve shown is the one with this field and axis.
void compose_profile(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown,
                     int axis);

}  // namespace sph::render
