// What every viscosity term type (visc_*.h) tells a pair loop: which of its parts it has, kPi (a pair
// pressure Pi_ab added to the pressure bracket) and kLaplacian (a term k_ab v_ab of its own), and how it
// scales the pair signal speed (pair_terms.h signal_speed).
#pragma once

namespace sph::terms {

template <bool Pi, bool Laplacian>
struct ViscParts {
  static constexpr bool kPi = Pi;
  static constexpr bool kLaplacian = Laplacian;
  double alpha_scale = 1.0, beta_scale = 1.0;  ///< factors of the pair signal speed [dimensionless]
};

}  // namespace sph::terms
