// How much of a viscosity term acts between a fluid particle and a dummy-wall particle (walls.friction):
// 1 gives no-slip walls (the default), 0 free-slip walls, as Adami, Hu & Adams 2012 (JCP 231, 7057, §2.3)
// obtain by leaving out the viscous force between fluid and wall. Lennard-Jones walls take no part in the
// SPH sums, so the share is 1 there.
#pragma once
#include <cstdint>

#include "core/stage.h"

namespace sph::terms {

struct WallFriction {
  double f1;                 ///< walls.friction - 1 [dimensionless]
  const std::uint8_t* kind;  ///< Kind of every particle, ghosts included (0 fluid, 1 wall)
  explicit WallFriction(const StageContext& c)
      : f1(c.prm.physics.walls == WallType::Dummy ? c.prm.walls.friction - 1.0 : 0.0), kind(c.p.kind.data()) {}
  /// The factor of the pair term with neighbour j, without a branch (vectorised loops) [dimensionless].
  double operator()(std::uint32_t j) const { return 1.0 + f1 * static_cast<double>(kind[j]); }
};

}  // namespace sph::terms
