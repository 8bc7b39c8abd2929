// Where the particles of a scene sit in the box of the SWIFT/GADGET layout: those codes put a periodic
// box at [0, BoxSize), so coordinates are shifted; open axes get a box four times the scene's domain
// about its centre (one frame for a whole run); mirror walls have no counterpart (the target's box is
// periodic there).
#pragma once
#include <array>
#include <vector>

#include "sph/world.h"

namespace sph {

struct ExportBox {
  std::array<double, 3> shift{0, 0, 0};  ///< file coordinate = x + shift [length]
  std::array<double, 3> size{1, 1, 1};   ///< BoxSize per axis [length]
  bool periodic = false;                 ///< some axis of the scene is periodic or walled
  std::vector<int> wall_axes;            ///< axes with mirror walls (periodic in the target)
};

ExportBox export_box(const World& world);

/// Scenes without SPH sums or FPM: point masses, written as /PartType1.
inline bool is_nbody(const Params& p) {
  return p.physics.density == DensityMode::None && p.physics.fpm == FpmType::None;
}

}  // namespace sph
