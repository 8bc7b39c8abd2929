// SPHERIC test 2's reference: water-height gauges and the pressure sensor P1 read from the particles,
// against the MARIN measurements (kleefsman_data.h).
#pragma once
#include <array>
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

/// spacing: the lattice spacings along x, y, z [m]; depth: the column's initial depth [m] (the heights'
/// error scale); box_face: x of the box's front face, which carries P1 [m].
std::unique_ptr<Reference> make_dam_break_3d_reference(std::array<double, 3> spacing, double depth, double box_face);

}  // namespace sph::scenes
