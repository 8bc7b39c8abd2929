// 2D frames: particles as filled discs (radius from h, or fixed pixels; walls grey, or hidden) in an
// equal-aspect axes box that fits the domain bounds, with the domain outlined and the snapshot's
// reference outlines drawn over the particles.
#pragma once
#include "frame_build.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

void compose_plane(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown);

}  // namespace sph::render
