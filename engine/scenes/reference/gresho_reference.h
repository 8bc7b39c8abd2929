// The Gresho-Chan vortex (Gresho & Chan 1990, Int. J. Numer. Meth. Fluids 11, 621; the set-up of Liska &
// Wendroff 2003, SIAM J. Sci. Comput. 25, 995): a stationary solution of the Euler equations, the
// rotation balanced by the pressure gradient dP/dr = rho v_phi^2 / r. Centred on the origin.
#pragma once
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

/// v_phi(r) of the vortex: 5r (r < 0.2), 2 - 5r (0.2 <= r < 0.4), 0 beyond [length/time].
double gresho_vphi(double r);
/// P(r) for rho = 1: 5 + 12.5 r^2, 9 + 12.5 r^2 - 20 r + 4 ln(5r), 3 + 4 ln 2 (continuous) [pressure].
double gresho_pressure(double r);

/// Compares the particles with the stationary solution (vortex centred on the origin).
std::unique_ptr<Reference> make_gresho_reference();

}  // namespace sph::scenes
