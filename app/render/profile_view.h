// 1D frames: a profile plot of x against the shown field, particles as dots coloured by value, and
// the exact/reference curve of that field drawn over them in a contrasting colour.
#pragma once
#include "frame_build.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

/// Fills layout.plot, the camera, the axes, the dots and the exact curve with its legend.
void compose_profile(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown);

}  // namespace sph::render
