// Profile plots: a coordinate (x in 1D; x, y or r of a 2D/3D snapshot) against a field, particles as
// dots (walls left out), and the exact/reference curve of that field along that coordinate drawn over
// them in a contrasting colour. One panel coloured by value (the usual view), or a grid of panels
// (ViewSettings::panels: rho, v, p, u as the seed documents show shock tubes) and/or the two runs of a
// comparison in two colours, each with its L1 error in the legend.
#pragma once
#include <string>
#include <vector>

#include "frame_build.h"
#include "frame_scene.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

/// Fills layout.plot, the camera, the axes, the dots and the exact curve with its legend. `axis`
/// (0 x, 1 y, 2 z, 3 r) is the horizontal coordinate; the curve shown is the one with this field and axis.
void compose_profile(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown,
                     int axis);

/// The panels' fields as snapshot field names ("v" is the snapshot's "vx" in 1D, else its "speed").
std::vector<std::string> panel_fields(const sph::Snapshot& snap, const std::vector<std::string>& panels);

/// A grid of profile panels (one per field, or the shown field alone) with one run coloured by the
/// shown field, or the two runs of scene.b in kRunColors: every panel's dots go into f.batches.
void compose_profile_panels(FrameBuild& f, const FrameScene& scene, const ViewSettings& view, const ShownField& shown,
                            int axis, const std::vector<std::string>& fields);

}  // namespace sph::render
