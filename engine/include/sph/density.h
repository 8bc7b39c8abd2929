// Statistics of the density stage (summation with Newton-Raphson h, seed 000 eq. 3.5.1), reported in
// the diagnostics and the GUI's status line.
#pragma once
#include <cstddef>
#include <cstdint>

namespace sph {

struct DensityStats {
  double mean_iterations = 0.0;    ///< Newton-Raphson iterations per particle, averaged
  int max_iterations = 0;          ///< worst particle
  std::size_t not_converged = 0;   ///< particles that hit h.max_iter without converging
  std::int64_t first_not_converged = -1;  ///< the id of the first of them (lowest storage index), or -1
  std::size_t bisections = 0;      ///< Newton steps replaced by bisection of the bracket
  double mean_neighbours = 0.0;    ///< mean count of j with r < support h_i (self included)
};

/// The last step's pressure solves of an incompressible liquid (DFSPH; Stage::project).
struct ProjectionStats {
  int density_iterations = 0;     ///< iterations of the constant-density solve
  int divergence_iterations = 0;  ///< iterations of the divergence-free solve
  /// mean |rho* - rho0|/rho0 at the density solve's end over the fluid: compression, and expansion where
  /// a pressure acts (a free surface's particles expand freely) [dimensionless]
  double density_error = 0.0;
  double density_error_max = 0.0; ///< the same for the worst particle [dimensionless]
};

}  // namespace sph
