// Water at rest under gravity: P = rho0 g (H - y) below the free surface y = H.
#pragma once
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

/// H: depth [m]; W: tank width [m]; dx: spacing [m]; rho0 [kg/m^3]; g [m/s^2].
std::unique_ptr<Reference> make_hydrostatic_reference(double H, double W, double dx, double rho0, double g);

}  // namespace sph::scenes
