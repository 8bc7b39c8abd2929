// The Sedov blast's reference: the shock radius measured from the particles against the self-similar
// R(t), L1 of the density against the exact profile, and the total energy drift.
#pragma once
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

struct SedovSetup {
  int dim = 2;
  double gamma = 5.0 / 3.0;
  double E = 1.0;         ///< blast energy (2D: per unit length) [energy]
  double rho1 = 1.0;      ///< ambient density [mass/length^d]
  double u_ambient = 0;   ///< specific internal energy of the ambient gas [energy/mass]
  double dr = 0.01;       ///< shell width of the measured profile [length]
  double r_max = 0.5;     ///< shells out to this radius [length]
};

/// E0 = E + (sum m) u_ambient: the scene deposits exactly E on top of the ambient u.
std::unique_ptr<Reference> make_sedov_reference(const SedovSetup& s);

}  // namespace sph::scenes
