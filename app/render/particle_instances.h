// Packs snapshot arrays into the particle pass's instance layout (x, y, z, radius, value).
#pragma once
#include <vector>

#include "frame_build.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

enum class Placement {
  Positions,  ///< (x, y, z) as they are (2D: z = 0)
  Profile,    ///< (x, value, 0): the 1D profile plot
};

/// Appends one instance per particle: radius = radius_scale * h [world units], value = shown field
/// (NaN when no field is shown). Short or missing arrays read as 0 (positions, h) or NaN (values).
void build_instances(const sph::Snapshot& snap, const ShownField& shown, Placement placement, float radius_scale,
                     std::vector<float>* out);
/// True if the snapshot has a positive smoothing length for some particle.
bool has_smoothing_lengths(const sph::Snapshot& snap);

}  // namespace sph::render
