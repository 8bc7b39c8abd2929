// Close-packed particle lattices filling a box: hexagonal rows in 2D, body-centred cubic in 3D (a
// uniform row in 1D). They start multidimensional scenes nearer equilibrium than a square or cubic
// lattice, which SPH's pairing and tensile modes distort (Price 2012, J. Comput. Phys. 231, 759, §4.2).
#pragma once
#include <vector>

#include "sph/vec.h"

namespace sph::scenes {

struct Lattice {
  std::vector<Vec3> x;     ///< positions, inside [lo, hi)
  double spacing = 0.0;    ///< mean spacing (volume per particle)^(1/dim), the h guess's dx
};

/// Fills [lo, hi) (dim axes used) with a lattice of mean spacing near `spacing`. The counts per axis
/// are rounded so the lattice tiles the box exactly: the box can be periodic on every axis (hexagonal
/// rows come in even numbers); the spacing is adjusted per axis, never the box.
Lattice close_packed(int dim, const Vec3& lo, const Vec3& hi, double spacing);

}  // namespace sph::scenes
