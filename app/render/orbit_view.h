// 3D frames: lit spheres with depth under a perspective orbit camera, inside the wireframe of the
// domain box (hidden edges drawn behind the particles, visible ones in front), axes named.
#pragma once
#include "frame_build.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

void compose_orbit(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown);

}  // namespace sph::render
