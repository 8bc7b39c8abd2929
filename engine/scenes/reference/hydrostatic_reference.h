// Water at rest under gravity: P = rho0 g (H - y) below the free surface y = H (y: the vertical axis,
// z in 3D).
#pragma once
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

/// H: depth [m]; W: tank width [m]; dx: spacing [m]; rho0 [kg/m^3]; g [m/s^2]; up: the vertical axis
/// (1 in 2D, 2 in 3D); the tank spans [0, W] along x (and y in 3D).
std::unique_ptr<Reference> make_hydrostatic_reference(double H, double W, double dx, double rho0, double g, int up = 1);

}  // namespace sph::scenes
