// The viscous part of the corrected formulation's Cauchy stress (seed 001 eq. 51),
//   2 mu (D - tr D / 3 I),  mu = rho nu,  D = (grad v + grad v^T) / 2,
// with grad v from the velocity-gradient stage (seed 001 eq. 52). Shared by the force loop
// (forces_corrected.cpp) and the inspector's term split (inspect/force_terms.cpp).
#pragma once
#include <cstddef>

#include "sph/particles.h"

namespace sph {

struct ViscousStress {
  const double* grad[9] = {};  ///< dv_k/dx_l of every particle, at 3 k + l [1/time]; null when off
  int d;                       ///< dimension
  double nu;                   ///< visc.nu [length^2/time]

  /// d: the dimension; on = false (no Laplacian viscosity): the stress has no viscous part and grad is
  /// not read.
  ViscousStress(const Particles& p, int d_, double nu_, bool on) : d(d_), nu(nu_) {
    if (on)
      for (int k = 0; k < d; ++k)
        for (int l = 0; l < d; ++l) grad[3 * k + l] = p[component(Field::VelGradXX, k, l)].data();
  }
  bool on() const { return grad[0] != nullptr; }

  /// Adds particle b's viscous stress to T (3 x 3, row-major); rho_b its density.
  void add(std::size_t b, double rho_b, double T[9]) const {
    const double mu = rho_b * nu;
    double tr = 0.0;
    for (int k = 0; k < d; ++k) tr += grad[4 * k][b];
    for (int k = 0; k < d; ++k)
      for (int l = 0; l < d; ++l) {
        const double D = 0.5 * (grad[3 * k + l][b] + grad[3 * l + k][b]);
        T[3 * k + l] += 2.0 * mu * (D - (k == l ? tr / 3.0 : 0.0));
      }
  }
};

}  // namespace sph
