// The Barnes-Hut overlay: the cells of one particle's tree walk (Snapshot::tree_cells), drawn over the
// particles of 2D and 3D views so a lecturer can show what the tree opens at the current theta. Cells
// used whole (one multipole each) are sky blue, leaves summed particle by particle amber; the probed
// particle is a white ring; a caption names the counts.
#pragma once

namespace sph {
struct Snapshot;
}

namespace sph::render {

struct FrameBuild;

/// Adds the overlay for a snapshot that carries tree cells (nothing otherwise). 2D: squares in the
/// plane; 3D: the twelve edges of each cube, in the frame's camera.
void add_tree_overlay(FrameBuild& f, const sph::Snapshot& snap);

}  // namespace sph::render
