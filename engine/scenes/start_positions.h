// Where a 2D/3D test scene's particles start: a close-packed lattice or a glass, chosen by the scene
// values n_side (particles per unit length), start (0 lattice, 1 glass) and seed (of the glass).
#pragma once
#include <vector>

#include "close_packed.h"
#include "sph/scene.h"

namespace sph::scenes {

/// The three scene values, n_side defaulting to `n_side`.
std::vector<SceneParam> start_params(double n_side);

/// Positions in [lo, hi) and their mean spacing for those values.
Lattice start_positions(int dim, const Vec3& lo, const Vec3& hi, const SceneValues& v);

}  // namespace sph::scenes
