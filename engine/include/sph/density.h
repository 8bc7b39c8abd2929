// Summation density with variable smoothing length (seed 000 eqs. 3.2.17, 3.2.21, 3.3.2, 3.5.1).
#pragma once
#include <cstddef>

#include "sph/kernel.h"
#include "sph/neighbours.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

struct DensityStats {
  double mean_iterations = 0.0;    ///< Newton-Raphson iterations per particle, averaged
  int max_iterations = 0;          ///< worst particle
  std::size_t not_converged = 0;   ///< particles that hit h_max_iter without converging
  std::size_t bisections = 0;      ///< Newton steps replaced by bisection of the bracket
  double mean_neighbours = 0.0;    ///< mean count of j with r < support h_i (self included)
};

/// Solves rho_a = sum_b m_b W(r_ab, h_a) together with h_a = eta (m_a/rho_a)^(1/d) for every real
/// particle by Newton-Raphson on g(h) = rho(h) - m eta^d / h^d (seed 000 eq. 3.5.1) with a bracketing
/// fallback, then sets Omega_a = 1 + h_a/(d rho_a) sum_b m_b dW_ab/dh (seed 000 eqs. 3.3.2, 3.3.4).
/// In HMode::Fixed, h is kept and Omega = 1. The neighbour list must hold every j within
/// list_radius * max(h_i, h_j) with the current h; h may grow at most to h_limit[i] (the list's
/// reach). Returns false if some particle needs a larger h than its list allows: the caller then
/// rebuilds the list from the new h and calls again.
bool solve_density(const Kernel& kernel, const Params& prm, double eta, Particles& p, const NeighbourList& nl,
                   const std::vector<double>& h_limit, DensityStats& stats);

}  // namespace sph
