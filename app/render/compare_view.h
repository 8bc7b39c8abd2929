// 2D and 3D frames of an A/B comparison: run A and run B side by side with one colour range (the union
// of both), and in 2D a third panel, the difference map B - A of the shown field at A's particles
// (nearest_difference.h) in the diverging coolwarm map, symmetric about 0. Each panel is captioned with
// its run's label; pan, zoom and the orbit camera apply to every panel alike.
#pragma once
#include "frame_build.h"
#include "frame_scene.h"
#include "view_settings.h"

namespace sph::render {

/// shown: the field of run A with the colour range of both runs (see compare_range).
void compose_compare(FrameBuild& f, const FrameScene& scene, const ViewSettings& view, const ShownField& shown);

/// The colour range of a field shown for both runs: the view's range over A's and B's values together.
ValueRange compare_range(const sph::Snapshot& a, const sph::Snapshot& b, const ViewSettings& view,
                         const sph::SnapshotField& fa);

}  // namespace sph::render
