// The reference of the Burgers scenes (seed 002): the seed's error e(h) = h_max sum_i |u_i - u(x_i, t)|
// against the inviscid solution of eq. 22 (as the seed's Table 1 states it), the mean-absolute L1 used
// by the other scenes, and, when eps > 0, e(h) against the viscous solution (Cole-Hopf) that the
// viscous scheme actually approximates. Curves: u against x (field vx), the viscous solution for eps > 0.
#pragma once
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

/// Ramp parameter a (seed 002 eq. 6c) and viscosity eps (0: inviscid).
std::unique_ptr<Reference> make_burgers_reference(double a, double eps);

}  // namespace sph::scenes
