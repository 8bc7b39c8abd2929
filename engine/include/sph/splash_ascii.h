// A particle file for Daniel Price's SPLASH (its ascii reader, `splash -ascii FILE`): header lines with the
// time (and gamma for an ideal gas) where SPLASH looks for them, column labels in its "[NN label]" style
// that it maps to positions, velocities, mass, density, h, u and pressure, one row per particle.
#pragma once
#include <string>

#include "sph/world.h"

namespace sph {

/// Columns: x (y, z up to the scene's dimension), vx (vy, vz), then m, rho, h, u, p, phi where allocated,
/// and itype (1 fluid, 2 wall: SPLASH's particle types) when the scene has walls. Rows in id order.
std::string splash_ascii_file(const World& world);

}  // namespace sph
