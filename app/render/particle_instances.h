// Packs snapshot arrays into the particle pass's instance layout (x, y, z, radius, value, wall).
#pragma once
#include <cstdint>
#include <vector>

#include "frame_build.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

enum class Placement {
  Positions,  ///< (x, y, z) as they are (2D: z = 0)
  Profile,    ///< (coordinate `axis`, value, 0): profile plots; walls are always left out
};

struct InstanceOptions {
  Placement placement = Placement::Positions;
  int axis = 0;              ///< Profile: the coordinate on the horizontal axis (0 x, 1 y, 2 z)
  float radius_scale = 0.f;  ///< radius = radius_scale * h [world units]
  bool walls = true;         ///< Positions: include wall particles (flagged, drawn grey)
  /// Profile: the vertical values (one per snapshot particle) instead of the shown field's
  const std::vector<float>* y = nullptr;
  bool solid = false;        ///< flag every instance as a wall: drawn in one colour (FixedColors::wall)
  int cut_axis = -1;         ///< Positions: leave out particles whose coordinate cut_axis is > cut_at
  float cut_at = 0.f;
};

/// Appends one instance per shown particle: value = shown field (NaN when no field is shown), wall =
/// 1 for Snapshot::is_wall. Short or missing arrays read as 0 (positions, h) or NaN (values). With
/// `index`, appends the snapshot index of each instance to it.
void build_instances(const sph::Snapshot& snap, const ShownField& shown, const InstanceOptions& options,
                     std::vector<float>* out, std::vector<std::uint32_t>* index = nullptr);
/// True if the snapshot has a positive smoothing length for some particle.
bool has_smoothing_lengths(const sph::Snapshot& snap);

}  // namespace sph::render
